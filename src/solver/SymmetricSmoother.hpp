#pragma once
// ML's finest smoother in the piece basis on the upper triangle of its matrix (PETSc's SBAIJ, block
// size 1; docs/solver.md, "The finest smoother on the upper triangle"). The smoother's SOR sweeps and
// Chebyshev products are bound by the memory they read: the symmetric storage reads half the
// entries, for the same sweeps and products.
#include <petscksp.h>

#include "solver/SparseMatrix.hpp"

namespace ma {

// The upper triangle of a symmetric matrix as a PETSc SBAIJ matrix: B holds this process's rows
// (global columns, the first of them row `first`), `size` is the whole matrix's.
Mat upperTriangleOf(const CsrMatrix& B, size_t first, PetscInt size, MPI_Comm comm);

// When the finest smoother of the multigrid preconditioner `pc` sweeps by SOR on the assembled
// matrix (not on the Krylov operator, nor by another method OPTION_PETSC asked for), it sweeps and
// multiplies on `upper` instead. Returns whether it does.
bool smoothFinestOn(PC pc, Mat upper);

}  // namespace ma
