#include "scenes/Ssnv511Mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"

namespace ma {

namespace {

using Kind = Ssnv511MeshOptions::Kind;

std::vector<double> gridLine(double lo, double hi, int n, double offset) {
    std::vector<double> x(size_t(n) + 1);
    const double h = (hi - lo) / n;
    for (int i = 0; i <= n; ++i) x[size_t(i)] = (i == 0) ? lo : (i == n) ? hi : lo + (i + offset) * h;
    return x;
}

double tetraVolume(const Mesh& m, const std::array<int, 4>& t) {
    const auto &a = m.coords[size_t(t[0])], &b = m.coords[size_t(t[1])], &c = m.coords[size_t(t[2])],
               &d = m.coords[size_t(t[3])];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
    return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

// A triangle turned so that its normal (P2-P1)x(P3-P1) has a positive component along `out`.
std::array<int, 3> orientedTriangle(const Mesh& m, std::array<int, 3> t, const std::array<double, 3>& out) {
    const auto &a = m.coords[size_t(t[0])], &b = m.coords[size_t(t[1])], &c = m.coords[size_t(t[2])];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    if (n[0] * out[0] + n[1] * out[1] + n[2] * out[2] < 0) std::swap(t[1], t[2]);
    return t;
}

struct Builder {
    const Ssnv511MeshOptions& opt;
    int n;
    std::vector<double> xs, ys;
    std::shared_ptr<Mesh> mesh = std::make_shared<Mesh>();

    explicit Builder(const Ssnv511MeshOptions& o)
        : opt(o),
          n(o.divisions),
          xs(gridLine(o.xmin, o.xmax, o.divisions, o.offsetX)),
          ys(gridLine(o.ymin, o.ymax, o.divisions, o.offsetY)) {}

    int node(int i, int j, int layer = 0) const { return layer * (n + 1) * (n + 1) + j * (n + 1) + i; }

    void addNodes(int layers) {
        const size_t total = size_t(layers) * size_t(n + 1) * size_t(n + 1);
        mesh->coords.reserve(total);
        mesh->nodeNames.reserve(total);
        for (int l = 0; l < layers; ++l) {
            const double z = layers == 1       ? 0.0
                             : l == layers - 1 ? opt.zmax
                                               : opt.zmin + (opt.zmax - opt.zmin) * l / (layers - 1);
            for (int j = 0; j <= n; ++j)
                for (int i = 0; i <= n; ++i) mesh->coords.push_back({xs[size_t(i)], ys[size_t(j)], z});
        }
        for (size_t k = 0; k < total; ++k) mesh->nodeNames.push_back(fmt::format("N{}", k + 1));
    }

    int cell(CellType t, std::initializer_list<int> nodes) {
        const int index = mesh->cellCount();
        mesh->cellTypes.push_back(t);
        mesh->connectivity.insert(mesh->connectivity.end(), nodes.begin(), nodes.end());
        mesh->cellOffsets.push_back(int(mesh->connectivity.size()));
        mesh->cellNames.push_back(fmt::format("M{}", index + 1));
        return index;
    }

    // The two triangles of square (i, j), split along its anti-diagonal (i+1,j)-(i,j+1), as the
    // regular part of ssnv511b: counter-clockwise.
    std::array<std::array<int, 3>, 2> squareTriangles(int i, int j, int layer = 0) const {
        return {{{node(i, j, layer), node(i + 1, j, layer), node(i, j + 1, layer)},
                 {node(i + 1, j, layer), node(i + 1, j + 1, layer), node(i, j + 1, layer)}}};
    }

    void edges() {
        std::vector<int> lb, ld, lh, lg;
        for (int i = 0; i < n; ++i) lb.push_back(cell(CellType::SEG2, {node(i, 0), node(i + 1, 0)}));
        for (int j = 0; j < n; ++j) ld.push_back(cell(CellType::SEG2, {node(n, j), node(n, j + 1)}));
        for (int i = n - 1; i >= 0; --i) lh.push_back(cell(CellType::SEG2, {node(i + 1, n), node(i, n)}));
        for (int j = n - 1; j >= 0; --j) lg.push_back(cell(CellType::SEG2, {node(0, j + 1), node(0, j)}));
        mesh->cellGroups.set("LB", std::move(lb));
        mesh->cellGroups.set("LD", std::move(ld));
        mesh->cellGroups.set("LH", std::move(lh));
        mesh->cellGroups.set("LG", std::move(lg));
    }

    void quad4() {
        mesh->dim = 2;
        addNodes(1);
        edges();
        std::vector<int> surf;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                surf.push_back(cell(CellType::QUAD4, {node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)}));
        mesh->cellGroups.set("SURF", std::move(surf));
    }

    void tria3() {
        mesh->dim = 2;
        addNodes(1);
        edges();
        std::vector<int> surf;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                for (const auto& t : squareTriangles(i, j)) surf.push_back(cell(CellType::TRIA3, {t[0], t[1], t[2]}));
        mesh->cellGroups.set("SURF", std::move(surf));
    }

    void hexa8() {
        mesh->dim = 3;
        const int top = opt.layers;
        addNodes(top + 1);
        std::vector<int> env, sd, sg, volu;
        // Skin, every face outward (as ssnv511g): z=zmin, z=zmax, x=xmax (SD), x=xmin (SG),
        // y=ymax, y=ymin.
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                env.push_back(cell(CellType::QUAD4, {node(i, j), node(i, j + 1), node(i + 1, j + 1), node(i + 1, j)}));
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                env.push_back(cell(CellType::QUAD4, {node(i, j, top), node(i + 1, j, top), node(i + 1, j + 1, top),
                                                     node(i, j + 1, top)}));
        for (int l = 0; l < top; ++l) {
            for (int j = 0; j < n; ++j) {
                const int c =
                    cell(CellType::QUAD4, {node(n, j, l), node(n, j + 1, l), node(n, j + 1, l + 1), node(n, j, l + 1)});
                env.push_back(c), sd.push_back(c);
            }
            for (int j = 0; j < n; ++j) {
                const int c =
                    cell(CellType::QUAD4, {node(0, j + 1, l), node(0, j, l), node(0, j, l + 1), node(0, j + 1, l + 1)});
                env.push_back(c), sg.push_back(c);
            }
            for (int i = 0; i < n; ++i)
                env.push_back(cell(CellType::QUAD4,
                                   {node(i + 1, n, l), node(i, n, l), node(i, n, l + 1), node(i + 1, n, l + 1)}));
            for (int i = 0; i < n; ++i)
                env.push_back(cell(CellType::QUAD4,
                                   {node(i, 0, l), node(i + 1, 0, l), node(i + 1, 0, l + 1), node(i, 0, l + 1)}));
        }
        for (int l = 0; l < top; ++l)
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i)
                    volu.push_back(cell(CellType::HEXA8, {node(i, j, l), node(i + 1, j, l), node(i + 1, j + 1, l),
                                                          node(i, j + 1, l), node(i, j, l + 1), node(i + 1, j, l + 1),
                                                          node(i + 1, j + 1, l + 1), node(i, j + 1, l + 1)}));
        mesh->cellGroups.set("ENV", std::move(env));
        mesh->cellGroups.set("SD", std::move(sd));
        mesh->cellGroups.set("SG", std::move(sg));
        mesh->cellGroups.set("VOLU", std::move(volu));
    }

