// SOLVEUR METHODE='PETSC' / 'GCPC' (docs/solver.md) on small systems with known solutions: every
// ALGORITHME with the preconditioners that serve it, the saddle point with LDLT_SP, the refused
// combinations, a stalled method as an error naming the solver, REAC_PRECOND, OPTION_PETSC.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "csr_test_support.hpp"
#include "solver/LinearSolver.hpp"

using namespace ma;
using ma::test::Solved;
using ma::test::solveKnown;

namespace {

// k x k 5-point Laplacian (Dirichlet around) times `factor`, plus one multiplier tying each pair
// (2r, 2r + 1) of the first `multipliers` pairs.
CsrMatrix laplacian2d(int k, int multipliers = 0, double factor = 1.0) {
    const int n = k * k;
    std::vector<std::vector<std::pair<int, double>>> rows(static_cast<size_t>(n + multipliers));
    auto add = [&](int i, int j, double v) { rows[size_t(i)].push_back({j, v}); };
    for (int a = 0; a < n; ++a) {
        add(a, a, 4.0 * factor);
        if ((a % k) + 1 < k) add(a, a + 1, -factor), add(a + 1, a, -factor);
        if (a + k < n) add(a, a + k, -factor), add(a + k, a, -factor);
    }
    for (int r = 0; r < multipliers; ++r)
        for (auto [node, c] : {std::pair{2 * r, 1.0}, std::pair{2 * r + 1, -1.0}})
            add(n + r, node, c), add(node, n + r, c);
    return ma::test::fromRows(std::move(rows));
}

SolverOptions krylov(const std::string& method, const std::string& algorithm, const std::string& pc,
                     double resiRela = 1e-10) {
    SolverOptions o;
    o.method = method;
    o.algorithm = algorithm;
    o.preconditioner = pc;
    o.resiRela = resiRela;
    return o;
}

int iterationsIn(const std::string& mess) {
    const auto at = mess.find(" iterations, ");
    if (at == std::string::npos) return -1;
    const auto start = mess.rfind(' ', at - 1);
    return std::stoi(mess.substr(start + 1, at - start - 1));
}

}  // namespace

TEST(SolverKrylov, EveryAlgorithmWithEveryPreconditionerOnAnSpdSystem) {
    msg().setEcho(false);
    const CsrMatrix A = laplacian2d(30);
    for (const char* algorithm : {"CG", "CR", "GMRES", "GCR", "FGMRES"})
        for (const char* pc : {"LDLT_SP", "LDLT_DP", "GAMG", "BOOMER", "ML", "JACOBI", "SOR", "SANS", "LDLT_INC"}) {
            SCOPED_TRACE(fmt::format("{} {}", algorithm, pc));
            SolverOptions o = krylov("PETSC", algorithm, pc);
            o.maxIterations = 2000;
            if (std::string(pc) == "LDLT_SP" && (std::string(algorithm) == "GMRES" || std::string(algorithm) == "CR")) {
                // Their own residual is not the true one with single-precision factors: an error that
                // says so, never the 1e-7 answer.
                try {
                    solveKnown(A, o, MatrixKind::SymmetricPositiveDefinite);
                    ADD_FAILURE() << "an inaccurate answer was given";
                } catch (const NumericalError& e) {
                    EXPECT_NE(std::string(e.what()).find("but the true relative residual"), std::string::npos);
                    EXPECT_NE(std::string(e.what()).find("use ALGORITHME='FGMRES'"), std::string::npos);
                }
                continue;
            }
            const Solved s = solveKnown(A, o, MatrixKind::SymmetricPositiveDefinite);
            EXPECT_LT(s.residual, 1e-9) << s.mess;
            EXPECT_LT(s.error, 1e-6) << s.mess;
            EXPECT_NE(s.mess.find(fmt::format("PETSC (ALGORITHME='{}', PRE_COND='{}') solve", algorithm, pc)),
                      std::string::npos)
                << s.mess;
            EXPECT_NE(s.mess.find("preconditioner built in"), std::string::npos) << s.mess;
        }
}

