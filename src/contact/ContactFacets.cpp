#include "contact/ContactFacets.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "core/Error.hpp"
#include "core/Vec3.hpp"
#include "mesh/ShapeFunctions.hpp"
#include "xfem/CellGeometry.hpp"
#include "xfem/XfemModel.hpp"

namespace ma::contact {

namespace {

// Faces of a simplex of dimension d (local vertex numbers): triangle edges, tetrahedron faces.
const std::vector<std::vector<int>>& simplexFaces(int d) {
    static const std::vector<std::vector<int>> tri{{0, 1}, {1, 2}, {2, 0}};
    static const std::vector<std::vector<int>> tet{{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
    return d == 2 ? tri : tet;
}

std::vector<Vec3> nodeCoordinates(const Mesh& mesh, int cell) {
    const auto nodes = mesh.cellNodes(cell);
    std::vector<Vec3> xyz(nodes.size());
    for (size_t a = 0; a < nodes.size(); ++a) xyz[a] = mesh.coords[nodes[a]];
    return xyz;
}

// Physical coordinates of the points of a cut cell.
std::vector<Vec3> physicalPoints(const Mesh& mesh, const xfem::CellCut& cut) {
    const auto xyz = nodeCoordinates(mesh, cut.cell);
    std::vector<Vec3> out;
    out.reserve(cut.points.size());
    for (const auto& p : cut.points) out.push_back(mapToPhysical(cut.type, xyz, p.ref));
    return out;
}

double subcellMeasure(int dim, const std::vector<Vec3>& xyz, const xfem::SubCell& s) {
    std::vector<Vec3> v;
    for (int i = 0; i <= dim; ++i) v.push_back(xyz[s.vertices[i]]);
    return std::abs(xfem::simplexMeasure(dim, v));
}

// Physical measure of every block (Heaviside tuple) of a cut cell.
std::map<std::vector<signed char>, double> blockMeasures(int dim, const std::vector<Vec3>& xyz, const xfem::CellCut& cut) {
    std::map<std::vector<signed char>, double> out;
    for (const auto& s : cut.subcells) out[s.heaviside] += subcellMeasure(dim, xyz, s);
    return out;
}

// A face of a sub-cell lying on a crack, seen from one side.
struct FaceOnCrack {
    int cell, subcell;
    std::vector<int> points;  // CutPoint indices
    bool exact = true;        // every vertex has a level set of exactly 0 (not only within onTol)
    int local = -1;           // index of the crack in the cell's crack list
};

// Intersection of two coplanar triangles (3D), in the reference coordinates of their parent cell.
using Point2 = std::array<double, 2>;

double orient(const Point2& o, const Point2& a, const Point2& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

double polygonArea(const std::vector<Point2>& p) {
    double a = 0.0;
    for (size_t i = 0; i < p.size(); ++i) {
        const Point2& q = p[i];
        const Point2& r = p[(i + 1) % p.size()];
        a += q[0] * r[1] - q[1] * r[0];
    }
    return 0.5 * a;
}

// Sutherland-Hodgman: the part of `subject` inside the convex counter-clockwise polygon `clip`.
std::vector<Point2> clipConvex(std::vector<Point2> subject, const std::vector<Point2>& clip) {
    for (size_t e = 0; e < clip.size() && !subject.empty(); ++e) {
        const Point2& a = clip[e];
        const Point2& b = clip[(e + 1) % clip.size()];
        std::vector<Point2> out;
        for (size_t i = 0; i < subject.size(); ++i) {
            const Point2& p = subject[i];
            const Point2& q = subject[(i + 1) % subject.size()];
            const double dp = orient(a, b, p), dq = orient(a, b, q);
            if (dp >= 0.0) out.push_back(p);
            if ((dp >= 0.0) != (dq >= 0.0)) {
                const double t = dp / (dp - dq);
                out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
            }
        }
        subject = std::move(out);
    }
    return subject;
}

// Triangles (reference coordinates, on the plane of `a`) covering the intersection of the nearly
// coplanar reference triangles a and b; `negligible` is the smallest reference area kept.
std::vector<std::array<Vec3, 3>> triangleIntersection(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b,
                                                     double negligible) {
    // Project on the two coordinates most parallel to the plane of a.
    const Vec3 n = cross(difference(a[1], a[0]), difference(a[2], a[0]));
    int k = 0;
    for (int i = 1; i < 3; ++i)
        if (std::abs(n[i]) > std::abs(n[k])) k = i;
    const int u = (k + 1) % 3, v = (k + 2) % 3;
    auto project = [&](const std::array<Vec3, 3>& t) {
        std::vector<Point2> p{{t[0][u], t[0][v]}, {t[1][u], t[1][v]}, {t[2][u], t[2][v]}};
        if (polygonArea(p) < 0.0) std::swap(p[1], p[2]);
        return p;
    };
    const auto pa = project(a), pb = project(b);
    const double areaA = polygonArea(pa);
    if (areaA <= 0.0 || polygonArea(pb) <= 0.0) return {};
    const auto poly = clipConvex(pa, pb);
    if (poly.size() < 3 || polygonArea(poly) <= negligible) return {};
    // Back to 3D on the plane of a, through the barycentric coordinates in its projection.
    const std::array<Vec3, 3> ta = polygonArea({{a[0][u], a[0][v]}, {a[1][u], a[1][v]}, {a[2][u], a[2][v]}}) > 0.0
                                      ? a
                                      : std::array<Vec3, 3>{a[0], a[2], a[1]};
    auto lift = [&](const Point2& p) {
        const double l1 = orient(pa[2], pa[0], p) / areaA / 2.0;
        const double l2 = orient(pa[0], pa[1], p) / areaA / 2.0;
        const double l0 = 1.0 - l1 - l2;
        Vec3 r{};
        for (int j = 0; j < 3; ++j) r[j] = l0 * ta[0][j] + l1 * ta[1][j] + l2 * ta[2][j];
        return r;
    };
    std::vector<std::array<Vec3, 3>> out;
    const double total = polygonArea(poly);
    for (size_t i = 1; i + 1 < poly.size(); ++i)
        if (orient(poly[0], poly[i], poly[i + 1]) > 1e-12 * total) out.push_back({lift(poly[0]), lift(poly[i]), lift(poly[i + 1])});
    return out;
}

// Part of the reference segment b on the reference segment a (2D: the two sides of an interface split
// it at different points, one side cut by a branch at the junction, the other not); `negligible` is
// the smallest reference length kept. On the line of a.
std::vector<std::vector<Vec3>> segmentIntersection(const std::array<Vec3, 2>& a, const std::array<Vec3, 2>& b,
                                                  double negligible) {
    const Vec3 e = difference(a[1], a[0]);
    const double ee = dot(e, e);
    if (!(ee > 0.0)) return {};
    const double t0 = dot(difference(b[0], a[0]), e) / ee, t1 = dot(difference(b[1], a[0]), e) / ee;
    const double lo = std::max(0.0, std::min(t0, t1)), hi = std::min(1.0, std::max(t0, t1));
    if ((hi - lo) * std::sqrt(ee) <= negligible) return {};
    auto at = [&](double t) { return Vec3{a[0][0] + t * e[0], a[0][1] + t * e[1], a[0][2] + t * e[2]}; };
    return {{at(lo), at(hi)}};
}

// Face key by physical coordinates (rounded), vertex order independent.
std::vector<std::array<long long, 3>> coordinateKey(const std::vector<Vec3>& pts, double tol) {
    std::vector<std::array<long long, 3>> key;
    for (const auto& p : pts)
        key.push_back({std::llround(p[0] / tol), std::llround(p[1] / tol), std::llround(p[2] / tol)});
    std::sort(key.begin(), key.end());
    return key;
}

// Whether the points (reference coordinates of the parent) all lie on one face of the parent
// reference element (QUAD4/HEXA8: [-1,1]^d; TRIA3/TETRA4: unit simplex).
bool onParentFace(CellType type, const std::vector<Vec3>& ref) {
    constexpr double tol = 1e-12;
    const int d = (type == CellType::TRIA3 || type == CellType::QUAD4) ? 2 : 3;
    auto all = [&](auto pred) { return std::all_of(ref.begin(), ref.end(), pred); };
    const bool simplex = type == CellType::TRIA3 || type == CellType::TETRA4;
    for (int i = 0; i < d; ++i) {
        if (simplex && all([&](const Vec3& r) { return std::abs(r[i]) <= tol; })) return true;
        if (!simplex && (all([&](const Vec3& r) { return std::abs(r[i] - 1.0) <= tol; }) ||
                         all([&](const Vec3& r) { return std::abs(r[i] + 1.0) <= tol; })))
            return true;
    }
    if (simplex)
        return all([&](const Vec3& r) { return std::abs(r[0] + r[1] + (d == 3 ? r[2] : 0.0) - 1.0) <= tol; });
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
        for (size_t a = 1; a < nodes.size(); ++a) lref = std::max(lref, norm(difference(mesh.coords[nodes[a]], mesh.coords[nodes[0]])));
    }
    const double keyTol = 1e-9 * std::max(lref, 1e-300);
    // A cut point is on interface j when its level set is zero up to what CellCut's merging (1e-9
    // of an edge) leaves: a zero that close to an end of its edge, or to another crack's point on
    // it, is that point, whose level set is not 0. (When CellCut still merged points of different
    // edges, the junction point ended 1e-10 h off FISS1 with interfaces 1e-5 h from node rows and an
    // exact-zero test dropped every facet ending there; with exact cut points 1e-8 h and round-off
    // give the same facets, measured on the stability sweep's offsets.)
    const double onTol = 1e-8 * std::max(lref, 1e-300);
    auto onCrack = [&](const xfem::CutPoint& point, size_t j) { return std::abs(point.lsn[j]) <= onTol; };

    // Faces on a parent face (no partner inside the cell), per crack and side, by coordinates.
    using Key = std::pair<int, std::vector<std::array<long long, 3>>>;
    std::map<Key, FaceOnCrack> pendingMinus, pendingPlus;

    auto refOf = [](const xfem::CellCut& cut, const std::vector<int>& pts) {
        std::vector<Vec3> ref;
        for (int p : pts) ref.push_back(cut.points[p].ref);
        return ref;
    };
    auto makeSide = [&](const xfem::CellCut& cut, int s, std::vector<Vec3> ref,
                        const std::map<std::vector<signed char>, double>& blocks) {
        FacetSide side;
        side.cell = cut.cell;
        side.subcell = s;
        side.blockMeasure = blocks.at(cut.subcells[s].heaviside);
        for (const auto& [tuple, measure] : blocks) side.cellMeasure += measure;
        side.ref = std::move(ref);
        return side;
    };
    auto finishFacet = [&](ContactFacet& f, const std::vector<Vec3>& verts, const Vec3& towardsPlus) {
        f.vertices = verts;
        Vec3 n{};
        if (dim == 2) {
            const Vec3 t = difference(verts[1], verts[0]);
            f.measure = norm(t);
            n = {t[1], -t[0], 0.0};
        } else {
            n = cross(difference(verts[1], verts[0]), difference(verts[2], verts[0]));
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
    auto centroid = [&](const std::vector<Vec3>& xyz, const xfem::SubCell& s) {
        Vec3 c{};
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
                    std::vector<Vec3> verts;
                    for (int p : pts) verts.push_back(xyz[p]);
                    if (partner < 0) {
                        // On a parent face: matched with the neighbouring cell below.
                        FaceOnCrack f{cell, s, pts, true, int(j)};
                        for (int p : pts) f.exact = f.exact && cut->points[p].lsn[j] == 0.0;
                        auto& pending = sc.heaviside[j] < 0 ? pendingMinus : pendingPlus;
                        pending.emplace(Key{crack, coordinateKey(verts, keyTol)}, f);
                        continue;
                    }
                    if (sc.heaviside[j] > 0) continue;  // each facet once, from its - side
                    ContactFacet f;
                    f.crack = crack;
                    f.minus = makeSide(*cut, s, refOf(*cut, pts), blocks);
                    f.plus = makeSide(*cut, partner, refOf(*cut, pts), blocks);
                    if (!finishFacet(f, verts, difference(centroid(xyz, cut->subcells[partner]), centroid(xyz, sc)))) continue;
                    for (int p : pts)
                        for (size_t k = 0; k < cut->cracks.size(); ++k)
                            if (k != j && onCrack(cut->points[p], k)) f.atJunction = true;
                    pairs[{cell, cell, sc.heaviside, crack, cut->subcells[partner].heaviside, 0}].push_back(facets.size());
                    facets.push_back(std::move(f));
                }
            }
        }
    }
    // A face on an interface with no partner: on the boundary of the model (legitimately free), or
    // inside its cell where no sub-cell of the other side shares it: the two sides split that part of
    // the interface differently (a branch joined to it cuts its own side at the junction, the other
    // side stays whole where no branch cuts it), or the cut dropped a piece flat to round-off there.
    // Those faces are paired below (clipping, block across); faces on a parent face without partner
    // are on the boundary of the model or of the enriched zone.
    std::map<std::pair<int, int>, std::array<std::vector<FaceOnCrack>, 2>> loose;  // (cell, crack) -> -, + faces
    auto keepLoose = [&](const FaceOnCrack& f, int crack, bool plusSide) {
        if (!onParentFace(xm.cut(f.cell)->type, refOf(*xm.cut(f.cell), f.points)))
            loose[{f.cell, crack}][plusSide].push_back(f);
    };
    for (const auto& [key, fp] : pendingPlus)
        if (!pendingMinus.count(key)) keepLoose(fp, key.first, true);
    // Facets between two parent cells.
    for (const auto& [key, fm] : pendingMinus) {
        auto it = pendingPlus.find(key);
        if (it == pendingPlus.end()) {
            keepLoose(fm, key.first, false);
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
        f.minus = makeSide(*cm, fm.subcell, refOf(*cm, fm.points), bm);
        // + side vertices in the order of the - side's vertices.
        std::vector<Vec3> verts;
        for (int p : fm.points) verts.push_back(xm_[p]);
        std::vector<int> plusPoints;
        for (const auto& v : verts) {
            int best = fp.points[0];
            double bestD = 1e300;
            for (int p : fp.points) {
                const double d = norm(difference(xp_[p], v));
                if (d < bestD) bestD = d, best = p;
            }
            plusPoints.push_back(best);
        }
        f.plus = makeSide(*cp, fp.subcell, refOf(*cp, plusPoints), bp);
        for (int p : fm.points)
            for (size_t k = 0; k < cm->cracks.size(); ++k)
                if (cm->cracks[k] != key.first && onCrack(cm->points[p], k)) f.atJunction = true;
        if (!finishFacet(f, verts, difference(centroid(xp_, cp->subcells[fp.subcell]), centroid(xm_, cm->subcells[fm.subcell]))))
            continue;
        pairs[{fm.cell, fp.cell, cm->subcells[fm.subcell].heaviside, key.first, cp->subcells[fp.subcell].heaviside, 1}]
            .push_back(facets.size());
        facets.push_back(std::move(f));
        ++st.acrossParentFaces;
    }
    // Faces inside their cell without partner: each - face is paired with each + face of the same
    // cell and interface over their intersection, computed in the parent's reference coordinates
    // where the sub-cells are flat (2D: a branch joined to the interface splits the face of its side
    // at the junction point, the other side's face stays whole when no branch cuts it there).
    // A face no clipped piece touches is paired with the block across it (blockAcross); what stays
    // uncovered has no contact term: counted (alarm CONTACT_SLIVER in ContactLoop). Faces only within onTol of the interface are not counted: a
    // sub-cell face 1e-8 h from the interface (interfaces 1e-4 h from node rows) is no interface face.
    // Intersections below 1e-14 of the reference cell's face scale are round-off (triangles touching
    // along an edge).
    constexpr double kNegligibleReferenceArea = 1e-14;
    // A face no face of the other side touches (a sliver face whose overlaps are all below the
    // negligible measure, or a flat piece of the other side dropped by the cut). The facet is the
    // face itself, its other side the block just across it: Heaviside
    // digit of the face's interface flipped, the other interfaces' digits of the face's side of them
    // (or 0, the forbidden side of a branch). That block is looked for among the sub-cells of the
    // face's cell, then of the X-FEM cells around its nodes (the block's field there is a polynomial
    // of that cell, evaluated at the face through its inverse mapping): the nearest sub-cell, if the
    // digits name one block of its cell only.
    auto blockAcross = [&](const FaceOnCrack& face, int crack, bool plusSide) {
        const auto* cut = xm.cut(face.cell);
        const auto& h = cut->subcells[face.subcell].heaviside;
        const int j = face.local;
        const auto xyz = physicalPoints(mesh, *cut);
        Vec3 centre{};
        for (int p : face.points)
            for (int i = 0; i < 3; ++i) centre[i] += xyz[p][i] / double(face.points.size());
        std::map<int, std::pair<int, bool>> wanted;  // crack -> (digit, whether 0 is refused)
        wanted[crack] = {-h[j], true};
        for (size_t k = 0; k < cut->cracks.size(); ++k) {
            if (int(k) == j) continue;
            double mean = 0.0;
            for (int p : face.points) mean += cut->points[p].lsn[k] / double(face.points.size());
            if (std::abs(mean) > onTol) wanted[cut->cracks[k]] = {mean < 0.0 ? -1 : 1, false};
        }
        auto fits = [&](const xfem::CellCut& c, int t) {
            bool crosses = false;
            for (size_t k = 0; k < c.cracks.size(); ++k) {
                auto it = wanted.find(c.cracks[k]);
                if (it == wanted.end()) continue;
                const auto [digit, strict] = it->second;
                const int d = c.subcells[t].heaviside[k];
                if (d != digit && (strict || d != 0)) return false;
                crosses = crosses || c.cracks[k] == crack;
            }
            return crosses;
        };
        // Nearest sub-cell of the block in `other` (-1: none, or the digits fit several blocks).
        auto nearest = [&](const xfem::CellCut& other, double& distance) {
            const auto oxyz = physicalPoints(mesh, other);
            int best = -1;
            for (int t = 0; t < int(other.subcells.size()); ++t) {
                if (&other == cut && t == face.subcell) continue;
                if (!fits(other, t)) continue;
                if (best >= 0 && other.subcells[t].heaviside != other.subcells[best].heaviside) return -1;
                const double d = norm(difference(centroid(oxyz, other.subcells[t]), centre));
                if (best < 0 || d < distance) best = t, distance = d;
            }
            return best;
        };
        const xfem::CellCut* across = nullptr;
        int acrossSub = -1;
        double distance = 1e300;
        if ((acrossSub = nearest(*cut, distance)) >= 0) across = cut;
        if (!across) {
            std::vector<int> around;
            for (int n : mesh.cellNodes(face.cell))
                for (int c : xm.cellsOfNode(n)) around.push_back(c);
            std::sort(around.begin(), around.end());
            around.erase(std::unique(around.begin(), around.end()), around.end());
            for (int c : around) {
                const auto* other = xm.cut(c);
                if (c == face.cell || !other || other->skin) continue;
                double d = 1e300;
                const int t = nearest(*other, d);
                if (t >= 0 && d < distance) across = other, acrossSub = t, distance = d;
            }
        }
        if (!across) return false;
        std::vector<Vec3> verts;
        for (int p : face.points) verts.push_back(xyz[p]);
        std::vector<Vec3> acrossRef = refOf(*cut, face.points);
        if (across != cut) {
            const auto acrossNodes = nodeCoordinates(mesh, across->cell);
            for (size_t v = 0; v < verts.size(); ++v)
                if (!mapToReference(across->type, acrossNodes, verts[v], acrossRef[v])) return false;
        }
        const auto own = makeSide(*cut, face.subcell, refOf(*cut, face.points), blockMeasures(dim, xyz, *cut));
        const auto other = makeSide(*across, acrossSub, acrossRef, blockMeasures(dim, physicalPoints(mesh, *across), *across));
        ContactFacet f;
        f.crack = crack;
        f.minus = plusSide ? other : own;
        f.plus = plusSide ? own : other;
        const Vec3 fromOwn = difference(centroid(physicalPoints(mesh, *across), across->subcells[acrossSub]), centroid(xyz, cut->subcells[face.subcell]));
        const Vec3 towardsPlus = plusSide ? Vec3{-fromOwn[0], -fromOwn[1], -fromOwn[2]} : fromOwn;
        if (!finishFacet(f, verts, towardsPlus)) return false;
        for (int p : face.points)
            for (size_t k = 0; k < cut->cracks.size(); ++k)
                if (int(k) != j && onCrack(cut->points[p], k)) f.atJunction = true;
        const auto& minusCut = plusSide ? *across : *cut;
        const auto& plusCut = plusSide ? *cut : *across;
        pairs[{f.minus.cell, f.plus.cell, minusCut.subcells[f.minus.subcell].heaviside, crack,
               plusCut.subcells[f.plus.subcell].heaviside, f.minus.cell == f.plus.cell ? 0 : 1}]
            .push_back(facets.size());
        facets.push_back(std::move(f));
        ++st.acrossDropped;
        return true;
    };
    for (const auto& [key, sides] : loose) {
        const auto [cell, crack] = key;
        const auto* cut = xm.cut(cell);
        const auto nodeXyz = nodeCoordinates(mesh, cell);
        const auto xyz = physicalPoints(mesh, *cut);
        std::array<std::vector<double>, 2> covered{std::vector<double>(sides[0].size(), 0.0),
                                                   std::vector<double>(sides[1].size(), 0.0)};
        if (!sides[0].empty() && !sides[1].empty()) {
            const auto blocks = blockMeasures(dim, xyz, *cut);
            const int j = sides[0].front().local;
            // Points of a face on another interface of the cell: its vertices there, and the edges
            // between two of them (a clipped vertex there touches a junction).
            auto onOtherCrack = [&](const FaceOnCrack& f, const Vec3& r) {
                for (size_t k = 0; k < cut->cracks.size(); ++k) {
                    if (int(k) == j) continue;
                    for (size_t a = 0; a < f.points.size(); ++a)
                        for (size_t b = a; b < f.points.size(); ++b) {
                            const auto& pa = cut->points[f.points[a]];
                            const auto& pb = cut->points[f.points[b]];
                            if (!onCrack(pa, k) || !onCrack(pb, k)) continue;
                            const Vec3 e = difference(pb.ref, pa.ref);
                            const double ee = dot(e, e);
                            const double t = ee > 0.0 ? std::clamp(dot(difference(r, pa.ref), e) / ee, 0.0, 1.0) : 0.0;
                            const Vec3 q{pa.ref[0] + t * e[0], pa.ref[1] + t * e[1], pa.ref[2] + t * e[2]};
                            if (norm(difference(r, q)) <= 1e-12) return true;
                        }
                }
                return false;
            };
            for (size_t a = 0; a < sides[0].size(); ++a)
                for (size_t b = 0; b < sides[1].size(); ++b) {
                    const FaceOnCrack& fm = sides[0][a];
                    const FaceOnCrack& fp = sides[1][b];
                    auto vertex = [&](const FaceOnCrack& f, int v) { return cut->points[f.points[v]].ref; };
                    std::vector<std::vector<Vec3>> pieces;
                    if (dim == 2) {
                        pieces = segmentIntersection({vertex(fm, 0), vertex(fm, 1)}, {vertex(fp, 0), vertex(fp, 1)},
                                                     kNegligibleReferenceArea);
                    } else {
                        for (const auto& t : triangleIntersection({vertex(fm, 0), vertex(fm, 1), vertex(fm, 2)},
                                                                  {vertex(fp, 0), vertex(fp, 1), vertex(fp, 2)}, kNegligibleReferenceArea))
                            pieces.emplace_back(t.begin(), t.end());
                    }
                    const Vec3 towardsPlus = difference(centroid(xyz, cut->subcells[fp.subcell]), centroid(xyz, cut->subcells[fm.subcell]));
                    for (const auto& piece : pieces) {
                        const std::vector<Vec3>& ref = piece;
                        std::vector<Vec3> verts;
                        for (const auto& r : ref) verts.push_back(mapToPhysical(cut->type, nodeXyz, r));
                        ContactFacet f;
                        f.crack = crack;
                        f.minus = makeSide(*cut, fm.subcell, ref, blocks);
                        f.plus = makeSide(*cut, fp.subcell, ref, blocks);
                        if (!finishFacet(f, verts, towardsPlus)) continue;
                        for (const auto& r : ref) f.atJunction = f.atJunction || onOtherCrack(fm, r) || onOtherCrack(fp, r);
                        covered[0][a] += f.measure;
                        covered[1][b] += f.measure;
                        pairs[{cell, cell, cut->subcells[fm.subcell].heaviside, crack, cut->subcells[fp.subcell].heaviside, 0}]
                            .push_back(facets.size());
                        facets.push_back(std::move(f));
                        ++st.clipped;
                    }
                }
        }
        for (int side = 0; side < 2; ++side)
            for (size_t a = 0; a < sides[side].size(); ++a) {
                const FaceOnCrack& f = sides[side][a];
                if (!f.exact) continue;
                std::vector<Vec3> verts;
                for (int p : f.points) verts.push_back(xyz[p]);
                ContactFacet probe;
                if (!finishFacet(probe, verts, Vec3{1.0, 0.0, 0.0})) continue;
                if (covered[side][a] == 0.0 && blockAcross(f, crack, side == 1)) continue;
                // Left uncovered, up to round-off and to what the clipping neglects (its threshold in
                // physical measure: the face's physical / reference measure ratio).
                double negligible = 1e-9 * probe.measure;
                if (covered[side][a] > 0.0) {
                    const auto& r = cut->points;
                    const Vec3 e1 = difference(r[f.points[1]].ref, r[f.points[0]].ref);
                    const double refMeasure =
                        dim == 2 ? norm(e1) : 0.5 * norm(cross(e1, difference(r[f.points[2]].ref, r[f.points[0]].ref)));
                    if (refMeasure > 0.0) negligible = std::max(negligible, kNegligibleReferenceArea * probe.measure / refMeasure);
                }
                const double left = probe.measure - covered[side][a];
                if (left <= negligible) continue;
                ++st.unmatched;
                st.unmatchedMeasure += left;
            }
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
