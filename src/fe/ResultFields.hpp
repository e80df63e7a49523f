#pragma once
// Result fields of a mechanical problem's state: DEPL (nodal), SIEF_ELGA and EPSI_ELGA (stresses and
// strains at the elements' integration points, X-FEM sub-cell points included).
#include <memory>
#include <vector>

#include "fe/Discretisation.hpp"
#include "fields/Fields.hpp"

namespace ma {

std::shared_ptr<NodalField> displacementField(const Discretisation& space, const std::vector<double>& u);

// SIXX SIYY SIZZ SIXY (2D), + SIXZ SIYZ (3D); every point with its physical coordinates, physical
// weight, reference coordinates and sub-cell.
std::shared_ptr<GaussField> stressField(const Discretisation& space, const std::vector<double>& u);

// EPSI_ELGA: EPXX EPYY EPZZ EPXY (2D), + EPXZ EPYZ (3D), the tensor components (EPXY = (dux/dy +
// duy/dx) / 2), at the same points as stressField; EPZZ is 0 in D_PLAN, the free contraction in C_PLAN.
std::shared_ptr<GaussField> strainField(const Discretisation& space, const std::vector<double>& u);

}  // namespace ma
