// The crack-tip fields of an element at its integration points (TipEnrichment.hpp's
// tipElementFields): per group of tip nodes, the Williams fields in the group's basis minus their
// interpolation at the element's nodes, and their gradients (docs/cracks.md, "The enrichment").
#include <algorithm>
#include <cmath>
#include <span>

#include "mesh/ElementGeometry.hpp"
#include "mesh/ShapeFunctions.hpp"
#include "xfem/TipEnrichment.hpp"

namespace ma::xfem {

namespace {

struct LocalPoint {
    double r = 0, theta = 0;
};

LocalPoint localPolar(const Vec3& x, const Vec3& origin, const Vec3& e1, const Vec3& e2) {
    const Vec3 og = difference(x, origin);
    const double x1 = dot(og, e1), x2 = dot(og, e2);
    return {std::sqrt(x1 * x1 + x2 * x2), std::atan2(x2, x1)};
}

// Phi and dPhi of one part (A or B) at a point: P [F - sum_b N_b F_b] and its gradient. The shifted
// field and its gradient depend on the mode and the local component only: computed once for the
// three global components (the same operations, in the same order, as per component).
void composePart(int dim, const double F[3][3], const double dF[3][3][2], const std::vector<std::array<double, 9>>& Fn,
                 std::span<const double> N, std::span<const double> gradN, const Vec3 e[3], double* out) {
    double shifted[3][3], slope[3][3][3];  // [m][k], [m][k][j]
    for (int m = 0; m < 3; ++m)
        for (int k = 0; k < dim; ++k) {
            double value = F[m][k];
            double gradShift[3] = {0, 0, 0};
            for (size_t b = 0; b < Fn.size(); ++b) {
                value -= N[b] * Fn[b][size_t(m * 3 + k)];
                for (int j = 0; j < 3; ++j) gradShift[j] += Fn[b][size_t(m * 3 + k)] * gradN[b * 3 + size_t(j)];
            }
            shifted[m][k] = value;
            for (int j = 0; j < 3; ++j)
                slope[m][k][j] = dF[m][k][0] * e[0][size_t(j)] + dF[m][k][1] * e[1][size_t(j)] - gradShift[j];
        }
    for (int c = 0; c < 3; ++c)
        for (int m = 0; m < 3; ++m) {
            double v = 0.0, d[3] = {0, 0, 0};
            for (int k = 0; k < dim; ++k) {
                v += e[k][size_t(c)] * shifted[m][k];
                for (int j = 0; j < 3; ++j) d[j] += e[k][size_t(c)] * slope[m][k][j];
            }
            out[c * 3 + m] = v;
            for (int j = 0; j < 3; ++j) out[9 + (c * 3 + m) * 3 + j] = d[j];
        }
}

// One group's fields on an element: the nodal fields (per side of the crack, [0] for theta < 0) in
// the group's basis, the front point's for every node (2D), or each node's own (3D, `frame` null).
struct TipGroupFields {
    const FrontBasis* frame = nullptr;
    std::vector<std::array<double, 9>> FnA[2], FnB[2];
};

// The tip fields of one element's groups at its points.
class ElementTipFields {
public:
    ElementTipFields(const Mesh& mesh, int cell, int dim, const std::vector<FrontBasis>* nodal,
                     const std::vector<unsigned char>& status)
        : mesh_(mesh), nodes_(mesh.cellNodes(cell)), dim_(dim), nodal_(nodal), status_(status) {}

    // The nodal fields of group g on the side `sign` of the crack (computed once per side).
    size_t nodalFields(TipGroupFields& g, double sign) const {
        const size_t at = sign < 0 ? 0 : 1;
        if (!g.FnA[at].empty()) return at;
        const size_t n = nodes_.size();
        g.FnA[at].resize(n), g.FnB[at].resize(n);
        for (size_t b = 0; b < n; ++b) {  // nodal fields, in the group's basis of each node
            const FrontBasis& fb = basisOf(g, b);
            LocalPoint nb = localPolar(X(b), fb.origin, fb.e1, fb.e2);
            const int st = status_[size_t(nodes_[b])];
            if (st == 1 || st == 3) nb.theta = sign * std::abs(nb.theta);  // the point's side of the crack
            const AsymptoticFields fn = asymptoticFields(nb.r, nb.theta, dim_);
            for (int m = 0; m < 3; ++m)
                for (int k = 0; k < 3; ++k) {
                    g.FnA[at][b][size_t(m * 3 + k)] = nb.r > 0 ? fn.A[m][k] : 0.0;
                    g.FnB[at][b][size_t(m * 3 + k)] = nb.r > 0 ? fn.B[m][k] : 0.0;
                }
        }
        return at;
    }

