// The crack-tip part of the X-FEM model (docs/cracks.md, "Crack-tip enrichment"): which nodes are
// tip-enriched, the local front bases, the quadrature of the tip cells' sub-cells and the tip
// fields of their integration points.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "core/Error.hpp"
#include "mesh/ElementGeometry.hpp"
#include "mesh/ShapeFunctions.hpp"
#include "xfem/CellGeometry.hpp"
#include "xfem/TipEnrichment.hpp"
#include "xfem/XfemModel.hpp"

namespace ma::xfem {

void XfemModel::buildTip() {
    const Mesh& mesh = *mesh_;
    for (size_t k = 0; k < cracks_.size(); ++k) {
        const Crack& c = *cracks_[k];
        if (c.nodeCountWithStatus(2) + c.nodeCountWithStatus(3) == 0) continue;
        if (tipCrack_ >= 0)
            throw NotImplemented(
                fmt::format("cracks {} and {} both have a front in the mesh: one crack with crack-tip "
                            "enrichment per model is supported",
                            cracks_[size_t(tipCrack_)]->name, c.name));
        if (!c.masters.empty()) throw NotImplemented("crack " + c.name + ": a crack with a front joined (JONCTION)");
        tipCrack_ = static_cast<int>(k);
    }
    if (tipCrack_ < 0) return;
    const Crack& crack = *cracks_[size_t(tipCrack_)];
    tipNodes_.assign(size_t(mesh.nodeCount()), 0);
    for (int n = 0; n < mesh.nodeCount(); ++n)
        tipNodes_[size_t(n)] = nodeIndex_[size_t(n)] >= 0 && crack.nodeStatus[size_t(n)] >= 2;
    // BASLOC at every node of the elements with a tip node (code_aster has it everywhere): the
    // basis at a point and the subtracted interpolation use all the element's nodes.
    std::vector<char> basisNodes(size_t(mesh.nodeCount()), 0);
    for (const CellCut& c : cuts_) {
        const auto cn = mesh.cellNodes(c.cell);
        if (std::any_of(cn.begin(), cn.end(), [&](int n) { return tipNodes_[size_t(n)] != 0; }))
            for (int n : cn) basisNodes[size_t(n)] = 1;
    }
    tipPoint_.assign(cuts_.size(), std::nullopt);
    if (dim_ == 3) {
        bases_ = frontBases(mesh, crack, basisNodes);
        return buildFrontLines(crack);
    }
    pointBases_ = frontPointBases(mesh, crack);
    if (pointBases_.empty()) throw InternalError("crack " + crack.name + ": tip-enriched nodes but no front point");
    nodeFront_.assign(size_t(mesh.nodeCount()), 0);
    for (int n = 0; n < mesh.nodeCount(); ++n)
        if (basisNodes[size_t(n)]) nodeFront_[size_t(n)] = int(nearestFrontPoint(pointBases_, mesh.coords[size_t(n)]));
    for (const auto& f : crack.fronts) frontPoints_.push_back(f.points[0]);
    for (size_t i = 0; i < cuts_.size(); ++i) {
        if (cuts_[i].skin) continue;
        for (const auto& f : crack.fronts)
            if (!tipPoint_[i]) tipPoint_[i] = referencePointIn(mesh, cuts_[i].cell, f.points[0]);
    }
}

TipBases XfemModel::tipBases() const {
    if (dim_ == 3) return {&bases_, nullptr, nullptr};
    return {nullptr, &pointBases_, &nodeFront_};
}

void XfemModel::buildFrontLines(const Crack& crack) {
    const Mesh& mesh = *mesh_;
    frontLine_.assign(cuts_.size(), std::nullopt);
    for (size_t i = 0; i < cuts_.size(); ++i) {
        if (cuts_[i].skin) continue;
        const auto cn = mesh.cellNodes(cuts_[i].cell);
        Vec3 centre{};
        for (int n : cn)
            for (int j = 0; j < 3; ++j) centre[size_t(j)] += mesh.coords[size_t(n)][size_t(j)] / double(cn.size());
        double best = std::numeric_limits<double>::infinity();
        std::array<Vec3, 2> segment{};
        for (const auto& f : crack.fronts)
            for (size_t k = 0; k + 1 < f.points.size(); ++k) {
                const Vec3 &a = f.points[k], &b = f.points[k + 1];
                const Vec3 ab = difference(b, a);
                const double l2 = dot(ab, ab);
                if (l2 == 0.0) continue;
                const double s = std::clamp(dot(difference(centre, a), ab) / l2, 0.0, 1.0);
                const double d = distance(centre, Vec3{a[0] + s * ab[0], a[1] + s * ab[1], a[2] + s * ab[2]});
                if (d < best) best = d, segment = {a, b};
            }
        if (!std::isfinite(best)) continue;
        const auto ra = referenceCoordinates(mesh, cuts_[i].cell, segment[0]);
        const auto rb = referenceCoordinates(mesh, cuts_[i].cell, segment[1]);
        const Vec3 O{ra[0], ra[1], ra[2]}, d{rb[0] - ra[0], rb[1] - ra[1], rb[2] - ra[2]};
        const double l = norm(d);
        if (l > 0) frontLine_[i] = std::array<Vec3, 3>{O, Vec3{d[0] / l, d[1] / l, d[2] / l}, Vec3{l, 0, 0}};
    }
}

namespace {

// Distance from the line through O along t (unit) to the tetrahedron V: in the plane normal to the
// line, from the line's point to the convex hull of the projected vertices (0 when the line
// crosses the tetrahedron). The vertices' own distances overstate it when the line passes near
// an edge or a face between them.
double tetrahedronLineDistance(const std::array<std::array<double, 3>, 4>& V, const Vec3& O, const Vec3& t) {
    std::array<std::array<double, 2>, 4> p;
    const Vec3 a = std::abs(t[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = cross(t, a), w = cross(t, u);
    const double nu = norm(u), nw = norm(w);
    for (int v = 0; v < 4; ++v) {
        const Vec3 d = difference(Vec3{V[size_t(v)][0], V[size_t(v)][1], V[size_t(v)][2]}, O);
        p[size_t(v)] = {dot(d, u) / nu, dot(d, w) / nw};
    }
    auto cross2 = [](const std::array<double, 2>& a0, const std::array<double, 2>& b0,
                     const std::array<double, 2>& c0) {
        return (b0[0] - a0[0]) * (c0[1] - a0[1]) - (b0[1] - a0[1]) * (c0[0] - a0[0]);
    };
    const std::array<double, 2> origin{0.0, 0.0};
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) {
            const auto &A = p[size_t(i)], &B = p[size_t(j)];
            const double ab[2] = {B[0] - A[0], B[1] - A[1]}, l2 = ab[0] * ab[0] + ab[1] * ab[1];
            const double s = l2 > 0 ? std::clamp((-A[0] * ab[0] - A[1] * ab[1]) / l2, 0.0, 1.0) : 0.0;
            best = std::min(best, std::hypot(A[0] + s * ab[0], A[1] + s * ab[1]));
            for (int k = j + 1; k < 4; ++k) {  // inside the triangle (i, j, k): the line crosses
                const auto& C = p[size_t(k)];
                const double c1 = cross2(A, B, origin), c2 = cross2(B, C, origin), c3 = cross2(C, A, origin);
                if ((c1 >= 0 && c2 >= 0 && c3 >= 0) || (c1 <= 0 && c2 <= 0 && c3 <= 0)) return 0.0;
            }
        }
    return best;
}

// A lower bound of the distance from the front segment {O, t, (length)} to the tetrahedron V: the
// distance to its line, combined with the gap between their extents along it. A curved front's
// segment line, extended, crosses sub-cells far from the front: they are not fanned (the fan's
// signed pieces would then weigh a smooth integrand with weights of both signs).
double tetrahedronSegmentGap(const std::array<std::array<double, 3>, 4>& V, const std::array<Vec3, 3>& segment) {
    const Vec3 &O = segment[0], &t = segment[1];
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& v : V) {
        const double along = dot(difference(Vec3{v[0], v[1], v[2]}, O), t);
        lo = std::min(lo, along), hi = std::max(hi, along);
    }
    const double gap = std::max({0.0, lo - segment[2][0], -hi});
    return std::hypot(tetrahedronLineDistance(V, O, t), gap);
}

}  // namespace

void XfemModel::tipSubcellRule3(const CellCut& cut, int s, std::vector<std::array<double, 3>>& points,
                                std::vector<double>& weights) const {
    const auto& sub = cut.subcells[size_t(s)];
    std::array<std::array<double, 3>, 4> V;
    for (int v = 0; v < 4; ++v) V[size_t(v)] = cut.points[size_t(sub.vertices[size_t(v)])].ref;
    const auto& line = frontLine_[size_t(cellIndex_[size_t(cut.cell)])];
    double diameter = 0.0;
    for (int v = 0; v < 4; ++v)
        for (int w = 0; w < v; ++w)
            diameter = std::max(diameter, distance(Vec3{V[size_t(v)][0], V[size_t(v)][1], V[size_t(v)][2]},
                                                   Vec3{V[size_t(w)][0], V[size_t(w)][1], V[size_t(w)][2]}));
    const double near = line ? tetrahedronSegmentGap(V, *line) : std::numeric_limits<double>::infinity();
    if (line && near <= kTipFanReach * diameter)
        return fannedTetrahedronRule(V, (*line)[0], (*line)[1], kTipRadialPoints, kTipAngularPoints, points, weights);
    // The 1/r term is analytic on the sub-cell but its nearest singularity is near/diameter away:
    // Gauss's error falls as that ratio's Bernstein factor to the power 2n (docs/cracks.md).
    const double ratio = line ? near / diameter : std::numeric_limits<double>::infinity();
    const int n = ratio < 0.5 ? kTipFarPoints + 4
                  : ratio < 1 ? kTipFarPoints + 2
                  : ratio < 2 ? kTipFarPoints + 1
                              : kTipFarPoints;
    tetrahedronGaussRule(V, n, points, weights);
}

void XfemModel::tipSubcellRule(const CellCut& cut, int s, std::vector<std::array<double, 3>>& points,
                               std::vector<double>& weights) const {
    const auto& sub = cut.subcells[size_t(s)];
    std::array<std::array<double, 3>, 3> V;
    for (int v = 0; v < 3; ++v) V[size_t(v)] = cut.points[size_t(sub.vertices[size_t(v)])].ref;
    const auto nodes = mesh_->cellNodes(cut.cell);
    const CellType type = mesh_->cellTypes[size_t(cut.cell)];
    auto toPhysical = [&](const std::array<double, 3>& xi) {
        std::array<double, 8> N{};
        shapeValues(type, xi, std::span<double>(N.data(), nodes.size()));
        Vec3 x{};
        for (size_t a = 0; a < nodes.size(); ++a)
            for (int j = 0; j < 3; ++j) x[size_t(j)] += N[a] * mesh_->coords[size_t(nodes[a])][size_t(j)];
        return x;
    };
    tipTriangleRule(V, tipPoint_[size_t(cellIndex_[size_t(cut.cell)])], toPhysical, frontPoints_, kTipGaussPoints,
                    kTipRefinement, points, weights);
}

bool XfemModel::tipMatrix(int cell, int subcell, const std::array<double, 3>& ref, double lambdaEff, double mu,
                          TipPoint& out) const {
    const CellCut* c = cut(cell);
    if (!c || tipNodes_.empty()) return false;
    const auto at = std::find(c->cracks.begin(), c->cracks.end(), tipCrack_);
    const signed char h =
        at == c->cracks.end() ? 1 : c->subcells[size_t(subcell)].heaviside[size_t(at - c->cracks.begin())];
    out.cell = cell, out.ref = ref;
    if (c->skin) {  // evaluated in the volume element the skin cell bounds, at the same physical point
        const int volume = adjacentVolume(cell);
        if (volume < 0) return false;
        const auto sn = mesh_->cellNodes(cell);
        std::array<double, 8> N{};
        shapeValues(mesh_->cellTypes[size_t(cell)], ref, std::span<double>(N.data(), sn.size()));
        Vec3 x{};
        for (size_t a = 0; a < sn.size(); ++a)
            for (int j = 0; j < 3; ++j) x[size_t(j)] += N[a] * mesh_->coords[size_t(sn[a])][size_t(j)];
        // 3D: the skin cell is a face of the volume, so Newton's point is on it (no inside test).
        const auto r = dim_ == 2 ? referencePointIn(*mesh_, volume, x)
                                 : std::optional<std::array<double, 3>>(referenceCoordinates(*mesh_, volume, x));
        if (!r) return false;
        out.cell = volume, out.ref = *r;
    }
    return tipMatrixOnSide(out.cell, out.ref, h, lambdaEff, mu, out);
}

bool XfemModel::tipMatrixOnSide(int cell, const std::array<double, 3>& ref, int side, double lambdaEff, double mu,
                                TipPoint& out) const {
    if (tipNodes_.empty()) return false;
    out.cell = cell, out.ref = ref;
    ElementIntegration one;
    one.cell = cell;
    one.refPoints = {ref};
    tipElementFields(*mesh_, cell, dim_, tipBases(), cracks_[size_t(tipCrack_)]->nodeStatus, tipNodes_,
                     {static_cast<signed char>(side < 0 ? -1 : 1)}, one);
    if (std::count(one.tip.begin(), one.tip.end(), 1) == 0) return false;
    applyTipLaw(one, lambdaEff, mu);
    for (size_t a = 0; a < one.tip.size() && a < 8; ++a)
        if (one.tip[a]) std::copy_n(one.tipValue(0, one.tipGroupOf(int(a))), 9, out.Phi[a]);
    return true;
}

int XfemModel::boundaryTipFields(int cell, const std::vector<std::array<double, 3>>& xyz,
                                 ElementIntegration& ei) const {
    if (tipNodes_.empty()) return -1;
    const auto faceNodes = mesh_->cellNodes(cell);
    int volume = isEnriched(cell) ? adjacentVolume(cell) : -1;
    for (int c : cellsOfNode(faceNodes[0])) {
        if (volume >= 0) break;
        const auto cn = mesh_->cellNodes(c);
        if (cuts_[size_t(cellIndex_[size_t(c)])].skin) continue;
        if (std::all_of(faceNodes.begin(), faceNodes.end(),
                        [&](int n) { return std::find(cn.begin(), cn.end(), n) != cn.end(); }))
            volume = c;
    }
    if (volume < 0) return -1;
    const Crack& crack = *cracks_[size_t(tipCrack_)];
    const auto vn = mesh_->cellNodes(volume);
    ElementIntegration vol;
    vol.cell = volume;
    std::vector<signed char> side;
    std::vector<Vec3> corners;
    for (int n : vn) corners.push_back(mesh_->coords[size_t(n)]);
    for (const auto& x : xyz) {
        std::array<double, 3> ref{};
        if (!mapToReference(mesh_->cellTypes[size_t(volume)], corners, x, ref)) return -1;
        std::array<double, 8> N{};
        shapeValues(mesh_->cellTypes[size_t(volume)], ref, std::span<double>(N.data(), vn.size()));
        double lsn = 0.0;
        for (size_t a = 0; a < vn.size(); ++a) lsn += N[a] * crack.lsn[size_t(vn[a])];
        vol.refPoints.push_back(ref);
        side.push_back(lsn < 0 ? -1 : 1);
    }
    tipElementFields(*mesh_, volume, dim_, tipBases(), crack.nodeStatus, tipNodes_, side, vol);
    ei.tip.assign(faceNodes.size(), 0);
    ei.tipGroup.assign(faceNodes.size(), 0);
    ei.tipGroups = vol.tipGroups;
    for (size_t a = 0; a < faceNodes.size(); ++a) {
        ei.tip[a] = tipNodes_[size_t(faceNodes[a])];
        const auto at = std::find(vn.begin(), vn.end(), faceNodes[a]);  // a face node is a volume node
        if (at != vn.end()) ei.tipGroup[a] = vol.tipGroup[size_t(at - vn.begin())];
    }
    ei.tipA = std::move(vol.tipA);
    ei.tipB = std::move(vol.tipB);
    return volume;
}

void XfemModel::tipFields(int cell, const TipLaw& law, ElementIntegration& ei) const {
    if (tipNodes_.empty() || !isEnriched(cell) || !ei.hasTip()) return;
    const CellCut& cut = cuts_[size_t(cellIndex_[size_t(cell)])];
    if (!cut.skin) addTipFields(cut, ei, &law);
}

void XfemModel::addTipFields(const CellCut& cut, ElementIntegration& out, const TipLaw* law) const {
    const auto at = std::find(cut.cracks.begin(), cut.cracks.end(), tipCrack_);
    std::vector<signed char> side(out.refPoints.size(), 1);
    if (at != cut.cracks.end())
        for (size_t p = 0; p < side.size(); ++p) {
            const signed char h = cut.subcells[size_t(out.pointSubcell[p])].heaviside[size_t(at - cut.cracks.begin())];
            side[p] = h < 0 ? -1 : 1;
        }
    tipElementFields(*mesh_, cut.cell, cut.dim, tipBases(), cracks_[size_t(tipCrack_)]->nodeStatus, tipNodes_, side,
                     out, law);
}

}  // namespace ma::xfem
