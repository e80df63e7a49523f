#pragma once
// Result fields of a mechanical problem's state: DEPL (nodal) and SIEF_ELGA (stresses at the
// elements' integration points, X-FEM sub-cell points included).
#include <memory>
#include <vector>

#include "fe/Discretisation.hpp"
#include "fields/Fields.hpp"

namespace ma {

std::shared_ptr<NodalField> displacementField(const Discretisation& space, const std::vector<double>& u);

// SIXX SIYY SIZZ SIXY (2D), + SIXZ SIYZ (3D); every point with its physical coordinates, physical
// weight, reference coordinates and sub-cell.
std::shared_ptr<GaussField> stressField(const Discretisation& space, const std::vector<double>& u);

}  // namespace ma
