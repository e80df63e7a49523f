#pragma once
// The displacement jump of the crack lips that POST_K1_K2_K3 extrapolates, sampled as code_aster
// samples it for a fiss_xfem (post_k1_k2_k3_ops, MACR_LIGN_COUPE): NB_NOEUD_COUPE points evenly
// spaced on the segment from the front point back along the propagation direction over
// ABSC_CURV_MAXI, and at each twice the first Heaviside unknowns H1 projected as code_aster's
// PROJ_CHAMP projects a component some nodes lack (cnsprj: over the nodes that carry it,
// renormalised; 0 where none does). The shifted Heaviside function jumps by 2; code_aster neglects
// the crack-tip terms there, whose shifted functions vanish at the nodes. Points outside the mesh
// are dropped.
#include <vector>

#include "core/Vec3.hpp"
#include "fields/Fields.hpp"

namespace ma::fracture {

struct LipSamples {
    std::vector<double> abscissa;  // distance from the front point
    std::vector<Vec3> jump;        // global components (z = 0 in 2D)
};

LipSamples heavisideJumps(const Mesh& mesh, const NodalField& depl, const Vec3& front, const Vec3& direction,
                          double length, int points);

}  // namespace ma::fracture
