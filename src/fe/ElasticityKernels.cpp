#include "fe/ElasticityKernels.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "core/Error.hpp"

namespace ma {

IsotropicLaw IsotropicLaw::from(const Material& m, Modelisation modelisation, const std::string& where) {
    IsotropicLaw law;
    const double E = m.E, nu = m.nu;
    law.mu = E / (2.0 * (1.0 + nu));
    if (modelisation == Modelisation::C_PLAN) {
        law.lambdaEff = E * nu / (1.0 - nu * nu);
        law.lambdaZ = 0.0;
        law.strainZ = -nu / (1.0 - nu);
        return law;
    }
    if (nu >= 0.5)
        throw UserError(
            fmt::format("material {} has NU = {}: an incompressible material cannot be modelled "
                        "with {} displacement elements (lambda is infinite); use NU < 0.5",
                        where, nu, modelisationName(modelisation)));
    law.lambdaEff = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    law.lambdaZ = modelisation == Modelisation::D_PLAN ? law.lambdaEff : 0.0;
    return law;
}

const IsotropicLaw& LawCache::of(const ModelElement& element) {
    const Material& mat = field_.at(element.cell);
    if (&mat != last_ || element.modelisation != modelisation_) {
        law_ = IsotropicLaw::from(mat, element.modelisation, mat.name);
        last_ = &mat;
        modelisation_ = element.modelisation;
    }
    return law_;
}

void localDofs(const Mesh& mesh, const DofNumbering& numbering, const ElementIntegration& ei, std::vector<int>& dofs) {
    const auto nodes = mesh.cellNodes(ei.cell);
    const int dim = numbering.dim();
    dofs.clear();
    for (int a = 0; a < ei.nodeCount; ++a) {
        for (int k = 0; k < ei.slots[a]; ++k)
            for (int c = 0; c < dim; ++c) {
                const int d = numbering.dof(nodes[a], k, c);
                if (d < 0)
                    throw InternalError(
                        fmt::format("element on cell {} uses slot {} of node {}, which the "
                                    "enrichment does not give to the node",
                                    mesh.cellNames[ei.cell], k, mesh.nodeNames[nodes[a]]));
                dofs.push_back(d);
            }
        if (ei.tipAt(a))
            for (int c = 0; c < dim; ++c) {
                const int d = numbering.tipDof(nodes[a], c);
                if (d < 0)
                    throw InternalError(
                        fmt::format("element on cell {} uses the crack-tip unknowns of node {}, which "
                                    "the enrichment does not give to the node",
                                    mesh.cellNames[ei.cell], mesh.nodeNames[nodes[a]]));
                dofs.push_back(d);
            }
    }
}

void dofGradients(const ElementIntegration& ei, const PointGeometry& geo, size_t p, int dim, std::vector<double>& B) {
    const int n = ei.nodeCount;
    size_t i = 0;
    auto next = [&]() -> double* {
        if (B.size() < (i + 1) * 9) B.resize((i + 1) * 9);
        double* b = &B[i++ * 9];
        std::fill(b, b + 9, 0.0);
        return b;
    };
    for (int a = 0; a < n; ++a) {
        const double* ga = &geo.gradN[(p * n + a) * 3];
        for (int k = 0; k < ei.slots[a]; ++k) {
            const double pa = ei.multiplier(int(p), a, k);
            for (int c = 0; c < dim; ++c) {
                double* b = next();
                for (int j = 0; j < dim; ++j) b[c * 3 + j] = pa * ga[j];
            }
        }
        if (!ei.tipAt(a)) continue;
        const double Na = geo.N[p * n + a];
        const double* phi = ei.tipValue(p);
        const double* dphi = ei.tipGradient(p);
        for (int m = 0; m < dim; ++m) {  // mode m: u_c = N_a Phi[c][m]
            double* b = next();
            for (int c = 0; c < dim; ++c)
                for (int j = 0; j < dim; ++j) b[c * 3 + j] = ga[j] * phi[c * 3 + m] + Na * dphi[(c * 3 + m) * 3 + j];
        }
    }
}

void displacementGradient(const ElementIntegration& ei, const PointGeometry& geo, const std::vector<int>& dofs,
                          const std::vector<double>& u, size_t p, int dim, double G[3][3]) {
    for (int c = 0; c < 3; ++c)
        for (int j = 0; j < 3; ++j) G[c][j] = 0.0;
    const int n = ei.nodeCount;
    if (ei.hasTip()) {
        // dofGradients' B contracted with u without building it: its zero entries left out, the
        // others added in the same order (a sum from +0 is unchanged by a zero term: the same bits).
        size_t i = 0;
        for (int a = 0; a < n; ++a) {
            const double* ga = &geo.gradN[(p * size_t(n) + size_t(a)) * 3];
            for (int k = 0; k < ei.slots[size_t(a)]; ++k) {
                const double pa = ei.multiplier(int(p), a, k);
                for (int c = 0; c < dim; ++c, ++i)
                    for (int j = 0; j < dim; ++j) G[c][j] += u[size_t(dofs[i])] * (pa * ga[j]);
            }
            if (!ei.tipAt(a)) continue;
            const double Na = geo.N[p * size_t(n) + size_t(a)];
            const double* phi = ei.tipValue(p);
            const double* dphi = ei.tipGradient(p);
            for (int m = 0; m < dim; ++m, ++i)
                for (int c = 0; c < dim; ++c)
                    for (int j = 0; j < dim; ++j)
                        G[c][j] += u[size_t(dofs[i])] * (ga[j] * phi[c * 3 + m] + Na * dphi[(c * 3 + m) * 3 + j]);
        }
        return;
    }
    int i = 0;
    for (int a = 0; a < n; ++a) {
        const double* ga = &geo.gradN[(p * n + a) * 3];
        for (int k = 0; k < ei.slots[a]; ++k) {
            const double pa = ei.multiplier(int(p), a, k);
            for (int c = 0; c < dim; ++c, ++i)
                if (pa != 0.0)
                    for (int j = 0; j < dim; ++j) G[c][j] += pa * u[dofs[i]] * ga[j];
        }
    }
}

void storeStress(const double G[3][3], const IsotropicLaw& law, int dim, double* out) {
    double tr = 0.0;
    for (int c = 0; c < dim; ++c) tr += G[c][c];
    auto sigma = [&](int a, int b) { return law.mu * (G[a][b] + G[b][a]) + (a == b ? law.lambdaEff * tr : 0.0); };
    if (dim == 2) {
        out[0] = sigma(0, 0), out[1] = sigma(1, 1), out[2] = law.lambdaZ * (G[0][0] + G[1][1]), out[3] = sigma(0, 1);
    } else {
        out[0] = sigma(0, 0), out[1] = sigma(1, 1), out[2] = sigma(2, 2);
        out[3] = sigma(0, 1), out[4] = sigma(0, 2), out[5] = sigma(1, 2);
    }
}

void storeStrain(const double G[3][3], const IsotropicLaw& law, int dim, double* out) {
    auto eps = [&](int a, int b) { return 0.5 * (G[a][b] + G[b][a]); };
    if (dim == 2) {
        out[0] = G[0][0], out[1] = G[1][1], out[2] = law.strainZ * (G[0][0] + G[1][1]), out[3] = eps(0, 1);
    } else {
        out[0] = G[0][0], out[1] = G[1][1], out[2] = G[2][2];
        out[3] = eps(0, 1), out[4] = eps(0, 2), out[5] = eps(1, 2);
    }
}

namespace {

// Stiffness of an element with crack-tip slots: every local dof's displacement gradient at each
// point (dofGradients), then w * eps_i : C : eps_j.
void tipStiffness(const ElementIntegration& ei, const PointGeometry& geo, const IsotropicLaw& law, int dim, int nd,
                  std::vector<double>& Ke) {
    Ke.assign(size_t(nd) * nd, 0.0);
    thread_local std::vector<double> B;
    for (size_t p = 0; p < ei.refPoints.size(); ++p) {
        dofGradients(ei, geo, p, dim, B);
        const double w = geo.weight[p];
        for (int i = 0; i < nd; ++i) {
            double S[3][3], G[3][3];
            for (int c = 0; c < 3; ++c)
                for (int j = 0; j < 3; ++j) G[c][j] = B[size_t(i) * 9 + c * 3 + j];
            stressOf(G, law, dim, S);
            for (int l = 0; l < nd; ++l) {
                double sum = 0.0;
                for (int c = 0; c < dim; ++c)
                    for (int j = 0; j < dim; ++j) sum += S[c][j] * B[size_t(l) * 9 + c * 3 + j];
                Ke[size_t(i) * nd + l] += w * sum;
            }
        }
    }
}

}  // namespace

void generalStiffness(const ElementIntegration& ei, const PointGeometry& geo, const IsotropicLaw& law, int dim, int nd,
                      std::vector<double>& Ke) {
    if (ei.hasTip()) return tipStiffness(ei, geo, law, dim, nd, Ke);
    const int n = ei.nodeCount;
    std::vector<int> base(n + 1, 0);  // local index of (a, slot 0)
    for (int a = 0; a < n; ++a) base[a + 1] = base[a] + ei.slots[a] * dim;
    Ke.assign(size_t(nd) * nd, 0.0);
    for (size_t p = 0; p < ei.refPoints.size(); ++p) {
        const double w = geo.weight[p];
        for (int a = 0; a < n; ++a) {
            const double* ga = &geo.gradN[(p * n + a) * 3];
            for (int k = 0; k < ei.slots[a]; ++k) {
                const double pa = ei.multiplier(int(p), a, k);
                if (pa == 0.0) continue;
                const int ia = base[a] + k * dim;
                for (int b = 0; b < n; ++b) {
                    const double* gb = &geo.gradN[(p * n + b) * 3];
                    const double dot = ga[0] * gb[0] + ga[1] * gb[1] + ga[2] * gb[2];
                    for (int l = 0; l < ei.slots[b]; ++l) {
                        const double pb = ei.multiplier(int(p), b, l);
                        if (pb == 0.0) continue;
                        const double s = w * pa * pb;
                        const int ib = base[b] + l * dim;
                        for (int ci = 0; ci < dim; ++ci)
                            for (int di = 0; di < dim; ++di)
                                Ke[size_t(ia + ci) * nd + ib + di] +=
                                    s * (law.lambdaEff * ga[ci] * gb[di] + law.mu * ga[di] * gb[ci] +
                                         (ci == di ? law.mu * dot : 0.0));
                    }
                }
            }
        }
    }
}

void generalInternalForce(const ElementIntegration& ei, const PointGeometry& geo, const std::vector<int>& dofs,
                          const std::vector<double>& u, const IsotropicLaw& law, int dim, std::vector<double>& fe) {
    fe.assign(dofs.size(), 0.0);
    const int n = ei.nodeCount;
    for (size_t p = 0; p < ei.refPoints.size(); ++p) {
        double G[3][3], S[3][3];
        displacementGradient(ei, geo, dofs, u, p, dim, G);
        stressOf(G, law, dim, S);
        const double wp = geo.weight[p];
        if (ei.hasTip()) {
            thread_local std::vector<double> B;
            dofGradients(ei, geo, p, dim, B);
            for (size_t i = 0; i < dofs.size(); ++i) {
                double sum = 0.0;
                for (int c = 0; c < dim; ++c)
                    for (int j = 0; j < dim; ++j) sum += S[c][j] * B[i * 9 + c * 3 + j];
                fe[i] += wp * sum;
            }
            continue;
        }
        int i = 0;
        for (int a = 0; a < n; ++a) {
            const double* ga = &geo.gradN[(p * n + a) * 3];
            for (int k = 0; k < ei.slots[a]; ++k) {
                const double pa = ei.multiplier(int(p), a, k);
                for (int c = 0; c < dim; ++c, ++i) {
                    double sum = 0.0;
                    for (int j = 0; j < dim; ++j) sum += S[c][j] * ga[j];
                    fe[i] += wp * pa * sum;
                }
            }
        }
    }
}

}  // namespace ma
