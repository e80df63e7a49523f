#pragma once
// LISSAGE_G along a 3D front (code_aster's gmeth3 for OPTION='CALC_G', gkmet3 for 'CALC_K_G', with
// the mass matrix of the front's linear segments, gmatc3 / gmatl3): the domain integral of the
// theta field of front point k is the weighted mean int phi_k G ds, so
//   LAGRANGE:       M g = b, M_kl = int phi_k phi_l ds (a closed front joins its ends);
//   LAGRANGE_NO_NO: g_k = b_k / sum_l M_kl (the lumped matrix).
// With the stress intensity factors (gkmet3) on an open front of 3 points or more, LAGRANGE first
// replaces the integrals at the end points by b_2 (s_2 - s_1)/(s_3 - s_1) and the mirror at the
// other end, and LAGRANGE_NO_NO extrapolates the end values linearly from their two neighbours.
// LEGENDRE (gkmet1, gmatr1): the integrals of the Legendre polynomials' theta fields solve
// A c = b with A_ij = int P_i P_j ds (14 Gauss points per segment, ~ the identity) and
// g(s_i) = sum_j c_j P_j(s_i).
// G_IRWIN: sum_c (g_c)^2 of the smoothed K_c / sqrt(E*) (K3 / sqrt(2 mu)), whose integrals get no
// end correction (LAGRANGE), or the integrals' squared sum over the squared lumped mass (NO_NO).
#include <vector>

#include "fracture/DomainIntegrals.hpp"

namespace ma::fracture {

enum class GSmoothing { Lagrange, LagrangeNoNo, Legendre };

// `integrals[k]`: the domain integrals of front point k's theta field; `abscissa` the front's.
std::vector<FrontValues> smoothAlongFront(std::vector<FrontValues> integrals, const std::vector<double>& abscissa,
                                          bool closed, GSmoothing smoothing, bool withK);

// `integrals[k]`: those of the Legendre polynomial of degree k (0 ... DEGRE); values at the front points.
std::vector<FrontValues> legendreAlongFront(const std::vector<FrontValues>& integrals,
                                            const std::vector<double>& abscissa);

}  // namespace ma::fracture
