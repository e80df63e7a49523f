#include "fe/ElasticityKernels.hpp"

#include <Eigen/Dense>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
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

namespace {

// visit(i, c0, c1, b) for each local dof i in order, b its displacement gradient at point p (b[3 c +
// j] = du_c/dx_j of the dof's shape function, 3 x 3); only rows c0 <= c < c1 are written, the others
// are zero (a standard or Heaviside dof moves one component, a crack-tip dof all of them).
template <class Visit>
void forEachDofGradient(const ElementIntegration& ei, const PointGeometry& geo, size_t p, int dim, Visit&& visit) {
    const int n = ei.nodeCount;
    size_t i = 0;
    double b[9];
    for (int a = 0; a < n; ++a) {
        const double* ga = &geo.gradN[(p * size_t(n) + size_t(a)) * 3];
        for (int k = 0; k < ei.slots[size_t(a)]; ++k) {
            const double pa = ei.multiplier(int(p), a, k);
            for (int c = 0; c < dim; ++c) {
                for (int j = 0; j < dim; ++j) b[c * 3 + j] = pa * ga[j];
                visit(i++, c, c + 1, b);
            }
        }
        if (!ei.tipAt(a)) continue;
        const double Na = geo.N[p * size_t(n) + size_t(a)];
        const int g = ei.tipGroupOf(a);
        const double* phi = ei.tipValue(p, g);
        const double* dphi = ei.tipGradient(p, g);
        for (int m = 0; m < dim; ++m) {  // mode m: u_c = N_a Phi[c][m]
            for (int c = 0; c < dim; ++c)
                for (int j = 0; j < dim; ++j) b[c * 3 + j] = ga[j] * phi[c * 3 + m] + Na * dphi[(c * 3 + m) * 3 + j];
            visit(i++, 0, dim, b);
        }
    }
}

}  // namespace

void dofGradients(const ElementIntegration& ei, const PointGeometry& geo, size_t p, int dim, std::vector<double>& B) {
    forEachDofGradient(ei, geo, p, dim, [&](size_t i, int c0, int c1, const double* b) {
        if (B.size() < (i + 1) * 9) B.resize((i + 1) * 9);
        double* out = &B[i * 9];
        std::fill(out, out + 9, 0.0);
        for (int c = c0; c < c1; ++c)
            for (int j = 0; j < dim; ++j) out[c * 3 + j] = b[c * 3 + j];
    });
}

