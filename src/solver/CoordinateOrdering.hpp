#pragma once
// Fill-reducing ordering by nested dissection with coordinate bisection: the unknowns' graph is
// cut by a plane across the longest extent of each part, the separator being the vertices on
// one side with a neighbour on the other; the plane is chosen among the positions near the
// median by the separator's weight (unknowns) and the balance of the two parts, so a cut avoids
// an X-FEM interface's enriched nodes. The parts are ordered first, the separator last.
//
// Why beside METIS: on the refined ssnv511 grids (1e6 vertices) METIS_NodeND takes 5 s of a 20 s
// run, and needs 4-12 % more flops than coordinate bisection in 2D and 3D; planes through a mesh find the
// separators of a grid's nested dissection in a fraction of a second (docs/study.md, "Orderings").
// It needs a point per unknown (its node's coordinates).
#include <span>

#include "solver/LinearSolver.hpp"
#include "solver/MetisOrdering.hpp"

namespace ma {

// rowPoints: one point per row of A (finite). The graph is that of nestedDissectionOrdering.
// `threads` >= 2 orders the halves of the top levels on two threads; the ranks do not depend on it.
FillReducingOrdering coordinateNestedDissection(const CsrMatrix& A, std::span<const RowPoint> rowPoints,
                                                int threads = 1);

}  // namespace ma