    // Lateral quadrangle (bottom a-b, top a'-b') as two triangles split along the diagonal from
    // the lower-numbered bottom vertex to the top of the other one (the tetrahedra use the same
    // rule, so skin and volume are conforming), turned outward.
    void lateral(std::vector<int>& env, int a, int b, const std::array<double, 3>& out) {
        const int top = (n + 1) * (n + 1);
        const int lo = std::min(a, b), hi = std::max(a, b);
        for (auto t : {std::array<int, 3>{lo, hi, hi + top}, std::array<int, 3>{lo, hi + top, lo + top}}) {
            auto o = orientedTriangle(*mesh, t, out);
            env.push_back(cell(CellType::TRIA3, {o[0], o[1], o[2]}));
        }
    }

    void tetra4() {
        mesh->dim = 3;
        addNodes(2);
        const int top = (n + 1) * (n + 1);
        std::vector<int> env, volu;
        for (int layer = 0; layer < 2; ++layer)
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i)
                    for (const auto& t : squareTriangles(i, j, layer)) {
                        auto o = orientedTriangle(*mesh, t, {0.0, 0.0, layer == 0 ? -1.0 : 1.0});
                        env.push_back(cell(CellType::TRIA3, {o[0], o[1], o[2]}));
                    }
        for (int i = 0; i < n; ++i) lateral(env, node(i, 0), node(i + 1, 0), {0, -1, 0});
        for (int j = 0; j < n; ++j) lateral(env, node(n, j), node(n, j + 1), {1, 0, 0});
        for (int i = n - 1; i >= 0; --i) lateral(env, node(i + 1, n), node(i, n), {0, 1, 0});
        for (int j = n - 1; j >= 0; --j) lateral(env, node(0, j + 1), node(0, j), {-1, 0, 0});
        // Each prism (bottom triangle v0<v1<v2 and its top copy) in three tetrahedra whose lateral
        // diagonals go from the lower-numbered bottom vertex up: conforming between prisms.
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                for (auto t : squareTriangles(i, j)) {
                    std::sort(t.begin(), t.end());
                    const int v0 = t[0], v1 = t[1], v2 = t[2];
                    for (auto tet :
                         {std::array<int, 4>{v0, v1, v2, v2 + top}, std::array<int, 4>{v0, v1, v1 + top, v2 + top},
                          std::array<int, 4>{v0, v0 + top, v1 + top, v2 + top}}) {
                        if (tetraVolume(*mesh, tet) < 0) std::swap(tet[1], tet[2]);
                        volu.push_back(cell(CellType::TETRA4, {tet[0], tet[1], tet[2], tet[3]}));
                    }
                }
        mesh->cellGroups.set("ENV", std::move(env));
        mesh->cellGroups.set("VOLU", std::move(volu));
    }
};

}  // namespace

