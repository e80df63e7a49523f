#include "contact/ContactFacets.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "contact/FaceClipping.hpp"
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
std::map<std::vector<signed char>, double> blockMeasures(int dim, const std::vector<Vec3>& xyz,
                                                         const xfem::CellCut& cut) {
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
    if (simplex) return all([&](const Vec3& r) { return std::abs(r[0] + r[1] + (d == 3 ? r[2] : 0.0) - 1.0) <= tol; });
    return false;
}

// Builds the facets in named steps (docs/contact.md): faces shared by two sub-cells of one cell,
// faces matched across parent faces, then the faces left without partner (clipped against the
// other side's faces, or paired with the block across them).
class FacetBuilder {
public:
    FacetBuilder(const xfem::XfemModel& xm, const std::vector<char>& withContact)
        : xm_(xm), mesh_(xm.mesh()), dim_(xm.dim()), withContact_(withContact) {
        // Reference length of the mesh (rounding of the coordinate keys of faces on parent faces).
        double lref = 0.0;
        for (int cell : xm.xfemCells()) {
            const auto* cut = xm.cut(cell);
            if (cut->skin) continue;
            const auto nodes = mesh_.cellNodes(cell);
            for (size_t a = 1; a < nodes.size(); ++a)
                lref = std::max(lref, norm(difference(mesh_.coords[nodes[a]], mesh_.coords[nodes[0]])));
        }
        keyTol_ = 1e-9 * std::max(lref, 1e-300);
        // A cut point is on interface j when its level set is zero up to what CellCut's merging
        // (1e-9 of an edge) leaves: a zero that close to an end of its edge, or to another crack's
        // point on it, is that point, whose level set is not 0. (With exact cut points 1e-8 h and
        // round-off give the same facets, measured on the stability sweep's offsets; an exact-zero
        // test dropped every facet ending at a junction point 1e-10 h off an interface.)
        onTol_ = 1e-8 * std::max(lref, 1e-300);
    }

    std::vector<ContactFacet> build(FacetStatistics* stats) {
        for (int cell : xm_.xfemCells()) facetsInsideCell(cell);
        facetsAcrossParentFaces();
        for (const auto& [key, sides] : loose_) pairLooseFaces(key.first, key.second, sides);
        for (const auto& [key, list] : pairs_) {
            double total = 0.0;
            for (size_t i : list) total += facets_[i].measure;
            for (size_t i : list) facets_[i].pairMeasure = total;
        }
        for (const auto& f : facets_) {
            ++st_.facets;
            st_.atJunction += f.atJunction;
            st_.totalMeasure += f.measure;
        }
        if (stats) *stats = st_;
        return std::move(facets_);
    }

private:
    // Faces on a parent face (no partner inside the cell), per crack and side, by coordinates.
    using Key = std::pair<int, std::vector<std::array<long long, 3>>>;
    // Facets of one crack between the same two blocks of the same parent cell(s): (-cell, +cell,
    // - tuple, crack, + tuple, across parent faces).
    using PairKey = std::tuple<int, int, std::vector<signed char>, int, std::vector<signed char>, int>;
    using Blocks = std::map<std::vector<signed char>, double>;
    // Intersections below 1e-14 of the reference cell's face scale are round-off (triangles
    // touching along an edge).
    static constexpr double kNegligibleReferenceArea = 1e-14;

    bool onCrack(const xfem::CutPoint& point, size_t j) const { return std::abs(point.lsn[j]) <= onTol_; }

    static std::vector<Vec3> refOf(const xfem::CellCut& cut, const std::vector<int>& pts) {
        std::vector<Vec3> ref;
        for (int p : pts) ref.push_back(cut.points[p].ref);
        return ref;
    }

    static FacetSide makeSide(const xfem::CellCut& cut, int s, std::vector<Vec3> ref, const Blocks& blocks) {
        FacetSide side;
        side.cell = cut.cell;
        side.subcell = s;
        side.blockMeasure = blocks.at(cut.subcells[s].heaviside);
        for (const auto& [tuple, measure] : blocks) side.cellMeasure += measure;
        side.ref = std::move(ref);
        return side;
    }

