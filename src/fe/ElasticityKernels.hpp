#pragma once
// Small-strain isotropic elasticity at the element level: Hooke's law, the element's global dofs,
// displacement gradients, stresses, element stiffness matrices and internal-force vectors.
//
// Two forms of each kernel: the classical one (fixed sizes, fe/ClassicalElement.hpp, slot 0 and
// psi = 1) and the general one (any ElementIntegration: X-FEM slots and psi). The classical
// kernels do the general ones' operations in the same order, so both give the same bits.
#include <functional>
#include <string>
#include <vector>

#include "fe/ClassicalElement.hpp"
#include "fe/DofNumbering.hpp"
#include "fe/ElementIntegration.hpp"
#include "fe/ElementKinematics.hpp"
#include "fe/ElementLoop.hpp"
#include "fe/Material.hpp"
#include "fe/Model.hpp"

namespace ma {

// Hooke's law in the form used by the element loops: sigma = lambdaEff*tr(eps)*I + 2*mu*eps
// in the model plane; sigma_zz from lambdaZ (D_PLAN: lambda*(eps_xx+eps_yy), C_PLAN: 0), eps_zz
// from strainZ (D_PLAN: 0, C_PLAN: -nu/(1-nu)*(eps_xx+eps_yy), the free contraction).
struct IsotropicLaw {
    double lambdaEff = 0.0, mu = 0.0, lambdaZ = 0.0, strainZ = 0.0;
    static IsotropicLaw from(const Material& m, Modelisation modelisation, const std::string& where);
};

// Hooke's law of each element, recomputed only when the material or the modelisation changes
// from one element to the next (one material for the whole model is the usual case).
class LawCache {
public:
    explicit LawCache(const MaterialField& field) : field_(field) {}
    const IsotropicLaw& of(const ModelElement& element);

private:
    const MaterialField& field_;
    const Material* last_ = nullptr;
    Modelisation modelisation_ = Modelisation::D_PLAN;
    IsotropicLaw law_;
};

// What one worker of an element loop reuses from element to element: the general path's
// description and geometry, dofs, element matrix or vector, and the law.
struct ElementScratch {
    explicit ElementScratch(const MaterialField& material) : laws(material) {}
    GeneralElementScratch general;
    std::vector<int> dofs;
    std::vector<double> values;
    LawCache laws;
};

// The classical internal force's default: no look at the points.
struct NoPointHook {
    void operator()(int, const double (*)[3]) const {}
};

// Global dofs of the element's local unknowns (node-major, then slot, then component).
void localDofs(const Mesh& mesh, const DofNumbering& numbering, const ElementIntegration& ei, std::vector<int>& dofs);

// Displacement gradient of each local dof's shape function at point p of an element (psi and the
// crack-tip matrix included): B[i * 9 + c * 3 + j] = d(u_c)/dx_j for a unit value of local dof i.
// B grows to the element's dof count (a worker's scratch).
void dofGradients(const ElementIntegration& ei, const PointGeometry& geo, size_t p, int dim, std::vector<double>& B);

// Displacement gradient G[c][j] = du_c/dx_j at point p of an element (all slots, psi included).
void displacementGradient(const ElementIntegration& ei, const PointGeometry& geo, const std::vector<int>& dofs,
                          const std::vector<double>& u, size_t p, int dim, double G[3][3]);

// Stress S = lambda' tr(G) I + mu (G + G^T) in the model's dimensions.
inline void stressOf(const double G[3][3], const IsotropicLaw& law, int dim, double S[3][3]) {
    double tr = 0.0;
    for (int c = 0; c < dim; ++c) tr += G[c][c];
    for (int c = 0; c < dim; ++c)
        for (int j = 0; j < dim; ++j) S[c][j] = law.mu * (G[c][j] + G[j][c]) + (c == j ? law.lambdaEff * tr : 0.0);
}

// SIEF_ELGA components of a point (SIXX SIYY SIZZ SIXY [SIXZ SIYZ]) from its displacement gradient.
void storeStress(const double G[3][3], const IsotropicLaw& law, int dim, double* out);
// EPSI_ELGA components of a point (EPXX EPYY EPZZ EPXY [EPXZ EPYZ]).
void storeStrain(const double G[3][3], const IsotropicLaw& law, int dim, double* out);

// Stiffness of any element described by an ElementIntegration (X-FEM sub-cells, psi), nd x nd.
void generalStiffness(const ElementIntegration& ei, const PointGeometry& geo, const IsotropicLaw& law, int dim, int nd,
                      std::vector<double>& Ke);

// Internal-force vector of any element at the displacement u (fe: one entry per local dof).
// pointHook, when given, sees the displacement gradient of each point: (*pointHook)(p, G).
using PointHook = std::function<void(size_t p, const double (*G)[3])>;
void generalInternalForce(const ElementIntegration& ei, const PointGeometry& geo, const std::vector<int>& dofs,
                          const std::vector<double>& u, const IsotropicLaw& law, int dim, std::vector<double>& fe,
                          const PointHook* pointHook = nullptr);

// Global dofs of a classical element (slot 0 of each node: first(node) + component).
template <class Ref>
void classicalDofs(const Mesh& mesh, const DofNumbering& numbering, int cell, int* dofs) {
    const int* nodes = mesh.connectivity.data() + mesh.cellOffsets[cell];
    for (int a = 0; a < Ref::nodes; ++a)
        for (int c = 0; c < Ref::dim; ++c) dofs[a * Ref::dim + c] = numbering.first(nodes[a]) + c;
}

// Displacement gradient G[c][j] = du_c/dx_j of a classical element at one point (ue: the element's
// dofs node-major); the operations of displacementGradient with psi = 1.
template <int NN, int D>
void classicalGradient(const double (&grad)[NN][D], const double* ue, double G[3][3]) {
    for (int c = 0; c < 3; ++c)
        for (int j = 0; j < 3; ++j) G[c][j] = 0.0;
    for (int a = 0; a < NN; ++a)
        for (int c = 0; c < D; ++c)
            for (int j = 0; j < D; ++j) G[c][j] += ue[a * D + c] * grad[a][j];
}

// The stiffness block of a node pair a, b from the sum over the points of M = w grad N_a grad N_b^T
// (dim x dim, rows `stride` apart), in place: lambda M + mu M^T + mu tr(M) I. The point loops sum
// M only (dim x dim products a pair and point); the law comes once per pair.
inline void pairBlockFromProducts(double* m, int stride, const IsotropicLaw& law, int dim) {
    double M[3][3], trace = 0.0;
    for (int i = 0; i < dim; ++i) {
        for (int j = 0; j < dim; ++j) M[i][j] = m[i * stride + j];
        trace += M[i][i];
    }
    for (int i = 0; i < dim; ++i)
        for (int j = 0; j < dim; ++j)
            m[i * stride + j] = law.lambdaEff * M[i][j] + law.mu * M[j][i] + (i == j ? law.mu * trace : 0.0);
}

// Stiffness of a classical element (upper blocks, mirrored), row-major nd x nd. The same operations
// as generalStiffness would do with psi = 1.
template <class Ref>
void classicalStiffness(const classical::Geometry<Ref>& g, const IsotropicLaw& law, double* Ke) {
    constexpr int n = Ref::nodes, dim = Ref::dim, nd = Ref::dofs;
    for (int i = 0; i < nd * nd; ++i) Ke[i] = 0.0;
    for (int p = 0; p < Ref::points; ++p) {
        const double w = g.weight[p];
        for (int a = 0; a < n; ++a) {
            double wa[dim];
            for (int c = 0; c < dim; ++c) wa[c] = w * g.grad[p][a][c];
            for (int b = a; b < n; ++b) {
                const double* gb = g.grad[p][b];
                for (int ci = 0; ci < dim; ++ci)
                    for (int di = 0; di < dim; ++di) Ke[(a * dim + ci) * nd + b * dim + di] += wa[ci] * gb[di];
            }
        }
    }
    for (int a = 0; a < n; ++a)
        for (int b = a; b < n; ++b) pairBlockFromProducts(&Ke[(a * dim) * nd + b * dim], nd, law, dim);
    for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b)
            for (int ci = 0; ci < dim; ++ci)
                for (int di = 0; di < dim; ++di)
                    Ke[(b * dim + di) * nd + a * dim + ci] = Ke[(a * dim + ci) * nd + b * dim + di];
}

// Internal-force vector of a classical element (ue: its dofs' displacements, fl: zeroed by the
// caller); onPoint(p, G) sees the displacement gradient of each point.
template <class Ref, class OnPoint = NoPointHook>
void classicalInternalForce(const classical::Geometry<Ref>& g, const double* ue, const IsotropicLaw& law, double* fl,
                            OnPoint&& onPoint = {}) {
    for (int p = 0; p < Ref::points; ++p) {
        double G[3][3], S[3][3];
        classicalGradient(g.grad[p], ue, G);
        onPoint(p, G);
        stressOf(G, law, Ref::dim, S);
        const double wp = g.weight[p];
        for (int a = 0; a < Ref::nodes; ++a)
            for (int c = 0; c < Ref::dim; ++c) {
                double sum = 0.0;
                for (int j = 0; j < Ref::dim; ++j) sum += S[c][j] * g.grad[p][a][j];
                fl[a * Ref::dim + c] += wp * sum;
            }
    }
}

}  // namespace ma
