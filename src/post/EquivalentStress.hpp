#pragma once
// CALC_CHAMP CRITERES: the equivalent stresses of a stress field at each of its points, the 17
// components of code_aster's SIEQ (fgequi, 'SIGM_DIR'):
//   VMIS = sqrt(3/2 s:s) (s the deviator), TRESCA = the largest difference of principal stresses,
//   PRIN_1 <= PRIN_2 <= PRIN_3 the principal stresses, VMIS_SG = VMIS signed by the trace,
//   VECT_i_X/Y/Z the unit principal direction of PRIN_i (its sign is arbitrary), TRSIG = the
//   trace, TRIAX = (trace/3) / VMIS (0 when VMIS is ~0).
// In 2D the tensor is the 3x3 one with SIXZ = SIYZ = 0 (SIZZ as the modelisation gives it).
#include <memory>

#include "fields/Fields.hpp"

namespace ma::post {

// SIEQ at the points of `sigma` (SIXX SIYY SIZZ SIXY [SIXZ SIYZ]): SIEQ_ELGA from SIGM_ELGA,
// SIEQ_ELNO from SIGM_ELNO.
std::shared_ptr<GaussField> equivalentStresses(const GaussField& sigma);

}  // namespace ma::post
