#include "contact/ContactFacets.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "core/Error.hpp"
#include "fe/ShapeFunctions.hpp"
#include "xfem/CellGeometry.hpp"
#include "xfem/XfemModel.hpp"

namespace ma::contact {

namespace {

using Vec = std::array<double, 3>;

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec cross(const Vec& a, const Vec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec& a) { return std::sqrt(dot(a, a)); }

// Faces of a simplex of dimension d (local vertex numbers): triangle edges, tetrahedron faces.
const std::vector<std::vector<int>>& simplexFaces(int d) {
    static const std::vector<std::vector<int>> tri{{0, 1}, {1, 2}, {2, 0}};
    static const std::vector<std::vector<int>> tet{{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
    return d == 2 ? tri : tet;
}

// Physical coordinates of the points of a cut cell.
std::vector<Vec> physicalPoints(const Mesh& mesh, const xfem::CellCut& cut) {
    const auto nodes = mesh.cellNodes(cut.cell);
    std::vector<Vec> xyz(nodes.size());
    for (size_t a = 0; a < nodes.size(); ++a) xyz[a] = mesh.coords[nodes[a]];
    std::vector<Vec> out;
    out.reserve(cut.points.size());
    for (const auto& p : cut.points) out.push_back(mapToPhysical(cut.type, xyz, p.ref));
    return out;
}

double subcellMeasure(int dim, const std::vector<Vec>& xyz, const xfem::SubCell& s) {
    std::vector<Vec> v;
    for (int i = 0; i <= dim; ++i) v.push_back(xyz[s.vertices[i]]);
    return std::abs(xfem::simplexMeasure(dim, v));
}

// Physical measure of every block (Heaviside tuple) of a cut cell.
std::map<std::vector<signed char>, double> blockMeasures(int dim, const std::vector<Vec>& xyz, const xfem::CellCut& cut) {
    std::map<std::vector<signed char>, double> out;
    for (const auto& s : cut.subcells) out[s.heaviside] += subcellMeasure(dim, xyz, s);
    return out;
}

// A face of a sub-cell lying on a crack, seen from one side.
struct FaceOnCrack {
    int cell, subcell;
    std::vector<int> points;  // CutPoint indices
    bool exact = true;        // every vertex has a level set of exactly 0 (not only within onTol)
};

// Face key by physical coordinates (rounded), vertex order independent.
std::vector<std::array<long long, 3>> coordinateKey(const std::vector<Vec>& pts, double tol) {
    std::vector<std::array<long long, 3>> key;
    for (const auto& p : pts)
        key.push_back({std::llround(p[0] / tol), std::llround(p[1] / tol), std::llround(p[2] / tol)});
    std::sort(key.begin(), key.end());
    return key;
}

// Whether the points (reference coordinates of the parent) all lie on one face of the parent
// reference element (QUAD4/HEXA8: [-1,1]^d; TRIA3/TETRA4: unit simplex).
bool onParentFace(CellType type, const std::vector<Vec>& ref) {
    constexpr double tol = 1e-12;
    const int d = (type == CellType::TRIA3 || type == CellType::QUAD4) ? 2 : 3;
    auto all = [&](auto pred) { return std::all_of(ref.begin(), ref.end(), pred); };
    const bool simplex = type == CellType::TRIA3 || type == CellType::TETRA4;
    for (int i = 0; i < d; ++i) {
        if (simplex && all([&](const Vec& r) { return std::abs(r[i]) <= tol; })) return true;
        if (!simplex && (all([&](const Vec& r) { return std::abs(r[i] - 1.0) <= tol; }) ||
                         all([&](const Vec& r) { return std::abs(r[i] + 1.0) <= tol; })))
            return true;
    }
    if (simplex)
        return all([&](const Vec& r) { return std::abs(r[0] + r[1] + (d == 3 ? r[2] : 0.0) - 1.0) <= tol; });
    return false;
}

}  // namespace

std::vector<ContactFacet> buildContactFacets(const xfem::XfemModel& xm, const std::vector<char>& withContact,
                                             FacetStatistics* stats) {
    const Mesh& mesh = xm.mesh();
    const int dim = xm.dim();
    std::vector<ContactFacet> facets;
    FacetStatistics st;
    // Reference length of the mesh (rounding of the coordinate keys of faces on parent faces).
    double lref = 0.0;
    for (int cell : xm.xfemCells()) {
        const auto* cut = xm.cut(cell);
        if (cut->skin) continue;
        const auto nodes = mesh.cellNodes(cell);
        for (size_t a = 1; a < nodes.size(); ++a) lref = std::max(lref, norm(sub(mesh.coords[nodes[a]], mesh.coords[nodes[0]])));
    }
    const double keyTol = 1e-9 * std::max(lref, 1e-300);
    // A cut point is on interface j when its level set is zero up to what CellCut's point merging
    // (1e-9 of an edge) leaves: at a junction the junction point, found on two edges, can be
    // merged with a point 1e-10 h off the interface (seen with interfaces 1e-5 h from node rows),
    // and an exact-zero test then drops every facet ending there.
    const double onTol = 1e-8 * std::max(lref, 1e-300);
    auto onCrack = [&](const xfem::CutPoint& point, size_t j) { return std::abs(point.lsn[j]) <= onTol; };

    // Faces on a parent face (no partner inside the cell), per crack and side, by coordinates.
    using Key = std::pair<int, std::vector<std::array<long long, 3>>>;
    std::map<Key, FaceOnCrack> pendingMinus, pendingPlus;

    auto makeSide = [&](const xfem::CellCut& cut, int s, const std::vector<int>& pts, const std::vector<Vec>& xyz,
                        const std::map<std::vector<signed char>, double>& blocks) {
        FacetSide side;
        side.cell = cut.cell;
        side.subcell = s;
        side.blockMeasure = blocks.at(cut.subcells[s].heaviside);
        for (const auto& [tuple, measure] : blocks) side.cellMeasure += measure;
        for (int p : pts) side.ref.push_back(cut.points[p].ref);
        (void)xyz;
        return side;
    };
    auto finishFacet = [&](ContactFacet& f, const std::vector<Vec>& verts, const Vec& towardsPlus) {
        f.vertices = verts;
        Vec n{};
        if (dim == 2) {
            const Vec t = sub(verts[1], verts[0]);
            f.measure = norm(t);
            n = {t[1], -t[0], 0.0};
        } else {
            n = cross(sub(verts[1], verts[0]), sub(verts[2], verts[0]));
            f.measure = 0.5 * norm(n);
        }
        const double len = norm(n);
        if (len == 0.0) return false;
        for (auto& v : n) v /= len;
        if (dot(n, towardsPlus) < 0.0)
            for (auto& v : n) v = -v;
        f.normal = n;
        return true;
    };
    auto centroid = [&](const std::vector<Vec>& xyz, const xfem::SubCell& s) {
        Vec c{};
        for (int i = 0; i <= dim; ++i)
            for (int j = 0; j < 3; ++j) c[j] += xyz[s.vertices[i]][j] / (dim + 1);
        return c;
    };

    // Map from block pairs to facets (pairMeasure).
    std::map<std::tuple<int, int, std::vector<signed char>, int, std::vector<signed char>, int>, std::vector<size_t>> pairs;

    for (int cell : xm.xfemCells()) {
        const auto* cut = xm.cut(cell);
        if (cut->skin) continue;
        const auto xyz = physicalPoints(mesh, *cut);
        std::map<std::vector<signed char>, double> blocks;
        bool blocksDone = false;
        for (size_t j = 0; j < cut->cracks.size(); ++j) {
            const int crack = cut->cracks[j];
            if (crack >= int(withContact.size()) || !withContact[crack]) continue;
            for (int s = 0; s < int(cut->subcells.size()); ++s) {
                const auto& sc = cut->subcells[s];
                if (sc.heaviside[j] == 0) continue;
                for (const auto& face : simplexFaces(dim)) {
                    std::vector<int> pts;
                    bool on = true;
                    for (int v : face) {
                        const int p = sc.vertices[v];
                        pts.push_back(p);
                        on = on && onCrack(cut->points[p], j);
                    }
                    if (!on) continue;
                    std::vector<int> sortedPts = pts;
                    std::sort(sortedPts.begin(), sortedPts.end());
                    // Partner inside the cell: the sub-cell on the other side sharing the face.
                    int partner = -1;
                    for (int t = 0; t < int(cut->subcells.size()) && partner < 0; ++t) {
                        if (t == s || cut->subcells[t].heaviside[j] != -sc.heaviside[j]) continue;
                        std::vector<int> tv(cut->subcells[t].vertices.begin(), cut->subcells[t].vertices.begin() + dim + 1);
                        std::sort(tv.begin(), tv.end());
                        if (std::includes(tv.begin(), tv.end(), sortedPts.begin(), sortedPts.end())) partner = t;
                    }
                    if (!blocksDone) blocks = blockMeasures(dim, xyz, *cut), blocksDone = true;
                    std::vector<Vec> verts;
                    for (int p : pts) verts.push_back(xyz[p]);
                    if (partner < 0) {
                        // On a parent face: matched with the neighbouring cell below.
                        FaceOnCrack f{cell, s, pts, true};
                        for (int p : pts) f.exact = f.exact && cut->points[p].lsn[j] == 0.0;
                        auto& pending = sc.heaviside[j] < 0 ? pendingMinus : pendingPlus;
                        pending.emplace(Key{crack, coordinateKey(verts, keyTol)}, f);
                        continue;
                    }
                    if (sc.heaviside[j] > 0) continue;  // each facet once, from its - side
                    ContactFacet f;
                    f.crack = crack;
                    f.minus = makeSide(*cut, s, pts, xyz, blocks);
                    f.plus = makeSide(*cut, partner, pts, xyz, blocks);
                    if (!finishFacet(f, verts, sub(centroid(xyz, cut->subcells[partner]), centroid(xyz, sc)))) continue;
                    for (int p : pts)
                        for (size_t k = 0; k < cut->cracks.size(); ++k)
                            if (k != j && onCrack(cut->points[p], k)) f.atJunction = true;
                    pairs[{cell, cell, sc.heaviside, crack, cut->subcells[partner].heaviside, 0}].push_back(facets.size());
                    facets.push_back(std::move(f));
                }
            }
        }
    }
    // Facets between two parent cells.
    // A face on an interface with no partner: on the boundary of the model (legitimately free), or
    // inside its cell where no sub-cell of the other side shares it (in 3D, sliver pieces dropped by
    // the cut as degenerate): there the weak form misses the interface term (counted, ContactLoop).
    // Only faces inside their parent cell are counted (a face on a parent face without partner is
    // on the boundary of the model or of the enriched zone).
    // Faces only within onTol of the interface are not counted: a sub-cell face 1e-8 h from the
    // interface (interfaces 1e-4 h from node rows) is no interface face and has no partner.
    auto unmatched = [&](const FaceOnCrack& f) {
        if (!f.exact) return;
        const auto* cut = xm.cut(f.cell);
        std::vector<Vec> ref;
        for (int p : f.points) ref.push_back(cut->points[p].ref);
        if (onParentFace(cut->type, ref)) return;
        const auto xyz = physicalPoints(mesh, *cut);
        std::vector<Vec> verts;
        for (int p : f.points) verts.push_back(xyz[p]);
        ContactFacet probe;
        if (!finishFacet(probe, verts, Vec{1.0, 0.0, 0.0})) return;
        ++st.unmatched;
        st.unmatchedMeasure += probe.measure;
    };
    for (const auto& [key, fp] : pendingPlus)
        if (!pendingMinus.count(key)) unmatched(fp);
    for (const auto& [key, fm] : pendingMinus) {
        auto it = pendingPlus.find(key);
        if (it == pendingPlus.end()) {
            unmatched(fm);
            continue;
        }
        const FaceOnCrack& fp = it->second;
        const auto* cm = xm.cut(fm.cell);
        const auto* cp = xm.cut(fp.cell);
        const auto xm_ = physicalPoints(mesh, *cm);
        const auto xp_ = physicalPoints(mesh, *cp);
        const auto bm = blockMeasures(dim, xm_, *cm);
        const auto bp = blockMeasures(dim, xp_, *cp);
        ContactFacet f;
        f.crack = key.first;
        f.minus = makeSide(*cm, fm.subcell, fm.points, xm_, bm);
        // + side vertices in the order of the - side's vertices.
        std::vector<Vec> verts;
        for (int p : fm.points) verts.push_back(xm_[p]);
        FacetSide plus;
        plus.cell = fp.cell;
        plus.subcell = fp.subcell;
        plus.blockMeasure = bp.at(cp->subcells[fp.subcell].heaviside);
        for (const auto& [tuple, measure] : bp) plus.cellMeasure += measure;
        for (const auto& v : verts) {
            int best = fp.points[0];
            double bestD = 1e300;
            for (int p : fp.points) {
                const double d = norm(sub(xp_[p], v));
                if (d < bestD) bestD = d, best = p;
            }
            plus.ref.push_back(cp->points[best].ref);
        }
        f.plus = plus;
        for (int p : fm.points)
            for (size_t k = 0; k < cm->cracks.size(); ++k)
                if (cm->cracks[k] != key.first && onCrack(cm->points[p], k)) f.atJunction = true;
        if (!finishFacet(f, verts, sub(centroid(xp_, cp->subcells[fp.subcell]), centroid(xm_, cm->subcells[fm.subcell]))))
            continue;
        pairs[{fm.cell, fp.cell, cm->subcells[fm.subcell].heaviside, key.first, cp->subcells[fp.subcell].heaviside, 1}]
            .push_back(facets.size());
        facets.push_back(std::move(f));
        ++st.acrossParentFaces;
    }
    for (const auto& [key, list] : pairs) {
        double total = 0.0;
        for (size_t i : list) total += facets[i].measure;
        for (size_t i : list) facets[i].pairMeasure = total;
    }
    for (const auto& f : facets) {
        ++st.facets;
        st.atJunction += f.atJunction;
        st.totalMeasure += f.measure;
    }
    if (stats) *stats = st;
    return facets;
}

}  // namespace ma::contact
