#pragma once
// Internal to src/solver: what SOLVEUR METHODE='PETSC' / 'GCPC' means in PETSc's terms (the Krylov
// method, the preconditioner, OPTION_PETSC) and which combinations are refused before iterating
// (docs/solver.md, "Which preconditioner for which system").
#include <petscksp.h>

#include <string>

#include "solver/LinearSolver.hpp"

namespace ma {

// ALGORITHME, or CG for GCPC.
// A PETSc call's error code as an exception naming the call (NumericalError).
void checkPetsc(PetscErrorCode code, const char* call);

std::string krylovAlgorithm(const SolverOptions& options);
// A NotImplemented / UserError for what PETSc cannot do here or cannot converge on: a saddle-point
// system (`indefinite`: multipliers, contact unknowns) with a preconditioner that divides by its
// zero diagonal or coarsens it (JACOBI, SOR, LDLT_INC, GAMG, BOOMER, ML, SANS), or with CG / CR
// (which need a positive definite operator and preconditioner).
void refuseUnsound(const SolverOptions& options, bool indefinite);
// PRE_COND='LDLT_SP' / 'LDLT_DP': MUMPS factors of the scaled matrix, applied once per iteration.
bool usesFactors(const SolverOptions& options);
// PRE_COND='GAMG' / 'BOOMER' / 'ML': algebraic multigrid (the piece basis on X-FEM models).
bool isMultigrid(const SolverOptions& options);
SolverOptions factorOptions(const SolverOptions& options);
// Method, tolerances (RESI_RELA on the unpreconditioned residual, NMAX_ITER), preconditioning side.
void configureKrylov(KSP ksp, const SolverOptions& options);
// PETSc's own preconditioners: SANS, JACOBI, SOR, LDLT_INC (ICC with NIVE_REMPLISSAGE levels),
// GAMG, BOOMER (hypre's BoomerAMG), ML. `inPieces`: the Krylov operator is the piece basis's shell and
// the preconditioner matrix its assembled copy (PetscSolver.cpp).
void configurePreconditioner(PC pc, const SolverOptions& options, bool inPieces);
// miniaster's defaults, then OPTION_PETSC, into the options database, read by the KSP, its PC and the
// PC's inner solvers while they are built (KSPSetUp), then cleared (a later solve starts from the
// SOLVEUR keywords again); the options the solver did not use are logged.
void setUpWithOptionPetsc(KSP ksp, const SolverOptions& options, bool inPieces);

// ML in the piece basis: its smoothers then sweep their matrices' upper triangles, where PETSc
// estimates their largest eigenvalue again (SymmetricSmoother.hpp), so the set-up's own estimates
// are made with one GMRES step and only the second with PETSc's 10 (kSmootherEstimateSteps). Not
// when OPTION_PETSC says anything of the estimates: PETSc's are then left as they are.
bool estimatesAfterSetUp(const SolverOptions& options, bool inPieces);
constexpr int kSmootherEstimateSteps = 10;  // PETSc's default for Chebyshev's estimate

// What to try when the method stalls (or converged by its own estimate only: `inaccurate`), for the
// error message.
std::string stallAdvice(const SolverOptions& options, bool inaccurate);

}  // namespace ma