TEST(SolverKrylov, FactorPreconditionersConvergeInAFewIterations) {
    msg().setEcho(false);
    const CsrMatrix A = laplacian2d(40);
    const Solved sp = solveKnown(A, krylov("PETSC", "FGMRES", "LDLT_SP", 1e-12), MatrixKind::SymmetricPositiveDefinite);
    const Solved dp = solveKnown(A, krylov("PETSC", "FGMRES", "LDLT_DP", 1e-12), MatrixKind::SymmetricPositiveDefinite);
    // Single factors: each iteration gains ~ -log10(cond * 6e-8) digits; double factors: one or two.
    EXPECT_LE(iterationsIn(sp.mess), 6) << sp.mess;
    EXPECT_LE(iterationsIn(dp.mess), 2) << dp.mess;
    EXPECT_NE(sp.mess.find("applications of the LDLT_SP factors"), std::string::npos) << sp.mess;
    EXPECT_LT(sp.error, 1e-9);
    EXPECT_LT(dp.error, 1e-9);
}

TEST(SolverKrylov, GcpcIsPreconditionedConjugateGradients) {
    msg().setEcho(false);
    const CsrMatrix A = laplacian2d(30);
    for (const char* pc : {"LDLT_INC", "LDLT_SP", "LDLT_DP"}) {
        const Solved s = solveKnown(A, krylov("GCPC", "", pc), MatrixKind::SymmetricPositiveDefinite);
        EXPECT_NE(s.mess.find(fmt::format("GCPC (ALGORITHME='CG', PRE_COND='{}') solve", pc)), std::string::npos)
            << s.mess;
        EXPECT_LT(s.error, 1e-7) << s.mess;
    }
}

TEST(SolverKrylov, SaddlePointWithLdltSpAndTheRefusedCombinations) {
    msg().setEcho(false);
    const CsrMatrix A = laplacian2d(20, 50);
    for (auto [algorithm, pc] : {std::pair{"GCR", "LDLT_SP"}, std::pair{"FGMRES", "LDLT_SP"},
                                 std::pair{"GMRES", "LDLT_DP"}, std::pair{"FGMRES", "LDLT_DP"}}) {
        const Solved s = solveKnown(A, krylov("PETSC", algorithm, pc, 1e-12), MatrixKind::SymmetricIndefinite);
        EXPECT_LT(s.error, 1e-9) << s.mess;
    }
    for (const char* pc : {"GAMG", "BOOMER", "ML", "JACOBI", "SOR", "SANS", "LDLT_INC"}) {
        try {
            solveKnown(A, krylov("PETSC", "FGMRES", pc), MatrixKind::SymmetricIndefinite);
            ADD_FAILURE() << pc << " accepted on a saddle point";
        } catch (const UserError& e) {
            EXPECT_NE(std::string(e.what()).find("cannot converge on this system"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("PRE_COND='LDLT_SP'"), std::string::npos) << e.what();
        }
    }
    for (const char* algorithm : {"CG", "CR"}) {
        EXPECT_THROW(solveKnown(A, krylov("PETSC", algorithm, "LDLT_SP"), MatrixKind::SymmetricIndefinite), UserError);
    }
    EXPECT_THROW(solveKnown(A, krylov("GCPC", "", "LDLT_SP"), MatrixKind::SymmetricIndefinite), UserError);
    EXPECT_THROW(makeLinearSolver(krylov("PETSC", "FGMRES", "FIELDSPLIT")), NotImplemented);
}

TEST(SolverKrylov, AStalledMethodIsAnErrorNamingTheSolver) {
    msg().setEcho(false);
    const CsrMatrix A = laplacian2d(40);
    SolverOptions o = krylov("PETSC", "CG", "SANS", 1e-12);
    o.maxIterations = 5;
    try {
        solveKnown(A, o, MatrixKind::SymmetricPositiveDefinite);
        FAIL() << "five unpreconditioned CG iterations met 1e-12";
    } catch (const NumericalError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("linear solver PETSC (ALGORITHME='CG', PRE_COND='SANS') did not converge"),
                  std::string::npos)
            << what;
        EXPECT_NE(what.find("DIVERGED_ITS after 5 iterations"), std::string::npos) << what;
    }
}

