#pragma once
// Direct solvers behind one interface: MUMPS (the default, SOLVEUR METHODE='MUMPS'; on one process
// or distributed over several, docs/mpi.md)
// and Eigen's sparse factorisations (METHODE='MULT_FRONT' / 'LDLT'). Both factorise the
// symmetrically diagonal-scaled matrix D^-1/2 A D^-1/2 and refine the solution iteratively
// (transparent to callers: A, b and x are the unscaled ones). Each logs the system size,
// non-zeros, ordering, scaling, factorisation and solve times, the residual ||Ax - b|| / ||b||
// and the componentwise backward error; a singular matrix raises NumericalError with the likely
// cause.
#include <array>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "solver/PieceBasis.hpp"
#include "solver/SparseMatrix.hpp"

namespace ma {

// Where an unknown lives (its node's coordinates), for the coordinate ordering of RENUM='AUTO'.
using RowPoint = std::array<float, 3>;

enum class MatrixKind {
    SymmetricPositiveDefinite,  // stiffness with Dirichlet conditions eliminated
    SymmetricIndefinite,        // with Lagrange multipliers
};

struct SolverOptions {
    std::string method = "MUMPS";  // MUMPS | MULT_FRONT | LDLT | PETSC | GCPC
    // PETSC and GCPC: Krylov methods, whose RESI_RELA is their stopping tolerance.
    bool krylov() const { return method == "PETSC" || method == "GCPC"; }
    // MUMPS ordering: AUTO (coordinate nested dissection when every row has a point, else METIS)
    // METIS AMD AMF QAMD PORD SCOTCH
    std::string renum = "AUTO";
    int nprec = 8;                   // singular pivot threshold 10^-NPREC; < 0 disables the detection
    int pcentPivot = 20;             // MUMPS workspace relaxation (%)
    std::string typeResol = "AUTO";  // MUMPS TYPE_RESOL: SYMDEF forces SYM=1 on SPD systems
    // MUMPS ACCELERATION: AUTO and FR* full rank; LR* refused (MumpsSolver.cpp says why).
    std::string acceleration = "AUTO";
    // MUMPS MIXER_PRECISION='OUI': single-precision factors (smumps) refined against the double
    // matrix until the answer meets RESI_RELA (or, without it, double-precision round-off).
    bool mixedPrecision = false;
    // RESI_RELA: a solve whose relative residual ||Ax-b||/||b|| stays above it is an error naming
    // the solver; <= 0: no check (the alarm FACTOR_57 above 1e-6 only).
    double resiRela = -1.0;
    // MUMPS FILTRAGE_MATRICE: off-diagonal entries with |a_ij| < f (|a_ii| + |a_jj|) are left out of
    // the factorised matrix (the refinement works against the whole one); <= 0: none.
    double matrixFilter = -1.0;
    // MUMPS GESTION_MEMOIRE: IN_CORE, OUT_OF_CORE (factors on disk under TMPDIR), AUTO (in core
    // unless the analysis' estimate exceeds the available memory), EVAL (estimates, then stop).
    std::string memory = "AUTO";
    // PETSC / GCPC (docs/solver.md): ALGORITHME, PRE_COND, NMAX_ITER (0: PETSc's default, 10000),
    // REAC_PRECOND (LDLT_SP/LDLT_DP factors kept for the next matrices while a solve needs at most that
    // many iterations), OPTION_PETSC, NIVE_REMPLISSAGE (LDLT_INC). RESI_RELA is the Krylov tolerance.
    std::string algorithm = "FGMRES";
    std::string preconditioner = "LDLT_SP";
    int maxIterations = 0;
    int reacPrecond = 30;
    std::string petscOptions;
    int fillLevel = 0;
    bool conditionEstimate = false;  // MUMPS ICNTL(11)=1: condition numbers (costs a few solves)
    bool diagonalScaling = true;     // factorise D^-1/2 A D^-1/2 (code_aster: PRETRAITEMENTS)
    int maxRefinementSteps = 3;      // iterative refinement while it helps; 0 = none (POSTTRAITEMENTS)
    int info = 1;
    // Threads of the solver's own loops (MUMPS's input, the residuals, the coordinate ordering's
    // top halves) and processes of the METIS ordering's two halves, when >= 2.
    int threads = 1;
    // The matrix is the sum of the MPI processes' parts (docs/mpi.md, MUMPS only): each process
    // passes its own; right-hand sides are the same on every process, and so are the solutions.
    bool distributed = false;
    // Distributed: the pattern of the whole matrix (each process holds only its cells' part), for
    // the fill-reducing ordering on rank 0; built when asked and freed after the analysis.
    std::function<CsrMatrix()> wholePattern;
    // The near null space of the matrix (the rigid modes of the model's blocks, vector after vector,
    // `rows` values each; empty when unknown), asked by the multigrid preconditioners GAMG and ML
    // (docs/solver.md).
    std::function<std::vector<double>()> nearNullSpace;
    // X-FEM models: the piece basis (solver/PieceBasis.hpp) GAMG, ML and BOOMER iterate in, with its
    // rigid modes; empty (copies == 0, with the reason) when the model has none.
    std::function<PieceBasis()> pieceBasis;
    // Appended to the "singular system" message: what the caller knows about likely causes.
    std::string singularHint = "a missing boundary condition (rigid body motion) or an unattached enriched dof";
};

class LinearSolver {
public:
    virtual ~LinearSolver() = default;
    virtual std::string name() const = 0;
    // Analyses and factorises A. A must stay alive and unchanged until the last solve (the
    // residual check reads it). rowPoints: one per row, or empty when some row has none.
    virtual void factorize(const CsrMatrix& A, MatrixKind kind, std::span<const RowPoint> rowPoints = {}) = 0;
    // rhs is overwritten by the solution. Returns ||A x - b|| / ||b|| (0 when b = 0).
    virtual double solve(std::span<double> rhs) = 0;
};

std::unique_ptr<LinearSolver> makeLinearSolver(const SolverOptions& options);

// Relative residual ||A x - b||_2 / ||b||_2, computed in a separate pass.
double relativeResidual(const CsrMatrix& A, std::span<const double> x, std::span<const double> b);

}  // namespace ma
