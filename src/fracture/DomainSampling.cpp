#include "fracture/DomainSampling.hpp"

#include <algorithm>
#include <iterator>

#include "fe/ElasticityKernels.hpp"
#include "fe/ElementKinematics.hpp"
#include "fe/FieldSampling.hpp"

namespace ma::fracture {

namespace {

// Integration point p of an element with its weight, position, material and displacement gradient;
// the theta parts and the side are the caller's.
DomainPoint pointOf(const ElementIntegration& ei, const PointGeometry& geo, const std::vector<int>& dofs,
                    const std::vector<double>& u, const Material& material, size_t p, int dim) {
    DomainPoint q;
    q.weight = geo.weight[p];
    q.xyz = geo.xyz[p];
    q.E = material.E;
    q.nu = material.nu;
    displacementGradient(ei, geo, dofs, u, p, dim, q.gradU);
    return q;
}

}  // namespace

bool thetaVaries(const Mesh& mesh, int cell, const std::vector<Vec3>& theta) {
    const auto nodes = mesh.cellNodes(cell);
    for (int n : nodes)
        if (theta[size_t(n)] != theta[size_t(nodes[0])]) return true;
    return false;
}

std::vector<DomainPoint> domainPoints(const Discretisation& space, const std::vector<double>& u,
                                      const std::vector<Vec3>& theta, const std::vector<double>& lsn,
                                      double positiveLsnSide) {
    const Mesh& mesh = space.mesh();
    const int dim = space.dim();
    std::vector<DomainPoint> out;
    ElementIntegration scratch;
    PointGeometry geo;
    std::vector<int> dofs;
    // Reserved: crack-tip elements hold ~10^5 points, and a growing vector's copies would triple
    // the peak (ssnp138a's memory_limit).
    size_t count = 0;
    for (size_t e = 0; e < space.elementCount(); ++e)
        if (thetaVaries(mesh, space.model().elements[e].cell, theta)) count += space.pointCount(e);
    out.reserve(count);
    for (size_t e = 0; e < space.elementCount(); ++e) {
        const int cell = space.model().elements[e].cell;
        if (!thetaVaries(mesh, cell, theta)) continue;
        const Material& material = space.material().at(cell);
        const ElementIntegration& ei = space.integrationOf(e, scratch);
        computePointGeometry(mesh, cell, dim, false, ei, geo);
        localDofs(mesh, space.numbering(), ei, dofs);
        const auto nodes = mesh.cellNodes(cell);
        const size_t n = nodes.size();
        for (size_t p = 0; p < ei.refPoints.size(); ++p) {
            DomainPoint q = pointOf(ei, geo, dofs, u, material, p, dim);
            double levelSet = 0.0;
            for (size_t a = 0; a < n; ++a) {
                const size_t node = size_t(nodes[a]);
                const double Na = geo.N[p * n + a];
                levelSet += Na * lsn[node];
                for (int k = 0; k < dim; ++k) {
                    q.theta[size_t(k)] += Na * theta[node][size_t(k)];
                    for (int j = 0; j < dim; ++j)
                        q.gradTheta[k][j] += geo.gradN[(p * n + a) * 3 + size_t(j)] * theta[node][size_t(k)];
                }
            }
            q.side = levelSet > 0 ? positiveLsnSide : (levelSet < 0 ? -positiveLsnSide : 0.0);
            out.push_back(q);
        }
    }
    return out;
}

}  // namespace ma::fracture