    // A and B of group g at a point (shape values N, physical gradients grad, Heaviside side).
    void atPoint(TipGroupFields& g, std::span<const double> N, std::span<const double> grad, signed char side,
                 double* A, double* B) const {
        Vec3 x{}, origin{}, e1{}, e2{};
        for (size_t a = 0; a < nodes_.size(); ++a) {
            const FrontBasis& b = basisOf(g, a);
            for (int j = 0; j < 3; ++j) {
                x[size_t(j)] += N[a] * X(a)[size_t(j)];
                origin[size_t(j)] += N[a] * b.origin[size_t(j)];
                e1[size_t(j)] += N[a] * b.e1[size_t(j)];
                e2[size_t(j)] += N[a] * b.e2[size_t(j)];
            }
        }
        const Vec3 e[3] = {unit(e1), unit(e2), unit(cross(unit(e1), unit(e2)))};
        LocalPoint at = localPolar(x, origin, e[0], e[1]);
        // At the front itself (r < 1e-12, xcoocy's tolerance) F is its limit 0 and only the shift
        // remains; code_aster sets the whole enrichment to 0 there, which no Gauss point meets but a
        // POST_CHAM_XFEM node at the tip does (u would jump to the standard part alone).
        const bool atFront = at.r < 1e-12;
        at.theta = side * std::abs(at.theta);
        const size_t nodal = nodalFields(g, at.theta < 0 ? -1.0 : 1.0);
        const AsymptoticFields f = atFront ? AsymptoticFields{} : asymptoticFields(at.r, at.theta, dim_);
        composePart(dim_, f.A, f.dA, g.FnA[nodal], N, grad, e, A);
        composePart(dim_, f.B, f.dB, g.FnB[nodal], N, grad, e, B);
    }

private:
    const FrontBasis& basisOf(const TipGroupFields& g, size_t a) const {
        return g.frame ? *g.frame : (*nodal_)[size_t(nodes_[a])];
    }
    const Vec3& X(size_t a) const { return mesh_.coords[size_t(nodes_[a])]; }

    const Mesh& mesh_;
    std::span<const int> nodes_;
    int dim_;
    const std::vector<FrontBasis>* nodal_;
    const std::vector<unsigned char>& status_;
};

// The groups of an element's tip nodes (ei.tip, ei.tipGroup, ei.tipGroups): 2D, one per distinct
// front point of its tip nodes, in increasing order; 3D, one.
std::vector<TipGroupFields> tipGroupsOf(std::span<const int> nodes, const TipBases& bases,
                                        const std::vector<char>& tipNodes, ElementIntegration& ei) {
    const size_t n = nodes.size();
    ei.tip.assign(n, 0);
    ei.tipGroup.assign(n, 0);
    for (size_t a = 0; a < n; ++a) ei.tip[a] = tipNodes[size_t(nodes[a])];
    std::vector<TipGroupFields> groups(1);
    if (bases.points) {
        std::vector<int> fronts;
        for (size_t a = 0; a < n; ++a)
            if (ei.tip[a]) fronts.push_back((*bases.front)[size_t(nodes[a])]);
        if (fronts.empty()) fronts.push_back((*bases.front)[size_t(nodes[0])]);  // no tip node: never read
        std::sort(fronts.begin(), fronts.end());
        fronts.erase(std::unique(fronts.begin(), fronts.end()), fronts.end());
        groups.resize(fronts.size());
        for (size_t g = 0; g < fronts.size(); ++g) groups[g].frame = &(*bases.points)[size_t(fronts[g])];
        for (size_t a = 0; a < n; ++a)
            if (ei.tip[a])
                ei.tipGroup[a] = static_cast<unsigned char>(
                    std::lower_bound(fronts.begin(), fronts.end(), (*bases.front)[size_t(nodes[a])]) - fronts.begin());
    }
    ei.tipGroups = int(groups.size());
    return groups;
}

}  // namespace

void tipElementFields(const Mesh& mesh, int cell, int dim, const TipBases& bases,
                      const std::vector<unsigned char>& status, const std::vector<char>& tipNodes,
                      const std::vector<signed char>& side, ElementIntegration& ei, const TipLaw* law) {
    const CellType type = mesh.cellTypes[size_t(cell)];
    const auto nodes = mesh.cellNodes(cell);
    const size_t n = nodes.size();
    const size_t np = ei.refPoints.size();
    std::vector<TipGroupFields> groups = tipGroupsOf(nodes, bases, tipNodes, ei);
    const size_t ng = groups.size();
    constexpr size_t stride = ElementIntegration::kTipStride;
    ei.tipA.assign(law ? 0 : np * ng * stride, 0.0);
    ei.tipB.assign(law ? 0 : np * ng * stride, 0.0);
    if (law) ei.tipPhi.resize(np * ng * stride);
    const ElementTipFields fields(mesh, cell, dim, bases.nodal, status);
    double A[stride], B[stride];
    std::vector<double> N(n), grad(n * 3);
    std::array<double, 24> dN{};
    auto X = [&](int a) -> const Vec3& { return mesh.coords[size_t(nodes[size_t(a)])]; };
    for (size_t p = 0; p < np; ++p) {
        shapeValues(type, ei.refPoints[p], N);
        shapeDerivatives(type, ei.refPoints[p], dN);
        double J[3][3] = {}, inv[3][3] = {};
        jacobian(
            dim, dim, int(n), X, [&](int a, int j) { return dN[size_t(3 * a + j)]; }, J);
        invertJacobian(dim, J, inv);
        std::fill(grad.begin(), grad.end(), 0.0);
        for (size_t a = 0; a < n; ++a)
            physicalGradient(
                dim, inv, [&](int j) { return dN[3 * a + size_t(j)]; }, &grad[3 * a]);
        for (size_t g = 0; g < ng; ++g) {
            const size_t at = (p * ng + g) * stride;
            fields.atPoint(groups[g], N, grad, side[p], law ? A : &ei.tipA[at], law ? B : &ei.tipB[at]);
            if (law)
                for (size_t i = 0; i < stride; ++i) ei.tipPhi[at + i] = law->scale * (law->kappa * A[i] + B[i]);
        }
    }
}

}  // namespace ma::xfem
