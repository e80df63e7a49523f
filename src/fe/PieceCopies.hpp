#pragma once
// The piece basis of an X-FEM model (solver/PieceBasis.hpp, docs/solver.md "The piece basis"): per
// node and component, the values of the enriched displacement in the pieces of the node's support
// (fe/NearNullSpace's blocks) instead of the slot values, and the model's rigid modes on them.
#include "fe/DirichletConstraints.hpp"
#include "fe/Discretisation.hpp"
#include "solver/PieceBasis.hpp"

namespace ma {

// Empty (copies == 0, `refusal` says why) when some free equation is not a piece value of a node's
// displacement (multipliers, crack-tip or contact unknowns) or the pieces of a node do not determine
// its free slots one to one.
PieceBasis pieceBasisOf(const Discretisation& space, const DirichletConstraints& constraints, int rows);

}  // namespace ma
