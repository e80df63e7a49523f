#pragma once
// External forces F_ext of a mechanical problem's loads at one instant: pressures on boundary
// cells (t = -p n) and volume forces, values x FONC_MULT(INST). Function values are evaluated
// once per load and instant, in one batch over all points.
#include <vector>

#include "fe/Discretisation.hpp"
#include "fe/LoadCase.hpp"

namespace ma {

// f: numbering().size() entries.
void assembleExternalForces(const Discretisation& space, const std::vector<LoadCase>& loads, double inst,
                            std::vector<double>& f);

}  // namespace ma
