#pragma once
// The displacement jump of the crack lips that POST_K1_K2_K3 extrapolates, sampled as code_aster
// samples it for a fiss_xfem (post_k1_k2_k3_ops: MACR_LIGN_COUPE, whose PROJ_CHAMP projects an
// X-FEM DEPL with pjxfem): NB_NOEUD_COUPE points evenly spaced on the segment from the front point
// back along the propagation direction over ABSC_CURV_MAXI, and at each 2 H1 with
// H1 = sum_a N_a H1_a (nodes without H1 add nothing) plus half the jump of the crack-tip terms
// across the crack at the point (`tipJump` returns the whole tip jump). The shifted Heaviside
// function jumps by 2. A point outside the mesh takes the values at its projection on the nearest
// cell when that lies within maxDistance (MACR_LIGN_COUPE's DISTANCE_MAX, PREC_VIS_A_VIS times
// ABSC_CURV_MAXI: a segment from a front end on a boundary face that leaves the face at a slant),
// and is dropped otherwise.
#include <functional>
#include <span>
#include <vector>

#include "core/Vec3.hpp"
#include "fields/Fields.hpp"
#include "mesh/PointLocation.hpp"

namespace ma::fracture {

struct LipSamples {
    std::vector<double> abscissa;  // distance from the front point
    std::vector<Vec3> jump;        // global components (z = 0 in 2D)
};

// The jump of the crack-tip terms at a point (its cell, reference coordinates, shape functions).
using TipJump = std::function<Vec3(const PointInCell& at, std::span<const double> N)>;

LipSamples heavisideJumps(const Mesh& mesh, const NodalField& depl, const Vec3& front, const Vec3& direction,
                          double length, int points, double maxDistance = 0.0, const TipJump& tipJump = {});

}  // namespace ma::fracture