bool ssnv511KindFromName(const std::string& name, Ssnv511MeshOptions::Kind& kind) {
    if (name == "quad4") kind = Kind::Quad4;
    else if (name == "tria3") kind = Kind::Tria3;
    else if (name == "hexa8") kind = Kind::Hexa8;
    else if (name == "tetra4") kind = Kind::Tetra4;
    else return false;
    return true;
}

std::shared_ptr<Mesh> buildSsnv511Mesh(const Ssnv511MeshOptions& o) {
    if (o.divisions < 1)
        throw UserError(fmt::format("the number of divisions must be at least 1 (got {})", o.divisions));
    if (o.layers < 1 || (o.layers > 1 && o.kind != Kind::Hexa8))
        throw UserError(fmt::format("--layers {}: at least 1, and more only for HEXA8", o.layers));
    if (!(o.xmax > o.xmin) || !(o.ymax > o.ymin) || !(o.zmax > o.zmin))
        throw UserError("the bounds must satisfy xmin < xmax, ymin < ymax, zmin < zmax");
    if (!(std::abs(o.offsetX) < 1) || !(std::abs(o.offsetY) < 1))
        throw UserError("the offsets are fractions of the cell size: |offset| < 1");
    if (o.divisions == 1 && (o.offsetX != 0 || o.offsetY != 0))
        throw UserError("offsets need at least 2 divisions (there is no interior grid line)");
    Builder b(o);
    switch (o.kind) {
        case Kind::Quad4: b.quad4(); break;
        case Kind::Tria3: b.tria3(); break;
        case Kind::Hexa8: b.hexa8(); break;
        case Kind::Tetra4: b.tetra4(); break;
    }
    b.mesh->name = "MAILLAGE";
    return b.mesh;
}

}  // namespace ma
