#include "fe/ElementKinematics.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/Error.hpp"
#include "fe/ClassicalElement.hpp"
#include "fe/Enrichment.hpp"
#include "fe/Quadrature.hpp"
#include "mesh/ElementGeometry.hpp"
#include "mesh/ShapeFunctions.hpp"

namespace ma {

void classicalIntegration(const Mesh& mesh, int cell, bool boundary, ElementIntegration& out) {
    const CellType type = mesh.cellTypes[cell];
    const QuadratureRule& rule = stiffnessRule(type, boundary);
    out.cell = cell;
    out.nodeCount = nodeCount(type);
    out.refPoints.assign(rule.points.begin(), rule.points.end());
    out.refWeights.assign(rule.weights.begin(), rule.weights.end());
    out.pointSubcell.assign(rule.points.size(), 0);
    out.slots.assign(out.nodeCount, 1);
    out.maxSlots = 1;
    out.psi.clear();
    // A reused ElementIntegration (the load loops) must not keep the previous cell's tip terms.
    out.tip.clear();
    out.tipGroup.clear();
    out.tipGroups = 1;
    out.tipA.clear();
    out.tipB.clear();
    out.tipPhi.clear();
}

void elementIntegration(const Model& model, int cell, bool boundary, ElementIntegration& out) {
    if (model.enrichment && model.enrichment->isEnriched(cell)) {
        model.enrichment->integration(cell, out);
        return;
    }
    classicalIntegration(*model.mesh, cell, boundary, out);
}

void computePointGeometry(const Mesh& mesh, int cell, int spaceDim, bool boundary,
                          const ElementIntegration& integration, PointGeometry& geo) {
    const CellType type = mesh.cellTypes[cell];
    const auto nodes = mesh.cellNodes(cell);
    const int n = static_cast<int>(nodes.size());
    const int np = static_cast<int>(integration.refPoints.size());
    const int rdim = referenceDimension(type);
    geo.nodeCount = n;
    geo.N.resize(size_t(np) * n);
    geo.weight.resize(np);
    geo.xyz.resize(np);
    if (boundary) geo.normal.resize(np);
    else geo.gradN.resize(size_t(np) * n * 3);
    std::array<double, 24> dN{};
    auto X = [&](int a) -> const Vec3& { return mesh.coords[nodes[a]]; };
    auto d = [&](int a, int j) { return dN[3 * a + j]; };
    for (int p = 0; p < np; ++p) {
        double* N = &geo.N[size_t(p) * n];
        shapeValues(type, integration.refPoints[p], std::span<double>(N, n));
        shapeDerivatives(type, integration.refPoints[p], dN);
        std::array<double, 3> x{};
        for (int a = 0; a < n; ++a)
            for (int i = 0; i < 3; ++i) x[i] += N[a] * X(a)[i];
        geo.xyz[p] = x;
        double J[3][3] = {};
        jacobian(3, rdim, n, X, d, J);
        if (boundary && rdim + 2 == spaceDim) {  // an edge of a 3D model (FORCE_ARETE): no normal
            geo.normal[p] = {0.0, 0.0, 0.0};
            geo.weight[p] = integration.refWeights[p] * jacobianMeasure(J, rdim);
            if (!(geo.weight[p] > 0.0))
                throw NumericalError(fmt::format("edge cell {} ({}) is degenerate (zero length)", mesh.cellNames[cell],
                                                 cellTypeName(type)));
            continue;
        }
        if (boundary) {
            Vec3 nrm = boundaryNormal(J, rdim);
            const double measure = norm(nrm);
            if (!(measure > 0.0))
                throw NumericalError(fmt::format("boundary cell {} ({}) is degenerate (zero Jacobian)",
                                                 mesh.cellNames[cell], cellTypeName(type)));
            for (auto& v : nrm) v /= measure;
            geo.normal[p] = nrm;
            geo.weight[p] = integration.refWeights[p] * measure;
            continue;
        }
        double inv[3][3] = {};
        const double det = invertJacobian(spaceDim, J, inv);
        if (degenerateJacobian(spaceDim, J, det)) classical::badJacobian(mesh, cell, det);
        geo.weight[p] = integration.refWeights[p] * std::abs(det);
        for (int a = 0; a < n; ++a) {
            double* g = &geo.gradN[(size_t(p) * n + a) * 3];
            g[0] = g[1] = g[2] = 0.0;
            physicalGradient(
                spaceDim, inv, [&](int i) { return dN[3 * a + i]; }, g);
        }
    }
}

}  // namespace ma
