#pragma once
// The Krylov operator of the PETSc solver (PetscSolver.cpp), a PETSc shell.
#include <petscmat.h>

#include <vector>

#include "solver/PiecesOnProcesses.hpp"
#include "solver/SparseMatrix.hpp"

namespace ma {

// y = S A S x without storing S A S. Distributed (MATR_DISTRIBUEE on several processes): A is
// this process's part, the products are summed over the processes (rank 0's sum broadcast, so that
// every process holds the same y and their Krylov iterations stay identical).
// With a piece basis (multigrid on an X-FEM model), y = S T^T A T S x on the copies, and x itself on
// the padding unknowns; shared between processes, x and y are the process's share, and the products
// of the processes' parts are summed in its equations.
struct ScaledOperator {
    const CsrMatrix* A = nullptr;
    const std::vector<double>* scale = nullptr;
    const PieceBasis* basis = nullptr;
    const SharedPieces* shared = nullptr;
    bool distributed = false;
    std::vector<double> work, equations, product, mine;

    void apply(const double* x, double* y);
    void applyInPieces(const double* x, double* y);
};

// MATOP_MULT of the shell whose context is a ScaledOperator.
PetscErrorCode multiplyScaled(Mat m, Vec x, Vec y);

}  // namespace ma
