#pragma once
// Geometry of a linear cell's map x(xi) = sum_a N_a(xi) X_a at one reference point, the single
// source of the Jacobian J = dx/dxi, its determinant and inverse, the measure and the physical
// gradients of the shape functions (MFEM's ElementTransformation in spirit). Shape values and
// reference derivatives come from mesh/ShapeFunctions.hpp; these functions only combine them with
// the node coordinates, in one fixed order of operations, so every user gets the same bits.
//
// Conventions: J[i][j] = dx_i/dxi_j; dN(a, j) = dN_a/dxi_j; inv = J^-1, so the physical gradient is
// grad_j N_a = sum_i inv[i][j] dN(a, i) (grad N = J^-T dN).
#include <span>

#include "core/Vec3.hpp"
#include "mesh/CellType.hpp"

namespace ma {

// J[i][j] for i < R, j < C (other entries untouched), summed over the n nodes in node order;
// X(a) gives node a's coordinates, dN(a, j) its reference derivatives.
template <int R, int C, class Coords, class Derivatives, class Matrix>
inline void jacobian(int n, Coords&& X, Derivatives&& dN, Matrix& J) {
    for (int i = 0; i < R; ++i)
        for (int j = 0; j < C; ++j) J[i][j] = 0.0;
    for (int a = 0; a < n; ++a) {
        const Vec3& Xa = X(a);
        for (int i = 0; i < R; ++i)
            for (int j = 0; j < C; ++j) J[i][j] += Xa[i] * dN(a, j);
    }
}

// Runtime-size form on 3 x 3 storage: rows = space dimension used (2, 3), cols = reference
// dimension (1, 2, 3).
template <class Coords, class Derivatives>
inline void jacobian(int rows, int cols, int n, Coords&& X, Derivatives&& dN, double J[3][3]) {
    if (rows == 2 && cols == 2) return jacobian<2, 2>(n, X, dN, J);
    if (rows == 2 && cols == 1) return jacobian<2, 1>(n, X, dN, J);
    if (cols == 1) return jacobian<3, 1>(n, X, dN, J);
    if (cols == 2) return jacobian<3, 2>(n, X, dN, J);
    jacobian<3, 3>(n, X, dN, J);
}

// The full 3 x rdim Jacobian (rows x, y, z) from derivatives laid out dN[3a + j], the layout of
// shapeDerivatives; columns j >= rdim set to 0.
void jacobian(std::span<const Vec3> nodes, std::span<const double> dN, int rdim, double J[3][3]);

// det J and inv = J^-1 of the leading D x D block (D = 2, 3), by cofactors divided by det. When
// det = 0 the inverse is not finite: callers test det first.
template <int D, class Matrix, class Inverse>
inline double invertJacobian(const Matrix& J, Inverse& inv) {
    double det;
    if constexpr (D == 2) {
        det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
        inv[0][0] = J[1][1] / det, inv[0][1] = -J[0][1] / det;
        inv[1][0] = -J[1][0] / det, inv[1][1] = J[0][0] / det;
    } else {
        static_assert(D == 3, "2D or 3D Jacobians only");
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
    return det;
}

// Whether det J is round-off for the cell's own size: |det J| <= kDegenerateJacobian times the
// product of the lengths of J's columns (the reference edges once mapped). The ratio is the volume
// of the mapped edges over that of a box with the same edge lengths: near 1 for a well-shaped cell
// however thin, 0 for coincident or aligned nodes. Its sign (the cell's orientation) does not
// matter: left-handed and clockwise cells are integrated with |det J|, as code_aster does. A NaN
// (non-finite coordinates) counts as degenerate.
inline constexpr double kDegenerateJacobian = 1e-12;

template <int D, class Matrix>
inline bool degenerateJacobian(const Matrix& J, double det) {
    double product = 1.0;
    for (int j = 0; j < D; ++j) {
        double column = 0.0;
        for (int i = 0; i < D; ++i) column += J[i][j] * J[i][j];
        product *= column;
    }
    return !(det * det > kDegenerateJacobian * kDegenerateJacobian * product);
}

inline bool degenerateJacobian(int dim, const double J[3][3], double det) {
    return dim == 2 ? degenerateJacobian<2>(J, det) : degenerateJacobian<3>(J, det);
}

// Runtime dimension (2 or 3) form of invertJacobian on 3 x 3 storage.
inline double invertJacobian(int dim, const double J[3][3], double inv[3][3]) {
    return dim == 2 ? invertJacobian<2>(J, inv) : invertJacobian<3>(J, inv);
}

// Physical gradient of one shape function: g[j] = sum_i inv[i][j] d(i), j < D.
template <int D, class Inverse, class Derivative, class Gradient>
inline void physicalGradient(const Inverse& inv, Derivative&& d, Gradient&& g) {
    for (int j = 0; j < D; ++j) {
        double s = 0.0;
        for (int i = 0; i < D; ++i) s += inv[i][j] * d(i);
        g[j] = s;
    }
}

template <class Inverse, class Derivative, class Gradient>
inline void physicalGradient(int dim, const Inverse& inv, Derivative&& d, Gradient&& g) {
    if (dim == 2) physicalGradient<2>(inv, d, g);
    else physicalGradient<3>(inv, d, g);
}

// Measure of the map at the point: |det J| for a cell of the space's dimension, the length or
// area element sqrt(det(J^T J)) for edges and faces (J: 3 x rdim).
double jacobianMeasure(const double J[3][3], int rdim);

// Normal of a boundary cell by its node order, not normalised (|normal| = its measure): 2D skin
// (rdim 1) n = (t_y, -t_x) with t = dx/dxi from node 1 to node 2; 3D face: dx/dxi x dx/deta.
Vec3 boundaryNormal(const double J[3][3], int rdim);

}  // namespace ma