namespace ma::fracture {

namespace {

// The gradient of the nodal bases (e1, e2 normalised, e3 = e1 x e2) at a point of gradients dN.
void basisGradient(const std::vector<xfem::FrontBasis>& basloc, std::span<const int> nodes, std::span<const double> dN,
                   FrontFrame& f) {
    for (size_t a = 0; a < nodes.size(); ++a) {
        const auto& b = basloc[size_t(nodes[a])];
        const Vec3 e1 = unit(b.e1), e2 = unit(b.e2);
        const Vec3 e[3] = {e1, e2, cross(e1, e2)};
        for (size_t k = 0; k < 3; ++k)
            for (size_t i = 0; i < 3; ++i)
                for (size_t j = 0; j < 3; ++j) f.basisGradient[k][i][j] += e[k][i] * dN[a * 3 + j];
    }
}

}  // namespace

FrontFrame interpolatedFrame(const std::vector<xfem::FrontBasis>& basloc, std::span<const int> nodes,
                             std::span<const double> N) {
    Vec3 o{}, e1{}, e2{};
    for (size_t a = 0; a < nodes.size(); ++a) {
        const auto& b = basloc[size_t(nodes[a])];
        for (size_t c = 0; c < 3; ++c) o[c] += N[a] * b.origin[c], e1[c] += N[a] * b.e1[c], e2[c] += N[a] * b.e2[c];
    }
    FrontFrame f;
    f.origin = o;
    f.e2 = unit(e2);
    const double along = dot(e1, f.e2);
    f.e1 = unit({e1[0] - along * f.e2[0], e1[1] - along * f.e2[1], e1[2] - along * f.e2[2]});
    f.e3 = cross(f.e1, f.e2);
    return f;
}

void domainPoints3D(const Discretisation& space, const std::vector<double>& u,
                    const std::vector<std::vector<Vec3>>& thetas, const std::vector<double>& lsn,
                    const std::vector<xfem::FrontBasis>& basloc,
                    const std::vector<std::array<double, 2>>& basisDivergence, const FieldPointSink& sink) {
    const Mesh& mesh = space.mesh();
    // One element's points, their theta parts refilled for each field (~7e4 points in ssnv185c's
    // largest crack-tip element: a copy per field held 220 MB).
    std::vector<DomainPoint> points;
    std::vector<FrontFrame> frames;
    ElementIntegration scratch;
    PointGeometry geo;
    std::vector<int> dofs;
    std::vector<size_t> fields;
    for (size_t e = 0; e < space.elementCount(); ++e) {
        const int cell = space.model().elements[e].cell;
        fields.clear();
        for (size_t k = 0; k < thetas.size(); ++k)
            if (thetaVaries(mesh, cell, thetas[k])) fields.push_back(k);
        if (fields.empty()) continue;
        const Material& material = space.material().at(cell);
        // Described here, one element at a time: a 3D crack-tip element holds ~10^4 points with
        // Phi and its gradient, which `space` need not keep for the whole front (CalcG3D).
        elementIntegration(space.model(), cell, false, scratch);
        applyMaterialToTip(space.model(), &space.material(), space.model().elements[e], scratch);
        const ElementIntegration& ei = scratch;
        computePointGeometry(mesh, cell, 3, false, ei, geo);
        localDofs(mesh, space.numbering(), ei, dofs);
        const auto nodes = mesh.cellNodes(cell);
        const size_t n = nodes.size();
        points.clear(), frames.clear();
        for (size_t p = 0; p < ei.refPoints.size(); ++p) {
            DomainPoint q = pointOf(ei, geo, dofs, u, material, p, 3);
            const std::span<const double> N(&geo.N[p * n], n);
            double levelSet = 0.0;
            for (size_t a = 0; a < n; ++a) levelSet += N[a] * lsn[size_t(nodes[a])];
            q.side = levelSet > 0 ? 1.0 : (levelSet < 0 ? -1.0 : 0.0);
            FrontFrame& frame = frames.emplace_back(interpolatedFrame(basloc, nodes, N));
            basisGradient(basloc, nodes, std::span<const double>(&geo.gradN[p * n * 3], n * 3), frame);
            for (size_t a = 0; a < n && !basisDivergence.empty(); ++a)
                for (size_t k = 0; k < 2; ++k)
                    for (size_t j = 0; j < 3; ++j)
                        frame.divergenceGradient[k][j] +=
                            basisDivergence[size_t(nodes[a])][k] * geo.gradN[(p * n + a) * 3 + j];
            points.push_back(q);
        }
        for (size_t k : fields) {
            for (size_t p = 0; p < points.size(); ++p) {
                DomainPoint& r = points[p];
                r.theta = {};
                for (auto& row : r.gradTheta) std::fill(std::begin(row), std::end(row), 0.0);
                for (size_t a = 0; a < n; ++a) {
                    const Vec3& t = thetas[k][size_t(nodes[a])];
                    const double Na = geo.N[p * n + a];
                    for (size_t i = 0; i < 3; ++i) {
                        r.theta[i] += Na * t[i];
                        for (size_t j = 0; j < 3; ++j) r.gradTheta[i][j] += geo.gradN[(p * n + a) * 3 + j] * t[i];
                    }
                }
            }
            sink(k, points, frames);
        }
    }
}

std::vector<std::array<double, 2>> basisDivergence(const Mesh& mesh, const std::vector<xfem::FrontBasis>& basloc) {
    std::vector<std::array<double, 2>> out(basloc.size(), {0.0, 0.0});
    std::vector<double> component(basloc.size());
    for (size_t k = 0; k < 2; ++k)
        for (size_t c = 0; c < 3; ++c) {
            for (size_t n = 0; n < basloc.size(); ++n) component[n] = unit(k == 0 ? basloc[n].e1 : basloc[n].e2)[c];
            const auto gradient = xfem::nodalLevelSetGradient(mesh, component);
            for (size_t n = 0; n < basloc.size(); ++n) out[n][k] += gradient[n][c];
        }
    return out;
}

}  // namespace ma::fracture