void displacementGradient(const ElementIntegration& ei, const PointGeometry& geo, const std::vector<int>& dofs,
                          const std::vector<double>& u, size_t p, int dim, double G[3][3]) {
    for (int c = 0; c < 3; ++c)
        for (int j = 0; j < 3; ++j) G[c][j] = 0.0;
    const int n = ei.nodeCount;
    if (ei.hasTip()) {
        // dofGradients' B contracted with u without building it: its zero entries left out, the
        // others added in the same order (a sum from +0 is unchanged by a zero term: the same bits).
        forEachDofGradient(ei, geo, p, dim, [&](size_t i, int c0, int c1, const double* b) {
            for (int c = c0; c < c1; ++c)
                for (int j = 0; j < dim; ++j) G[c][j] += u[size_t(dofs[i])] * b[c * 3 + j];
        });
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

// The symmetric part of a displacement gradient g (row-major 3 x 3) in Mandel's form (off-diagonal
// terms times sqrt 2, so that e . e' = sym g : sym g'), then its trace: 3 + 1 terms in 2D, 6 + 1 in 3D.
void mandelStrain(const double* g, int dim, double* e) {
    const double r2 = std::numbers::sqrt2;
    if (dim == 2) {
        e[0] = g[0], e[1] = g[4], e[2] = (g[1] + g[3]) / r2, e[3] = g[0] + g[4];
        return;
    }
    e[0] = g[0], e[1] = g[4], e[2] = g[8];
    e[3] = (g[1] + g[3]) / r2, e[4] = (g[2] + g[6]) / r2, e[5] = (g[5] + g[7]) / r2;
    e[6] = g[0] + g[4] + g[8];
}

// Stiffness of an element with crack-tip slots: every local dof's displacement gradient at each
// point (dofGradients), then w eps_i : C : eps_l = w (2 mu e_i . e_l + lambda tr_i tr_l). Tip
// elements have thousands of points, so the points go in chunks as columns of two matrices and each
// chunk is one matrix product: Ke += L R^T with L = [2 mu w e, lambda w tr] and R = [e, tr].
void tipStiffness(const ElementIntegration& ei, const PointGeometry& geo, const IsotropicLaw& law, int dim, int nd,
                  std::vector<double>& Ke) {
    using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    constexpr int kChunk = 256;
    const int terms = dim == 3 ? 7 : 4;
    thread_local std::vector<double> B;
    thread_local Eigen::MatrixXd L, R;
    L.resize(nd, terms * kChunk), R.resize(nd, terms * kChunk);
    Ke.assign(size_t(nd) * size_t(nd), 0.0);
    Eigen::Map<RowMajor> K(Ke.data(), nd, nd);
    const size_t points = ei.refPoints.size();
    for (size_t p0 = 0; p0 < points; p0 += kChunk) {
        const int count = int(std::min<size_t>(kChunk, points - p0));
        for (int q = 0; q < count; ++q) {
            dofGradients(ei, geo, p0 + size_t(q), dim, B);
            const double w = geo.weight[p0 + size_t(q)];
            for (int i = 0; i < nd; ++i) {
                double e[7];
                mandelStrain(&B[size_t(i) * 9], dim, e);
                for (int t = 0; t < terms; ++t) {
                    L(i, q * terms + t) = (t + 1 < terms ? 2 * law.mu : law.lambdaEff) * w * e[t];
                    R(i, q * terms + t) = e[t];
                }
            }
        }
        K.noalias() += L.leftCols(count * terms) * R.leftCols(count * terms).transpose();
    }
}

}  // namespace

namespace {

// The classical node-pair blocks of the points [p0, p1) (one sub-cell, where psi is constant):
// C[(a n + b) 9 + 3 ci + di] = sum_p w (lambda ga_ci gb_di + mu ga_di gb_ci + [ci = di] mu ga.gb), the
// products summed first (pairBlockFromProducts).
void subcellBlocks(const PointGeometry& geo, const IsotropicLaw& law, int n, int dim, size_t p0, size_t p1,
                   std::vector<double>& C) {
    C.assign(size_t(n) * size_t(n) * 9, 0.0);
    for (size_t p = p0; p < p1; ++p) {
        const double w = geo.weight[p];
        for (int a = 0; a < n; ++a) {
            const double* ga = &geo.gradN[(p * size_t(n) + size_t(a)) * 3];
            const double wa[3] = {w * ga[0], w * ga[1], w * ga[2]};
            for (int b = a; b < n; ++b) {
                const double* gb = &geo.gradN[(p * size_t(n) + size_t(b)) * 3];
                double* c = &C[size_t(a * n + b) * 9];
                for (int ci = 0; ci < dim; ++ci)
                    for (int di = 0; di < dim; ++di) c[ci * 3 + di] += wa[ci] * gb[di];
            }
        }
    }
    for (int a = 0; a < n; ++a)
        for (int b = a; b < n; ++b) pairBlockFromProducts(&C[size_t(a * n + b) * 9], 3, law, dim);
    for (int a = 1; a < n; ++a)  // the lower blocks are the transposed upper ones
        for (int b = 0; b < a; ++b)
            for (int ci = 0; ci < 3; ++ci)
                for (int di = 0; di < 3; ++di)
                    C[size_t(a * n + b) * 9 + size_t(ci * 3 + di)] = C[size_t(b * n + a) * 9 + size_t(di * 3 + ci)];
}

// Ke += psi_ak psi_bl C_ab for every pair of slots of the sub-cell of point p0.
void scatterSubcell(const ElementIntegration& ei, int p0, const std::vector<int>& base, int dim, int nd,
                    const std::vector<double>& C, std::vector<double>& Ke) {
    const int n = ei.nodeCount;
    for (int a = 0; a < n; ++a)
        for (int k = 0; k < ei.slots[size_t(a)]; ++k) {
            const double pa = ei.multiplier(p0, a, k);
            if (pa == 0.0) continue;
            const int ia = base[size_t(a)] + k * dim;
            for (int b = 0; b < n; ++b)
                for (int l = 0; l < ei.slots[size_t(b)]; ++l) {
                    const double pb = ei.multiplier(p0, b, l);
                    if (pb == 0.0) continue;
                    const double s = pa * pb;
                    const int ib = base[size_t(b)] + l * dim;
                    const double* c = &C[size_t(a * n + b) * 9];
                    for (int ci = 0; ci < dim; ++ci)
                        for (int di = 0; di < dim; ++di)
                            Ke[size_t(ia + ci) * size_t(nd) + size_t(ib + di)] += s * c[ci * 3 + di];
                }
        }
}

}  // namespace

// psi is constant on a sub-cell, so the enriched blocks of a sub-cell are its classical node-pair
// blocks times psi_ak psi_bl: the point loop runs over node pairs only, not over pairs of slots.
void generalStiffness(const ElementIntegration& ei, const PointGeometry& geo, const IsotropicLaw& law, int dim, int nd,
                      std::vector<double>& Ke) {
    if (ei.hasTip()) return tipStiffness(ei, geo, law, dim, nd, Ke);
    const int n = ei.nodeCount;
    std::vector<int> base(size_t(n) + 1, 0);  // local index of (a, slot 0)
    for (int a = 0; a < n; ++a) base[size_t(a) + 1] = base[size_t(a)] + ei.slots[size_t(a)] * dim;
    Ke.assign(size_t(nd) * size_t(nd), 0.0);
    thread_local std::vector<double> C;
    const size_t points = ei.refPoints.size();
    auto subcell = [&](size_t p) { return ei.pointSubcell.empty() ? 0 : ei.pointSubcell[p]; };
    for (size_t p0 = 0, p1 = 0; p0 < points; p0 = p1) {
        for (p1 = p0 + 1; p1 < points && subcell(p1) == subcell(p0);) ++p1;
        subcellBlocks(geo, law, n, dim, p0, p1, C);
        scatterSubcell(ei, int(p0), base, dim, nd, C, Ke);
    }
}

void generalInternalForce(const ElementIntegration& ei, const PointGeometry& geo, const std::vector<int>& dofs,
                          const std::vector<double>& u, const IsotropicLaw& law, int dim, std::vector<double>& fe,
                          const PointHook* pointHook) {
    fe.assign(dofs.size(), 0.0);
    const int n = ei.nodeCount;
    for (size_t p = 0; p < ei.refPoints.size(); ++p) {
        double G[3][3], S[3][3];
        displacementGradient(ei, geo, dofs, u, p, dim, G);
        if (pointHook) (*pointHook)(p, G);
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
            double traction[3] = {0.0, 0.0, 0.0};  // S grad N_a, the same for each of the node's slots
            for (int c = 0; c < dim; ++c)
                for (int j = 0; j < dim; ++j) traction[c] += S[c][j] * ga[j];
            for (int k = 0; k < ei.slots[a]; ++k) {
                const double pa = ei.multiplier(int(p), a, k);
                for (int c = 0; c < dim; ++c, ++i) fe[i] += wp * pa * traction[c];
            }
        }
    }
}

}  // namespace ma
