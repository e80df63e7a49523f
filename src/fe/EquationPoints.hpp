#pragma once
// Where each equation of a mechanical problem lives, for the solver's coordinate ordering: the
// coordinates of the node that carries its unknown; and the rigid body modes for multigrid.
#include <vector>

#include "fe/DirichletConstraints.hpp"
#include "fe/Discretisation.hpp"
#include "solver/LinearSolver.hpp"

namespace ma {

// One point per equation (`rows` of them), or none when some equation has no node (a Lagrange
// multiplier of a relation, an additional term's own unknown): the solver then orders by METIS.
std::vector<RowPoint> equationPoints(const Discretisation& space, const DirichletConstraints& constraints, int rows);

// The rigid body motions (2D: 2 translations, 1 rotation; 3D: 3 and 3) on the free equations, mode
// after mode (`rows` values each), for algebraic multigrid's near null space (PETSc's GAMG, ML).
// The enrichment unknowns are 0 in every mode (a rigid motion of the whole needs no jump). Empty
// when some equation has no node (multipliers, additional unknowns).
std::vector<double> rigidBodyModes(const Discretisation& space, const DirichletConstraints& constraints, int rows);

}  // namespace ma
