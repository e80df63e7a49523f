#pragma once
// Where each equation of a mechanical problem lives, for the solver's coordinate ordering: the
// coordinates of the node that carries its unknown (the near null space: fe/NearNullSpace.hpp).
#include <vector>

#include "fe/DirichletConstraints.hpp"
#include "fe/Discretisation.hpp"
#include "solver/LinearSolver.hpp"

namespace ma {

// One point per equation (`rows` of them), or none when some equation has no node (a Lagrange
// multiplier of a relation, an additional term's own unknown): the solver then orders by METIS.
std::vector<RowPoint> equationPoints(const Discretisation& space, const DirichletConstraints& constraints, int rows);

}  // namespace ma