    // Vertices, measure and unit normal (oriented towards the + side); false for a degenerate face.
    bool finishFacet(ContactFacet& f, const std::vector<Vec3>& verts, const Vec3& towardsPlus) const {
        f.vertices = verts;
        Vec3 n{};
        if (dim_ == 2) {
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
    }

    Vec3 centroid(const std::vector<Vec3>& xyz, const xfem::SubCell& s) const {
        Vec3 c{};
        for (int i = 0; i <= dim_; ++i)
            for (int j = 0; j < 3; ++j) c[j] += xyz[s.vertices[i]][j] / (dim_ + 1);
        return c;
    }

    // Whether point p of the cut is on another interface of the cell than local crack j.
    bool onOtherCrack(const xfem::CellCut& cut, int p, size_t j) const {
        for (size_t k = 0; k < cut.cracks.size(); ++k)
            if (k != j && onCrack(cut.points[p], k)) return true;
        return false;
    }

    void addFacet(ContactFacet&& f, const PairKey& key) {
        pairs_[key].push_back(facets_.size());
        facets_.push_back(std::move(f));
    }

    bool wanted(int crack) const { return crack < int(withContact_.size()) && withContact_[crack]; }

    // Step 1: every face of a sub-cell of `cell` on an interface with contact. A face shared with
    // a sub-cell of the other side is a facet (from its - side); one without partner waits on the
    // parent face for the neighbouring cell.
    void facetsInsideCell(int cell) {
        const auto* cut = xm_.cut(cell);
        if (cut->skin) return;
        const auto xyz = physicalPoints(mesh_, *cut);
        Blocks blocks;
        bool blocksDone = false;
        for (size_t j = 0; j < cut->cracks.size(); ++j) {
            if (!wanted(cut->cracks[j])) continue;
            for (int s = 0; s < int(cut->subcells.size()); ++s) {
                if (cut->subcells[s].heaviside[j] == 0) continue;
                for (const auto& face : simplexFaces(dim_)) {
                    std::vector<int> pts;
                    bool on = true;
                    for (int v : face) {
                        pts.push_back(cut->subcells[s].vertices[v]);
                        on = on && onCrack(cut->points[pts.back()], j);
                    }
                    if (!on) continue;
                    if (!blocksDone) blocks = blockMeasures(dim_, xyz, *cut), blocksDone = true;
                    faceOnCrack(*cut, j, s, pts, xyz, blocks);
                }
            }
        }
    }

    // The sub-cell on the other side of local crack j that shares the face `pts`, -1 if none.
    int partnerInCell(const xfem::CellCut& cut, size_t j, int s, const std::vector<int>& pts) const {
        std::vector<int> sortedPts = pts;
        std::sort(sortedPts.begin(), sortedPts.end());
        for (int t = 0; t < int(cut.subcells.size()); ++t) {
            if (t == s || cut.subcells[t].heaviside[j] != -cut.subcells[s].heaviside[j]) continue;
            std::vector<int> tv(cut.subcells[t].vertices.begin(), cut.subcells[t].vertices.begin() + dim_ + 1);
            std::sort(tv.begin(), tv.end());
            if (std::includes(tv.begin(), tv.end(), sortedPts.begin(), sortedPts.end())) return t;
        }
        return -1;
    }

    void faceOnCrack(const xfem::CellCut& cut, size_t j, int s, const std::vector<int>& pts,
                     const std::vector<Vec3>& xyz, const Blocks& blocks) {
        const auto& sc = cut.subcells[s];
        const int crack = cut.cracks[j];
        const int partner = partnerInCell(cut, j, s, pts);
        std::vector<Vec3> verts;
        for (int p : pts) verts.push_back(xyz[p]);
        if (partner < 0) {  // on a parent face: matched with the neighbouring cell in step 2
            FaceOnCrack f{cut.cell, s, pts, true, int(j)};
            for (int p : pts) f.exact = f.exact && cut.points[p].lsn[j] == 0.0;
            auto& pending = sc.heaviside[j] < 0 ? pendingMinus_ : pendingPlus_;
            pending.emplace(Key{crack, coordinateKey(verts, keyTol_)}, f);
            return;
        }
        if (sc.heaviside[j] > 0) return;  // each facet once, from its - side
        ContactFacet f;
        f.crack = crack;
        f.minus = makeSide(cut, s, refOf(cut, pts), blocks);
        f.plus = makeSide(cut, partner, refOf(cut, pts), blocks);
        if (!finishFacet(f, verts, difference(centroid(xyz, cut.subcells[partner]), centroid(xyz, sc)))) return;
        for (int p : pts) f.atJunction = f.atJunction || onOtherCrack(cut, p, j);
        addFacet(std::move(f), {cut.cell, cut.cell, sc.heaviside, crack, cut.subcells[partner].heaviside, 0});
    }

    // A face on an interface with no partner: on the boundary of the model (legitimately free), or
    // inside its cell where no sub-cell of the other side shares it: the two sides split that part
    // of the interface differently, or the cut dropped a piece flat to round-off there. Those are
    // kept for step 3; faces on a parent face without partner are on the boundary of the model or
    // of the enriched zone.
    void keepLoose(const FaceOnCrack& f, int crack, bool plusSide) {
        if (!onParentFace(xm_.cut(f.cell)->type, refOf(*xm_.cut(f.cell), f.points)))
            loose_[{f.cell, crack}][plusSide].push_back(f);
    }

    // Step 2: faces on a parent face matched by coordinates with the other side's in the
    // neighbouring cell.
    void facetsAcrossParentFaces() {
        for (const auto& [key, fp] : pendingPlus_)
            if (!pendingMinus_.count(key)) keepLoose(fp, key.first, true);
        for (const auto& [key, fm] : pendingMinus_) {
            auto it = pendingPlus_.find(key);
            if (it == pendingPlus_.end()) keepLoose(fm, key.first, false);
            else facetAcrossParentFace(key.first, fm, it->second);
        }
    }

    void facetAcrossParentFace(int crack, const FaceOnCrack& fm, const FaceOnCrack& fp) {
        const auto* cm = xm_.cut(fm.cell);
        const auto* cp = xm_.cut(fp.cell);
        const auto xm = physicalPoints(mesh_, *cm);
        const auto xp = physicalPoints(mesh_, *cp);
        ContactFacet f;
        f.crack = crack;
        f.minus = makeSide(*cm, fm.subcell, refOf(*cm, fm.points), blockMeasures(dim_, xm, *cm));
        // + side vertices in the order of the - side's vertices.
        std::vector<Vec3> verts;
        for (int p : fm.points) verts.push_back(xm[p]);
        std::vector<int> plusPoints;
        for (const auto& v : verts) {
            int best = fp.points[0];
            double bestD = 1e300;
            for (int p : fp.points)
                if (const double d = norm(difference(xp[p], v)); d < bestD) bestD = d, best = p;
            plusPoints.push_back(best);
        }
        f.plus = makeSide(*cp, fp.subcell, refOf(*cp, plusPoints), blockMeasures(dim_, xp, *cp));
        for (int p : fm.points)
            for (size_t k = 0; k < cm->cracks.size(); ++k)
                if (cm->cracks[k] != crack && onCrack(cm->points[p], k)) f.atJunction = true;
        if (!finishFacet(f, verts,
                         difference(centroid(xp, cp->subcells[fp.subcell]), centroid(xm, cm->subcells[fm.subcell]))))
            return;
        addFacet(std::move(f),
                 {fm.cell, fp.cell, cm->subcells[fm.subcell].heaviside, crack, cp->subcells[fp.subcell].heaviside, 1});
        ++st_.acrossParentFaces;
    }

    // Step 3 for one cell and interface: each - face is paired with each + face over their
    // intersection in the parent's reference coordinates; a face no clipped piece touches is paired
    // with the block across it; what stays uncovered has no contact term and is counted (alarm
    // CONTACT_SLIVER in ContactLoop). Faces only within onTol of the interface are not counted: a
    // sub-cell face 1e-8 h from the interface (interfaces 1e-4 h from node rows) is no interface face.
    void pairLooseFaces(int cell, int crack, const std::array<std::vector<FaceOnCrack>, 2>& sides) {
        const auto* cut = xm_.cut(cell);
        const auto xyz = physicalPoints(mesh_, *cut);
        std::array<std::vector<double>, 2> covered{std::vector<double>(sides[0].size(), 0.0),
                                                   std::vector<double>(sides[1].size(), 0.0)};
        if (!sides[0].empty() && !sides[1].empty()) {
            const auto blocks = blockMeasures(dim_, xyz, *cut);
            for (size_t a = 0; a < sides[0].size(); ++a)
                for (size_t b = 0; b < sides[1].size(); ++b)
                    clipFaces(*cut, crack, xyz, blocks, sides[0][a], sides[1][b], covered[0][a], covered[1][b]);
        }
        for (int side = 0; side < 2; ++side)
            for (size_t a = 0; a < sides[side].size(); ++a)
                countUncovered(*cut, crack, xyz, sides[side][a], side, covered[side][a]);
    }

    // Whether reference point r of a face lies on another interface of the cell: at its vertices
    // there or on the edges between two of them (a clipped vertex there touches a junction).
    bool touchesOtherCrack(const xfem::CellCut& cut, const FaceOnCrack& f, const Vec3& r) const {
        for (size_t k = 0; k < cut.cracks.size(); ++k) {
            if (int(k) == f.local) continue;
            for (size_t a = 0; a < f.points.size(); ++a)
                for (size_t b = a; b < f.points.size(); ++b) {
                    const auto& pa = cut.points[f.points[a]];
                    const auto& pb = cut.points[f.points[b]];
                    if (!onCrack(pa, k) || !onCrack(pb, k)) continue;
                    const Vec3 e = difference(pb.ref, pa.ref);
                    const double ee = dot(e, e);
                    const double t = ee > 0.0 ? std::clamp(dot(difference(r, pa.ref), e) / ee, 0.0, 1.0) : 0.0;
                    const Vec3 q{pa.ref[0] + t * e[0], pa.ref[1] + t * e[1], pa.ref[2] + t * e[2]};
                    if (norm(difference(r, q)) <= 1e-12) return true;
                }
        }
        return false;
    }

    // Facets over the intersection of a - face and a + face of one cell (FaceClipping).
    void clipFaces(const xfem::CellCut& cut, int crack, const std::vector<Vec3>& xyz, const Blocks& blocks,
                   const FaceOnCrack& fm, const FaceOnCrack& fp, double& coveredMinus, double& coveredPlus) {
        auto vertex = [&](const FaceOnCrack& f, int v) { return cut.points[f.points[v]].ref; };
        std::vector<std::vector<Vec3>> pieces;
        if (dim_ == 2) {
            pieces = segmentIntersection({vertex(fm, 0), vertex(fm, 1)}, {vertex(fp, 0), vertex(fp, 1)},
                                         kNegligibleReferenceArea);
        } else {
            for (const auto& t :
                 triangleIntersection({vertex(fm, 0), vertex(fm, 1), vertex(fm, 2)},
                                      {vertex(fp, 0), vertex(fp, 1), vertex(fp, 2)}, kNegligibleReferenceArea))
                pieces.emplace_back(t.begin(), t.end());
        }
        const auto nodeXyz = nodeCoordinates(mesh_, cut.cell);
        const Vec3 towardsPlus =
            difference(centroid(xyz, cut.subcells[fp.subcell]), centroid(xyz, cut.subcells[fm.subcell]));
        for (const auto& ref : pieces) {
            std::vector<Vec3> verts;
            for (const auto& r : ref) verts.push_back(mapToPhysical(cut.type, nodeXyz, r));
            ContactFacet f;
            f.crack = crack;
            f.minus = makeSide(cut, fm.subcell, ref, blocks);
            f.plus = makeSide(cut, fp.subcell, ref, blocks);
            if (!finishFacet(f, verts, towardsPlus)) continue;
            for (const auto& r : ref)
                f.atJunction = f.atJunction || touchesOtherCrack(cut, fm, r) || touchesOtherCrack(cut, fp, r);
            coveredMinus += f.measure;
            coveredPlus += f.measure;
            addFacet(std::move(f), {cut.cell, cut.cell, cut.subcells[fm.subcell].heaviside, crack,
                                    cut.subcells[fp.subcell].heaviside, 0});
            ++st_.clipped;
        }
    }

    // A loose exact face: paired with the block across when nothing covers it, else the part left
    // uncovered (beyond round-off and what the clipping neglects) is counted.
    void countUncovered(const xfem::CellCut& cut, int crack, const std::vector<Vec3>& xyz, const FaceOnCrack& f,
                        int side, double covered) {
        if (!f.exact) return;
        std::vector<Vec3> verts;
        for (int p : f.points) verts.push_back(xyz[p]);
        ContactFacet probe;
        if (!finishFacet(probe, verts, Vec3{1.0, 0.0, 0.0})) return;
        if (covered == 0.0 && facetWithBlockAcross(f, crack, side == 1)) return;
        // The clipping's threshold in physical measure: the face's physical / reference measure ratio.
        double negligible = 1e-9 * probe.measure;
        if (covered > 0.0) {
            const auto& r = cut.points;
            const Vec3 e1 = difference(r[f.points[1]].ref, r[f.points[0]].ref);
            const double refMeasure =
                dim_ == 2 ? norm(e1) : 0.5 * norm(cross(e1, difference(r[f.points[2]].ref, r[f.points[0]].ref)));
            if (refMeasure > 0.0)
                negligible = std::max(negligible, kNegligibleReferenceArea * probe.measure / refMeasure);
        }
        const double left = probe.measure - covered;
        if (left <= negligible) return;
        ++st_.unmatched;
        st_.unmatchedMeasure += left;
    }

    // The Heaviside digits of the block across a face (a sliver face whose overlaps are all below
    // the negligible measure, or a flat piece of the other side dropped by the cut): the digit of
    // the face's interface flipped (0 refused), the other interfaces' digits of the face's side of
    // them (or 0, the forbidden side of a branch). By crack: (digit, whether 0 is refused).
    std::map<int, std::pair<int, bool>> digitsAcross(const FaceOnCrack& face, int crack) const {
        const auto* cut = xm_.cut(face.cell);
        const int j = face.local;
        std::map<int, std::pair<int, bool>> wanted;
        wanted[crack] = {-cut->subcells[face.subcell].heaviside[j], true};
        for (size_t k = 0; k < cut->cracks.size(); ++k) {
            if (int(k) == j) continue;
            double mean = 0.0;
            for (int p : face.points) mean += cut->points[p].lsn[k] / double(face.points.size());
            if (std::abs(mean) > onTol_) wanted[cut->cracks[k]] = {mean < 0.0 ? -1 : 1, false};
        }
        return wanted;
    }

    // Nearest sub-cell (centroid to `centre`) of the block with `digits` in `other`; -1 when none,
    // or when the digits fit several blocks. `skip`: the face's own sub-cell in its own cell.
    int nearestOfBlock(const xfem::CellCut& other, const std::map<int, std::pair<int, bool>>& digits, int crack,
                       const Vec3& centre, int skip, double& distance) const {
        auto fits = [&](int t) {
            bool crosses = false;
            for (size_t k = 0; k < other.cracks.size(); ++k) {
                auto it = digits.find(other.cracks[k]);
                if (it == digits.end()) continue;
                const auto [digit, strict] = it->second;
                const int d = other.subcells[t].heaviside[k];
                if (d != digit && (strict || d != 0)) return false;
                crosses = crosses || other.cracks[k] == crack;
            }
            return crosses;
        };
        const auto oxyz = physicalPoints(mesh_, other);
        int best = -1;
        for (int t = 0; t < int(other.subcells.size()); ++t) {
            if (t == skip || !fits(t)) continue;
            if (best >= 0 && other.subcells[t].heaviside != other.subcells[best].heaviside) return -1;
            const double d = norm(difference(centroid(oxyz, other.subcells[t]), centre));
            if (best < 0 || d < distance) best = t, distance = d;
        }
        return best;
    }

    // The block across a face, looked for among the sub-cells of the face's cell, then of the
    // X-FEM cells around its nodes (the block's field there is a polynomial of that cell, evaluated
    // at the face through its inverse mapping). Null when none.
    const xfem::CellCut* blockAcross(const FaceOnCrack& face, int crack, const Vec3& centre, int& acrossSub) const {
        const auto* cut = xm_.cut(face.cell);
        const auto digits = digitsAcross(face, crack);
        double distance = 1e300;
        if ((acrossSub = nearestOfBlock(*cut, digits, crack, centre, face.subcell, distance)) >= 0) return cut;
        std::vector<int> around;
        for (int n : mesh_.cellNodes(face.cell))
            for (int c : xm_.cellsOfNode(n)) around.push_back(c);
        std::sort(around.begin(), around.end());
        around.erase(std::unique(around.begin(), around.end()), around.end());
        const xfem::CellCut* across = nullptr;
        for (int c : around) {
            const auto* other = xm_.cut(c);
            if (c == face.cell || !other || other->skin) continue;
            double d = 1e300;
            const int t = nearestOfBlock(*other, digits, crack, centre, -1, d);
            if (t >= 0 && d < distance) across = other, acrossSub = t, distance = d;
        }
        return across;
    }

    // The facet of a face no face of the other side touches: the face itself, its other side the
    // block just across it. False when there is no such block.
    bool facetWithBlockAcross(const FaceOnCrack& face, int crack, bool plusSide) {
        const auto* cut = xm_.cut(face.cell);
        const auto xyz = physicalPoints(mesh_, *cut);
        Vec3 centre{};
        for (int p : face.points)
            for (int i = 0; i < 3; ++i) centre[i] += xyz[p][i] / double(face.points.size());
        int acrossSub = -1;
        const xfem::CellCut* across = blockAcross(face, crack, centre, acrossSub);
        if (!across) return false;
        std::vector<Vec3> verts;
        for (int p : face.points) verts.push_back(xyz[p]);
        std::vector<Vec3> acrossRef = refOf(*cut, face.points);
        if (across != cut) {
            const auto acrossNodes = nodeCoordinates(mesh_, across->cell);
            for (size_t v = 0; v < verts.size(); ++v)
                if (!mapToReference(across->type, acrossNodes, verts[v], acrossRef[v])) return false;
        }
        const auto acrossXyz = physicalPoints(mesh_, *across);
        const auto own = makeSide(*cut, face.subcell, refOf(*cut, face.points), blockMeasures(dim_, xyz, *cut));
        const auto other = makeSide(*across, acrossSub, acrossRef, blockMeasures(dim_, acrossXyz, *across));
        ContactFacet f;
        f.crack = crack;
        f.minus = plusSide ? other : own;
        f.plus = plusSide ? own : other;
        const Vec3 fromOwn =
            difference(centroid(acrossXyz, across->subcells[acrossSub]), centroid(xyz, cut->subcells[face.subcell]));
        const Vec3 towardsPlus = plusSide ? Vec3{-fromOwn[0], -fromOwn[1], -fromOwn[2]} : fromOwn;
        if (!finishFacet(f, verts, towardsPlus)) return false;
        for (int p : face.points) f.atJunction = f.atJunction || onOtherCrack(*cut, p, size_t(face.local));
        const auto& minusCut = plusSide ? *across : *cut;
        const auto& plusCut = plusSide ? *cut : *across;
        const PairKey key{f.minus.cell,
                          f.plus.cell,
                          minusCut.subcells[f.minus.subcell].heaviside,
                          crack,
                          plusCut.subcells[f.plus.subcell].heaviside,
                          f.minus.cell == f.plus.cell ? 0 : 1};
        addFacet(std::move(f), key);
        ++st_.acrossDropped;
        return true;
    }

    const xfem::XfemModel& xm_;
    const Mesh& mesh_;
    const int dim_;
    const std::vector<char>& withContact_;
    double keyTol_ = 0.0, onTol_ = 0.0;
    std::map<Key, FaceOnCrack> pendingMinus_, pendingPlus_;
    std::map<std::pair<int, int>, std::array<std::vector<FaceOnCrack>, 2>> loose_;  // (cell, crack) -> -, + faces
    std::map<PairKey, std::vector<size_t>> pairs_;
    std::vector<ContactFacet> facets_;
    FacetStatistics st_;
};

}  // namespace

std::vector<ContactFacet> buildContactFacets(const xfem::XfemModel& xm, const std::vector<char>& withContact,
                                             FacetStatistics* stats) {
    return FacetBuilder(xm, withContact).build(stats);
}

}  // namespace ma::contact
