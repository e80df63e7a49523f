#pragma once
// The energy release rate and the stress intensity factors of a front point by the theta method
// (code_aster's CALC_G, te0297 / xsifel): domain integrals over the integration points of the cells
// where the virtual crack extension theta varies,
//
//   G    = sum_p w [ sigma_ij u_i,k theta_k,j - 1/2 sigma_ij u_i,j theta_k,k ]
//   I(a) = sum_p w [ (sigma_ij ua_i,k + sigma^a_ij u_i,k) theta_k,j - sigma^a_ij u_i,j theta_k,k ]
//
// (no body force, unloaded lips, linear elasticity, small strains), with the auxiliary Williams
// fields ua of unit K: K1 = E* I(mode I) / 2, K2 = E* I(mode II) / 2, K3 = mu I(mode III),
// E* = E / (1 - nu^2) in plane strain and 3D, E in plane stress. Where the frame turns (a curved 3D
// front) I(a) also takes the volume term sum_p w [div sigma^a . (grad u theta) + sigma_ij (ua_i,kj
// - ua_i,jk) theta_k] that the straight front's fields do not need (docs/cracks.md).
#include <array>
#include <span>
#include <vector>

#include "core/Vec3.hpp"
#include "fe/Model.hpp"

namespace ma::fracture {

// The local basis of a front point: e1 the propagation direction, e2 the normal to the crack,
// e3 = e1 x e2 along the front (2D: e3 = z).
struct FrontFrame {
    Vec3 origin{};
    Vec3 e1{}, e2{}, e3{};
    // d(e_k)_i / dx_j at the point (code_aster's xcourb): on a curved 3D front the auxiliary
    // displacement u_k e_k turns with the basis, which adds u_k d(e_k)_i / dx_j to its gradient.
    // Zero for a straight front and in 2D.
    double basisGradient[3][3][3]{};
    // grad(div e1), grad(div e2) at the point: the basis' second derivatives in the curved front's
    // volume term (e1, e2 taken as the gradients of LST, LSN). Zero for a straight front.
    Vec3 divergenceGradient[2]{};
};

// What the integrals need at one integration point.
struct DomainPoint {
    double weight = 0.0;       // physical weight (2D: unit thickness)
    Vec3 xyz{};                // physical point
    double gradU[3][3]{};      // du_i/dx_j of the solution
    Vec3 theta{};              // the virtual crack extension
    double gradTheta[3][3]{};  // dtheta_k/dx_j
    double side = 0.0;         // +1: theta = +pi side of the crack (x2 > 0 near it), -1 the other, 0: from x2
    double E = 0.0, nu = 0.0;  // the material of the point's cell
};

// Hooke's law of the model and the constants of the SIF formulas.
struct ElasticConstants {
    double lambda = 0.0, mu = 0.0;  // lambda: plane-stress reduced in C_PLAN
    double kappa = 0.0;             // Kolosov's constant
    double eStar = 0.0;             // E / (1 - nu^2), or E in plane stress
    static ElasticConstants of(double E, double nu, Modelisation modelisation);
};

struct FrontValues {
    double G = 0.0, K1 = 0.0, K2 = 0.0, K3 = 0.0;
    double gIrwin = 0.0;  // (K1^2 + K2^2) / E* + K3^2 / (2 mu), at the last point's material
    // K1 / sqrt(E*), K2 / sqrt(E*), K3 / sqrt(2 mu) summed point by point with each point's
    // material (code_aster's G_IRWIN components, smoothed along a 3D front before squaring).
    std::array<double, 3> irwin{};
};

// The integrals over `points` for the front point of `frame`; `dim` = 2 or 3 (index ranges).
// `withK`: the interaction integrals too (OPTION='CALC_K_G').
FrontValues domainIntegrals(const std::vector<DomainPoint>& points, const FrontFrame& frame, Modelisation modelisation,
                            int dim, bool withK);

// The same with the auxiliary fields written in a frame of each point (`frames[p]`, code_aster's
// BASLOC interpolated at the point in 3D, coor_cyl) instead of one front point's.
FrontValues domainIntegrals(const std::vector<DomainPoint>& points, std::span<const FrontFrame> frames,
                            Modelisation modelisation, int dim, bool withK);

}  // namespace ma::fracture
