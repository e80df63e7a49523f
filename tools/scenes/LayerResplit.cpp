#include "scenes/LayerResplit.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <fmt/format.h>

#include "core/Error.hpp"
#include "mesh/MeshQueries.hpp"

namespace ma {
namespace {

using Triangle = std::array<int, 3>;  // column (bottom node) indices, sorted

struct Columns {
    std::vector<int> columnOf;   // node -> its column (the bottom node's index)
    std::vector<int> topOf;      // bottom node -> top node
    std::vector<bool> isBottom;  // node on z = zmin
};

Columns matchColumns(const Mesh& mesh) {
    double zmin = INFINITY, zmax = -INFINITY, size = 0;
    for (const auto& x : mesh.coords) zmin = std::min(zmin, x[2]), zmax = std::max(zmax, x[2]);
    for (const auto& x : mesh.coords) size = std::max({size, std::abs(x[0]), std::abs(x[1]), std::abs(x[2])});
    const double tol = 1e-9 * std::max(size, 1.0);
    Columns c{std::vector<int>(mesh.coords.size(), -1), std::vector<int>(mesh.coords.size(), -1),
              std::vector<bool>(mesh.coords.size(), false)};
    std::map<std::pair<long long, long long>, int> bottomAt;
    const auto key = [&](const Vec3& x) { return std::pair{std::llround(x[0] / tol), std::llround(x[1] / tol)}; };
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        const double z = mesh.coords[size_t(n)][2];
        if (std::abs(z - zmin) > tol && std::abs(z - zmax) > tol)
            throw UserError(fmt::format("node {} is on neither plane z = {} nor z = {}: not a layer of prisms",
                                        mesh.nodeNames[size_t(n)], zmin, zmax));
        if (std::abs(z - zmin) <= tol) c.isBottom[size_t(n)] = true, bottomAt[key(mesh.coords[size_t(n)])] = n;
    }
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        const auto it = bottomAt.find(key(mesh.coords[size_t(n)]));
        if (it == bottomAt.end())
            throw UserError(fmt::format("top node {} has no bottom node below it", mesh.nodeNames[size_t(n)]));
        c.columnOf[size_t(n)] = it->second;
        if (!c.isBottom[size_t(n)]) c.topOf[size_t(it->second)] = n;
    }
    return c;
}

// Appends the tetrahedron right-handed (orientation enters nothing, but the alarm stays quiet).
void addTetra(Mesh& mesh, std::array<int, 4> n) {
    const auto& x = mesh.coords;
    const Vec3 a = difference(x[size_t(n[1])], x[size_t(n[0])]), b = difference(x[size_t(n[2])], x[size_t(n[0])]),
               c = difference(x[size_t(n[3])], x[size_t(n[0])]);
    if (dot(cross(a, b), c) < 0) std::swap(n[1], n[2]);
    mesh.addCell(CellType::TETRA4, n);
}

std::set<Triangle> prismsOf(const Mesh& layer, const Columns& c) {
    std::set<Triangle> prisms;
    for (int cell = 0; cell < layer.cellCount(); ++cell) {
        if (cellDimension(layer.cellTypes[size_t(cell)]) != 3) continue;
        if (layer.cellTypes[size_t(cell)] != CellType::TETRA4)
            throw UserError(fmt::format("cell {} is not a TETRA4", layer.cellNames[size_t(cell)]));
        std::set<int> columns;
        for (int n : layer.cellNodes(cell)) columns.insert(c.columnOf[size_t(n)]);
        if (columns.size() != 3)
            throw UserError(fmt::format("cell {} spans {} columns, not 3: not a prism's tetrahedron",
                                        layer.cellNames[size_t(cell)], columns.size()));
        prisms.insert(Triangle{*columns.begin(), *std::next(columns.begin()), *columns.rbegin()});
    }
    return prisms;
}

// The skin of the new tetrahedra: faces seen once, as TRIA3 cells; returns their indices.
std::vector<int> addSkin(Mesh& mesh, int firstTetra, int endTetra) {
    static constexpr int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};  // outward
    std::map<Triangle, std::pair<int, Triangle>> seen;  // sorted nodes -> (count, outward nodes)
    for (int cell = firstTetra; cell < endTetra; ++cell) {
        const auto nodes = mesh.cellNodes(cell);
        for (const auto& f : faces) {
            Triangle t{nodes[size_t(f[0])], nodes[size_t(f[1])], nodes[size_t(f[2])]}, sorted = t;
            std::sort(sorted.begin(), sorted.end());
            auto& entry = seen[sorted];
            entry.first++, entry.second = t;
        }
    }
    std::vector<int> skin;
    for (const auto& [sorted, entry] : seen)
        if (entry.first == 1) skin.push_back(mesh.addCell(CellType::TRIA3, entry.second));
    return skin;
}

}  // namespace

std::shared_ptr<Mesh> resplitPrismLayer(const Mesh& layer) {
    const Columns c = matchColumns(layer);
    auto out = std::make_shared<Mesh>();
    out->dim = layer.dim, out->coords = layer.coords, out->nodeNames = layer.nodeNames;
    for (const auto& name : layer.nodeGroups.names()) out->nodeGroups.set(name, layer.nodeGroups.get(name));
    const int firstTetra = out->cellCount();
    for (const auto& [a, b, cc] : prismsOf(layer, c)) {
        const int a1 = c.topOf[size_t(a)], b1 = c.topOf[size_t(b)], c1 = c.topOf[size_t(cc)];
        addTetra(*out, {a, b, cc, c1});
        addTetra(*out, {a, b, b1, c1});
        addTetra(*out, {a, a1, b1, c1});
    }
    const int endTetra = out->cellCount();
    const std::vector<int> skin = addSkin(*out, firstTetra, endTetra);
    std::vector<int> kept(size_t(layer.cellCount()), -1);  // 1D and 0D cells, copied
    for (int cell = 0; cell < layer.cellCount(); ++cell)
        if (cellDimension(layer.cellTypes[size_t(cell)]) <= 1)
            kept[size_t(cell)] = out->addCell(layer.cellTypes[size_t(cell)], layer.cellNodes(cell));
    std::vector<int> tetras(size_t(endTetra - firstTetra));
    for (int i = firstTetra; i < endTetra; ++i) tetras[size_t(i - firstTetra)] = i;
    int layerTetras = 0, layerTriangles = 0;
    for (auto t : layer.cellTypes) layerTetras += t == CellType::TETRA4, layerTriangles += t == CellType::TRIA3;
    for (const auto& name : layer.cellGroups.names()) {
        const auto& members = layer.cellGroups.get(name);
        const auto all = [&](CellType t) {
            return std::all_of(members.begin(), members.end(), [&](int m) { return layer.cellTypes[size_t(m)] == t; });
        };
        if (all(CellType::TETRA4) && int(members.size()) == layerTetras) {
            out->cellGroups.set(name, tetras);
        } else if (all(CellType::TRIA3) && int(members.size()) == layerTriangles) {
            out->cellGroups.set(name, skin);
        } else if (std::all_of(members.begin(), members.end(), [&](int m) { return kept[size_t(m)] >= 0; })) {
            std::vector<int> copied;
            for (int m : members) copied.push_back(kept[size_t(m)]);
            out->cellGroups.set(name, copied);
        } else {
            throw UserError(
                fmt::format("cell group {} is neither every tetrahedron, the whole skin nor 1D cells: "
                            "no re-split counterpart",
                            name));
        }
    }
    return out;
}

}  // namespace ma
