#include "fracture/DomainSampling.hpp"

#include "fe/ElasticityKernels.hpp"
#include "fe/ElementKinematics.hpp"

namespace ma::fracture {

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
            DomainPoint q;
            q.weight = geo.weight[p];
            q.xyz = geo.xyz[p];
            q.E = material.E;
            q.nu = material.nu;
            displacementGradient(ei, geo, dofs, u, p, dim, q.gradU);
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