// The advice after a failure names other preconditioners than the one that failed. Out of iterations:
// raise NMAX_ITER. A residual that drifted from the true one (RESI_RELA=1e-20: CG's own estimate goes on
// falling, the true residual stays at round-off) is not cured by more iterations.
TEST(SolverKrylov, TheAdviceAfterAFailureNamesOtherPreconditioners) {
    msg().setEcho(false);
    const CsrMatrix A = laplacian2d(40);
    for (const char* pc : {"GAMG", "ML"}) {
        for (bool drifted : {false, true}) {
            SolverOptions o = krylov("PETSC", "CG", pc, drifted ? 1e-20 : 1e-12);
            if (!drifted) o.maxIterations = 2;
            try {
                solveKnown(A, o, MatrixKind::SymmetricPositiveDefinite);
                ADD_FAILURE() << pc << (drifted ? " met RESI_RELA=1e-20" : " met 1e-12 in 2 iterations");
            } catch (const NumericalError& e) {
                const std::string what = e.what();
                EXPECT_EQ(what.find(fmt::format("or '{}'", pc)), std::string::npos) << what;
                EXPECT_EQ(what.find(fmt::format("/ '{}'", pc)), std::string::npos) << what;
                EXPECT_NE(what.find("PRE_COND='LDLT_SP'"), std::string::npos) << what;
                EXPECT_EQ(what.find("Raise NMAX_ITER") == std::string::npos, drifted) << what;
                EXPECT_EQ(what.find("converged by its own residual estimate") != std::string::npos, drifted) << what;
                EXPECT_EQ(what.find("drifted from the true one") != std::string::npos, drifted) << what;
            }
        }
    }
}

TEST(SolverKrylov, ReacPrecondKeepsTheFactorsForTheNextMatrix) {
    msg().setEcho(false);
    const CsrMatrix A = laplacian2d(30), B = laplacian2d(30, 0, 1.01);
    SolverOptions o = krylov("PETSC", "FGMRES", "LDLT_SP", 1e-12);
    auto solver = makeLinearSolver(o);
    std::vector<double> b(size_t(A.rows), 1.0);
    const size_t from = msg().messText().size();
    solver->factorize(A, MatrixKind::SymmetricPositiveDefinite);
    solver->solve(b);
    solver->factorize(B, MatrixKind::SymmetricPositiveDefinite);
    std::vector<double> x(size_t(B.rows), 1.0), bx(size_t(B.rows));
    B.multiply(x, bx);
    EXPECT_LT(solver->solve(bx), 1e-11);
    for (double v : bx) EXPECT_NEAR(v, 1.0, 1e-9);
    const std::string mess = msg().messText().substr(from);
    EXPECT_NE(mess.find("preconditioner kept from the previous matrix"), std::string::npos) << mess;
    EXPECT_EQ(mess.find("preconditioner built in"), mess.rfind("preconditioner built in")) << mess;
}

TEST(SolverKrylov, OptionPetscReachesPetsc) {
    msg().setEcho(false);
    const CsrMatrix A = laplacian2d(30);
    SolverOptions o = krylov("PETSC", "GMRES", "JACOBI", 1e-10);
    o.petscOptions = "-ksp_gmres_restart 5 -not_an_option 3";
    const Solved s = solveKnown(A, o, MatrixKind::SymmetricPositiveDefinite);
    EXPECT_NE(s.mess.find("OPTION_PETSC='-ksp_gmres_restart 5 -not_an_option 3' given to PETSc (1 option(s) not used"),
              std::string::npos)
        << s.mess;
    EXPECT_LT(s.error, 1e-6);
}

// Multigrid builds its levels' smoothers in KSPSetUp and reads their options there: a smoother given
// through OPTION_PETSC changes the iterations (more sweeps: fewer iterations), and is not counted as
// unused. PRE_COND='ML' says its own defaults in the .mess.
TEST(SolverKrylov, OptionPetscReachesTheMultigridLevels) {
    msg().setEcho(false);
    const CsrMatrix A = laplacian2d(40);
    for (const char* pc : {"GAMG", "ML"}) {
        SolverOptions o = krylov("PETSC", "CG", pc, 1e-10);
        o.petscOptions = "-mg_levels_ksp_max_it 1";
        const Solved one = solveKnown(A, o, MatrixKind::SymmetricPositiveDefinite);
        o.petscOptions = "-mg_levels_ksp_max_it 8";
        const Solved eight = solveKnown(A, o, MatrixKind::SymmetricPositiveDefinite);
        EXPECT_LT(iterationsIn(eight.mess), iterationsIn(one.mess)) << one.mess << eight.mess;
        EXPECT_EQ(eight.mess.find("not used"), std::string::npos) << eight.mess;
        EXPECT_LT(one.error, 1e-6);
        EXPECT_LT(eight.error, 1e-6);
    }
    const Solved ml = solveKnown(A, krylov("PETSC", "CG", "ML", 1e-10), MatrixKind::SymmetricPositiveDefinite);
    EXPECT_NE(ml.mess.find("PRE_COND='ML': miniaster's options -pc_ml_CoarsenScheme Uncoupled -mg_levels_ksp_type "
                           "chebyshev -mg_levels_ksp_max_it 4"),
              std::string::npos)
        << ml.mess;
}
