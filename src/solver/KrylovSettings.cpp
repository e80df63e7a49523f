#include "solver/KrylovSettings.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <sstream>
#include <vector>

#include "core/Error.hpp"
#include "core/Messages.hpp"

namespace ma {

namespace {

bool isOneOf(const std::string& value, std::initializer_list<const char*> values) {
    return std::any_of(values.begin(), values.end(), [&](const char* v) { return value == v; });
}

// Algebraic multigrid, for elasticity without multipliers: the order the failure advice names them in.
constexpr std::array<const char*, 3> kMultigrid{"GAMG", "BOOMER", "ML"};

}  // namespace

void checkPetsc(PetscErrorCode code, const char* call) {
    if (code != 0) throw NumericalError(fmt::format("PETSc: {} failed (PETSc error code {})", call, int(code)));
}

std::string krylovAlgorithm(const SolverOptions& options) {
    return options.method == "GCPC" ? "CG" : options.algorithm;
}

bool usesFactors(const SolverOptions& options) { return isOneOf(options.preconditioner, {"LDLT_SP", "LDLT_DP"}); }

bool isMultigrid(const SolverOptions& options) {
    return std::find(kMultigrid.begin(), kMultigrid.end(), options.preconditioner) != kMultigrid.end();
}

void refuseUnsound(const SolverOptions& options, bool indefinite) {
    const std::string& pc = options.preconditioner;
    const std::string algorithm = krylovAlgorithm(options);
    if (isOneOf(pc, {"BLOC_LAGR", "FIELDSPLIT"}))
        throw NotImplemented(
            "SOLVEUR/PRE_COND='" + pc +
            "': the block preconditioners of the multipliers are not available; use PRE_COND='LDLT_SP' "
            "(docs/solver.md)");
    if (algorithm == "GMRES_LMP")
        throw NotImplemented(
            "SOLVEUR/ALGORITHME='GMRES_LMP': the limited-memory preconditioner update is not available; use "
            "'FGMRES' (REAC_PRECOND keeps the LDLT_SP factors between matrices)");
    if (!indefinite) return;
    if (!usesFactors(options))
        throw UserError(fmt::format(
            "SOLVEUR/METHODE='{}', PRE_COND='{}' cannot converge on this system: its Lagrange multipliers or contact "
            "unknowns make it a saddle point with zero diagonal entries, which {} ; use PRE_COND='LDLT_SP' (MUMPS "
            "single-precision factors as preconditioner, docs/solver.md) or METHODE='MUMPS'",
            options.method, pc,
            isOneOf(pc, {"JACOBI", "SOR", "LDLT_INC"}) ? "this preconditioner divides by"
            : pc == "SANS"                             ? "an unpreconditioned Krylov method cannot handle"
                                                       : "algebraic multigrid cannot coarsen"));
    if (isOneOf(algorithm, {"CG", "CR"}))
        throw UserError(fmt::format(
            "SOLVEUR/{} cannot converge on this system: {} needs a positive definite matrix and preconditioner, and "
            "its Lagrange multipliers or contact unknowns make it indefinite; use METHODE='PETSC' with "
            "ALGORITHME='FGMRES' (or 'GMRES', 'GCR') and PRE_COND='LDLT_SP'",
            options.method == "GCPC" ? "METHODE='GCPC'" : "ALGORITHME='" + algorithm + "'", algorithm));
}

SolverOptions factorOptions(const SolverOptions& options) {
    SolverOptions f;
    f.method = "MUMPS";
    f.mixedPrecision = options.preconditioner == "LDLT_SP";
    f.diagonalScaling = options.diagonalScaling;  // factors of S A S from A, S as the Krylov operator's
    f.distributed = options.distributed;          // MUMPS on the processes' parts
    f.wholePattern = options.wholePattern;
    f.maxRefinementSteps = 0;
    f.resiRela = -1.0;
    f.pcentPivot = options.pcentPivot;
    f.nprec = options.nprec;
    f.info = options.info;
    f.threads = options.threads;
    f.singularHint = options.singularHint;
    return f;
}

void configureKrylov(KSP ksp, const SolverOptions& options) {
    const std::string algorithm = krylovAlgorithm(options);
    const KSPType type = algorithm == "CG"      ? KSPCG
                         : algorithm == "CR"    ? KSPCR
                         : algorithm == "GMRES" ? KSPGMRES
                         : algorithm == "GCR"   ? KSPGCR
                                                : KSPFGMRES;
    checkPetsc(KSPSetType(ksp, type), "KSPSetType");
    // code_aster's criterion: ||b - A x|| <= RESI_RELA ||b||, the unpreconditioned residual. CG
    // computes it with a left preconditioner; GMRES gets it from right preconditioning; FGMRES and GCR
    // are right-preconditioned. PETSc's CR iterates on the preconditioned norm only (with the other one
    // it stalls at once): the true residual is checked after every solve (PetscSolver.cpp).
    if (algorithm == "GMRES") checkPetsc(KSPSetPCSide(ksp, PC_RIGHT), "KSPSetPCSide");
    if (algorithm == "CG") checkPetsc(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
    const PetscInt maxIterations = options.maxIterations > 0 ? PetscInt(options.maxIterations) : PETSC_DEFAULT;
    checkPetsc(KSPSetTolerances(ksp, options.resiRela, PETSC_DEFAULT, PETSC_DEFAULT, maxIterations),
               "KSPSetTolerances");
}

void configurePreconditioner(PC pc, const SolverOptions& options, bool inPieces) {
    const std::string& p = options.preconditioner;
    if (p == "SANS") checkPetsc(PCSetType(pc, PCNONE), "PCSetType");
    else if (p == "JACOBI") checkPetsc(PCSetType(pc, PCJACOBI), "PCSetType");
    else if (p == "SOR") checkPetsc(PCSetType(pc, PCSOR), "PCSetType");  // symmetric sweeps: fit for CG
    else if (p == "GAMG") checkPetsc(PCSetType(pc, PCGAMG), "PCSetType");
    else if (p == "ML") checkPetsc(PCSetType(pc, PCML), "PCSetType");
    else if (p == "BOOMER") {
        checkPetsc(PCSetType(pc, PCHYPRE), "PCSetType");
        checkPetsc(PCHYPRESetType(pc, "boomeramg"), "PCHYPRESetType");
    } else if (p == "LDLT_INC") {
        checkPetsc(PCSetType(pc, PCICC), "PCSetType");
        checkPetsc(PCFactorSetLevels(pc, PetscInt(options.fillLevel)), "PCFactorSetLevels");
    } else {
        throw InternalError("SOLVEUR/PRE_COND='" + p + "' reached the PETSc setup");
    }
    // In the piece basis GAMG's and ML's smoothers and residuals multiply by the assembled S T^T K T S
    // instead of the shell (a product with K, twice as many non-zeros, and with T): the preconditioner
    // stays a fixed symmetric positive definite operator; only the Krylov method needs the true one.
    // OPTION_PETSC='-pc_use_amat true' asks for the shell.
    if (inPieces && (p == "GAMG" || p == "ML")) checkPetsc(PCSetUseAmat(pc, PETSC_FALSE), "PCSetUseAmat");
}

namespace {

// miniaster's defaults for PETSc's multigrid preconditioners, in the options database before
// OPTION_PETSC (which overrides them). ML: code_aster's aggregation (Uncoupled, also PETSc's) and
// Chebyshev over SOR sweeps per level instead of Richardson over 2: 4 steps on the flat cells of
// ssnv511c's box (half the iterations, less time), 2 in the piece basis, where each step costs more
// than the iterations it saves. In the piece basis, W-cycles: its coarse levels are light (operator
// complexity ~1.2), and visiting them twice is what flat cells need (a third fewer iterations there,
// the same on cubes); and the coarsening stops below 2 000 rows, whose LU (on every process) is a
// better coarse correction than W-cycles down to a few dozen rows, each visit an exchange between
// the processes (ssnv511c at N = 49: 46 -> 40 iterations). GAMG keeps PETSc's Chebyshev/Jacobi:
// SOR halves its iterations there but fails on the zero pivots of coarse levels with more rigid
// modes than rows in an aggregate (N = 31). docs/solver.md, "3D multigrid", "The finest smoother",
// "W-cycles" and "The coarsest level by LU".
const char* defaultOptionsOf(const std::string& preconditioner, bool inPieces) {
    if (preconditioner == "ML")
        return inPieces ? "-pc_ml_CoarsenScheme Uncoupled -mg_levels_ksp_type chebyshev -mg_levels_ksp_max_it 2 "
                          "-pc_mg_cycle_type w -pc_ml_maxCoarseSize 2000"
                        : "-pc_ml_CoarsenScheme Uncoupled -mg_levels_ksp_type chebyshev -mg_levels_ksp_max_it 4";
    return "";
}

// Options left unused among those OPTION_PETSC gave (the defaults a solver does not read are not
// counted).
int unusedGiven(const std::string& defaults, const std::string& given) {
    PetscInt unused = 0;
    PetscOptionsAllUsed(nullptr, &unused);
    std::istringstream words(defaults);
    for (std::string word; words >> word;) {
        if (word.size() < 2 || word[0] != '-' || std::isdigit(static_cast<unsigned char>(word[1])) ||
            given.find(word) != std::string::npos)
            continue;
        PetscBool used = PETSC_TRUE;
        PetscOptionsUsed(nullptr, word.c_str(), &used);
        if (!used) --unused;
    }
    return int(std::max<PetscInt>(unused, 0));
}

}  // namespace

void setUpWithOptionPetsc(KSP ksp, const SolverOptions& options, bool inPieces) {
    const std::string defaults = defaultOptionsOf(options.preconditioner, inPieces);
    const std::string setUpOnly = estimatesAfterSetUp(options, inPieces) ? " -mg_levels_esteig_ksp_max_it 1" : "";
    checkPetsc(PetscOptionsInsertString(nullptr, (defaults + setUpOnly).c_str()),
               "PetscOptionsInsertString (defaults)");
    checkPetsc(PetscOptionsInsertString(nullptr, options.petscOptions.c_str()),
               "PetscOptionsInsertString (SOLVEUR/OPTION_PETSC)");
    // The options stay in PETSc's database through KSPSetUp: multigrid creates its levels' smoothers
    // there and reads their options (-mg_levels_*, -mg_coarse_*) only then.
    PetscErrorCode code = KSPSetFromOptions(ksp);
    if (code == 0) code = KSPSetUp(ksp);
    const int unused = unusedGiven(defaults + setUpOnly, options.petscOptions);
    checkPetsc(PetscOptionsClear(nullptr), "PetscOptionsClear");
    checkPetsc(PetscOptionsSetValue(nullptr, "-no_signal_handler", "true"), "PetscOptionsSetValue");
    PetscBool set = PETSC_FALSE;  // marks it used: the next solve counts only its own unused options
    checkPetsc(PetscOptionsHasName(nullptr, nullptr, "-no_signal_handler", &set), "PetscOptionsHasName");
    checkPetsc(code, options.petscOptions.empty() ? "KSPSetUp (the preconditioner's construction)"
                                                  : "KSPSetFromOptions / KSPSetUp (SOLVEUR/OPTION_PETSC)");
    if (!defaults.empty()) msg().infof("    PRE_COND='{}': miniaster's options {}", options.preconditioner, defaults);
    if (!options.petscOptions.empty())
        msg().infof("    OPTION_PETSC='{}' given to PETSc{}", options.petscOptions,
                    unused > 0 ? fmt::format(" ({} option(s) not used by this solver)", unused) : "");
}

bool estimatesAfterSetUp(const SolverOptions& options, bool inPieces) {
    return inPieces && options.preconditioner == "ML" && options.petscOptions.find("esteig") == std::string::npos;
}

namespace {

// The preconditioners worth trying after `current` failed, in the order to try them.
std::string strongerPreconditioners(const std::string& current) {
    std::vector<std::string> multigrid;
    for (const char* name : kMultigrid)
        if (current != name) multigrid.push_back(fmt::format("'{}'", name));
    return fmt::format("PRE_COND='LDLT_SP', or {} for elasticity without multipliers", fmt::join(multigrid, " / "));
}

}  // namespace

std::string stallAdvice(const SolverOptions& options, bool inaccurate) {
    if (inaccurate && options.preconditioner == "LDLT_SP")
        return "With single-precision factors the method's own residual is not the true one (GMRES rebuilds the "
               "solution through factors that are not exactly linear, CR measures the preconditioned residual): use "
               "ALGORITHME='FGMRES' (code_aster's default) or 'GCR', which keep the preconditioned vectors.";
    if (usesFactors(options))
        return "The factors of the preconditioner do not approximate the matrix well enough: use PRE_COND='LDLT_DP' "
               "or METHODE='MUMPS'.";
    const std::string stronger = strongerPreconditioners(options.preconditioner);
    if (inaccurate)
        return "The method's own residual drifted from the true one over its iterations (rounding in its "
               "recurrences): use a preconditioner that needs fewer iterations (" +
               stronger + "), or a larger RESI_RELA.";
    return "Raise NMAX_ITER, or use a stronger preconditioner (" + stronger + ").";
}

}  // namespace ma
