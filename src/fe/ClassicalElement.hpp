#pragma once
// Classical (uncut, unenriched) volume elements with their sizes known at compile time: TRIA3 and
// QUAD4 in a 2D model, TETRA4 and HEXA8 in 3D, on their stiffness rule (fe/Quadrature.hpp).
//
// Nearly every element of a large model is classical, so their loops (stiffness, internal forces,
// stresses, POST_ERREUR sampling) are written here with fixed-size arrays: the shape values and
// reference derivatives at the rule's points are computed once per cell type, and an element needs
// no allocation and no per-point shape-function call. The arithmetic is the general path's
// (computePointGeometry, ElementIntegration loops of MechanicalProblem.cpp) operation for
// operation, so both give the same bits; tests/unit/fe_classical.cpp checks it.
#include <array>
#include <cmath>

#include "fe/Quadrature.hpp"
#include "mesh/ElementGeometry.hpp"
#include "mesh/Mesh.hpp"
#include "mesh/ShapeFunctions.hpp"

namespace ma::classical {

// Reference data of a cell type's stiffness rule.
template <int NN, int D, int NP>
struct Reference {
    static constexpr int nodes = NN, dim = D, points = NP, dofs = NN * D;
    double N[NP][NN];
    double dN[NP][NN][D];  // dN_a / dxi_j
    double weight[NP];
    std::array<double, 3> point[NP];

    explicit Reference(CellType type) {
        const QuadratureRule& rule = stiffnessRule(type, false);
        std::array<double, 24> d{};
        for (int p = 0; p < NP; ++p) {
            point[p] = rule.points[p];
            weight[p] = rule.weights[p];
            shapeValues(type, rule.points[p], std::span<double>(N[p], NN));
            shapeDerivatives(type, rule.points[p], d);
            for (int a = 0; a < NN; ++a)
                for (int j = 0; j < D; ++j) dN[p][a][j] = d[3 * a + j];
        }
    }
};

using Tria3 = Reference<3, 2, 1>;
using Quad4 = Reference<4, 2, 4>;
using Tetra4 = Reference<4, 3, 1>;
using Hexa8 = Reference<8, 3, 8>;

const Tria3& tria3();
const Quad4& quad4();
const Tetra4& tetra4();
const Hexa8& hexa8();

// Physical data of one element at the rule's points.
template <class Ref>
struct Geometry {
    double grad[Ref::points][Ref::nodes][Ref::dim];  // physical gradients of N_a
    double weight[Ref::points];                      // reference weight x |det J|
    std::array<double, 3> xyz[Ref::points];
};

// NumericalError naming the cell (the general path's message) for a degenerate Jacobian.
[[noreturn]] void badJacobian(const Mesh& mesh, int cell, double det);

template <class Ref>
inline void computeGeometry(const Ref& ref, const Mesh& mesh, int cell, Geometry<Ref>& g) {
    constexpr int NN = Ref::nodes, D = Ref::dim;
    const int* nodes = mesh.connectivity.data() + mesh.cellOffsets[cell];
    const std::array<double, 3>* X[NN];
    for (int a = 0; a < NN; ++a) X[a] = &mesh.coords[nodes[a]];
    for (int p = 0; p < Ref::points; ++p) {
        std::array<double, 3> x{};
        for (int a = 0; a < NN; ++a)
            for (int i = 0; i < 3; ++i) x[i] += ref.N[p][a] * (*X[a])[i];
        g.xyz[p] = x;
        double J[D][D], inv[D][D];
        jacobian<D, D>(
            NN, [&](int a) -> const Vec3& { return *X[a]; }, [&](int a, int j) { return ref.dN[p][a][j]; }, J);
        const double det = invertJacobian<D>(J, inv);
        if (degenerateJacobian<D>(J, det)) badJacobian(mesh, cell, det);
        g.weight[p] = ref.weight[p] * std::abs(det);
        for (int a = 0; a < NN; ++a)
            physicalGradient<D>(
                inv, [&](int i) { return ref.dN[p][a][i]; }, g.grad[p][a]);
    }
}

// Calls f(reference) with the fixed-size description of a classical volume cell of a model of
// dimension `dim`; false (f not called) for any other cell.
template <class F>
inline bool dispatch(CellType type, int dim, F&& f) {
    if (dim == 2) {
        if (type == CellType::QUAD4) return f(quad4()), true;
        if (type == CellType::TRIA3) return f(tria3()), true;
    } else if (dim == 3) {
        if (type == CellType::HEXA8) return f(hexa8()), true;
        if (type == CellType::TETRA4) return f(tetra4()), true;
    }
    return false;
}

}  // namespace ma::classical
