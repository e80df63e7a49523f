#include "fe/ElementKinematics.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/Error.hpp"
#include "fe/ClassicalElement.hpp"
#include "fe/Enrichment.hpp"
#include "fe/Quadrature.hpp"
#include "fe/ShapeFunctions.hpp"

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
    for (int p = 0; p < np; ++p) {
        double* N = &geo.N[size_t(p) * n];
        shapeValues(type, integration.refPoints[p], std::span<double>(N, n));
        shapeDerivatives(type, integration.refPoints[p], dN);
        std::array<double, 3> x{};
        double J[3][3] = {};  // J[i][j] = dx_i / dxi_j
        for (int a = 0; a < n; ++a) {
            const auto& X = mesh.coords[nodes[a]];
            for (int i = 0; i < 3; ++i) {
                x[i] += N[a] * X[i];
                for (int j = 0; j < rdim; ++j) J[i][j] += X[i] * dN[3 * a + j];
            }
        }
        geo.xyz[p] = x;
        if (boundary) {
            std::array<double, 3> nrm{};
            if (rdim == 1) {  // 2D skin: n = (t_y, -t_x), t from node 1 to node 2
                nrm = {J[1][0], -J[0][0], 0.0};
            } else {  // 3D face: right-hand rule
                nrm = {J[1][0] * J[2][1] - J[2][0] * J[1][1], J[2][0] * J[0][1] - J[0][0] * J[2][1],
                       J[0][0] * J[1][1] - J[1][0] * J[0][1]};
            }
            const double measure = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
            if (!(measure > 0.0))
                throw NumericalError(fmt::format("boundary cell {} ({}) is degenerate (zero Jacobian)",
                                                 mesh.cellNames[cell], cellTypeName(type)));
            for (auto& v : nrm) v /= measure;
            geo.normal[p] = nrm;
            geo.weight[p] = integration.refWeights[p] * measure;
            continue;
        }
        // Volume element: invert J (spaceDim x spaceDim).
        double inv[3][3] = {};
        double det = 0.0;
        if (spaceDim == 2) {
            det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
            inv[0][0] = J[1][1] / det, inv[0][1] = -J[0][1] / det;
            inv[1][0] = -J[1][0] / det, inv[1][1] = J[0][0] / det;
        } else {
            det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                  J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
            inv[0][0] = (J[1][1] * J[2][2] - J[1][2] * J[2][1]) / det;
            inv[0][1] = (J[0][2] * J[2][1] - J[0][1] * J[2][2]) / det;
            inv[0][2] = (J[0][1] * J[1][2] - J[0][2] * J[1][1]) / det;
            inv[1][0] = (J[1][2] * J[2][0] - J[1][0] * J[2][2]) / det;
            inv[1][1] = (J[0][0] * J[2][2] - J[0][2] * J[2][0]) / det;
            inv[1][2] = (J[0][2] * J[1][0] - J[0][0] * J[1][2]) / det;
            inv[2][0] = (J[1][0] * J[2][1] - J[1][1] * J[2][0]) / det;
            inv[2][1] = (J[0][1] * J[2][0] - J[0][0] * J[2][1]) / det;
            inv[2][2] = (J[0][0] * J[1][1] - J[0][1] * J[1][0]) / det;
        }
        if (!(det > 0.0)) classical::badJacobian(mesh, cell, det);
        geo.weight[p] = integration.refWeights[p] * det;
        // grad N_a = J^-T dN_a
        for (int a = 0; a < n; ++a) {
            double* g = &geo.gradN[(size_t(p) * n + a) * 3];
            for (int j = 0; j < 3; ++j) g[j] = 0.0;
            for (int j = 0; j < spaceDim; ++j)
                for (int i = 0; i < spaceDim; ++i) g[j] += inv[i][j] * dN[3 * a + i];
        }
    }
}

}  // namespace ma
