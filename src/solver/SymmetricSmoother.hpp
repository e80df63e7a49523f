#pragma once
// ML's smoothers in the piece basis on the upper triangle of their matrices (PETSc's SBAIJ, block
// size 1; docs/solver.md, "The finest smoother on the upper triangle"). The smoother's SOR sweeps and
// Chebyshev products are bound by the memory they read: the symmetric storage reads half the
// entries, for the same sweeps and products.
#include <petscksp.h>

#include <string>

#include "solver/SparseMatrix.hpp"

namespace ma {

// The upper triangle of a symmetric matrix as a PETSc SBAIJ matrix: B holds this process's rows
// (global columns, the first of them row `first`), `size` is the whole matrix's.
Mat upperTriangleOf(const CsrMatrix& B, size_t first, PetscInt size, MPI_Comm comm);

// Every multigrid level's smoother of `pc` that sweeps by SOR on its level's assembled matrix (not
// on the Krylov operator, nor by another method OPTION_PETSC asked for) sweeps and multiplies on that
// matrix's upper triangle instead, and the level's residual before restriction is computed there
// too: `finestUpper` on the finest level, a copy of the level's matrix elsewhere (the coarsest level
// is solved, not smoothed). Returns how many levels changed.
// estimateSteps > 0: every Chebyshev smoother's eigenvalue estimate is made again with that many
// GMRES steps, on the matrix it sweeps (KrylovSettings.hpp, estimatesAfterSetUp).
int smoothOnUpperTriangles(PC pc, Mat finestUpper, int estimateSteps);

// For the .mess: how a Chebyshev smoother's eigenvalue bounds were estimated (" (eigenvalue bounds
// from 10 gmres step(s))"; empty when they were not estimated).
std::string eigenvalueBoundsOf(KSP smoother);

}  // namespace ma
