// SOLVEUR of MUMPS beyond the defaults (docs/fe.md, "Linear solvers"): MIXER_PRECISION (single-
// precision factors refined against the double matrix), RESI_RELA, FILTRAGE_MATRICE and
// GESTION_MEMOIRE, on small systems with known solutions.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "core/Mpi.hpp"
#include "csr_test_support.hpp"
#include "solver/LinearSolver.hpp"

using namespace ma;
using ma::test::Solved;
using ma::test::solveKnown;

namespace {

// k x k 5-point Laplacian (Dirichlet around), plus `weak` x the couplings (a, a + 2) when weak > 0,
// plus one multiplier tying each pair (2r, 2r + 1) of the first `multipliers` pairs.
CsrMatrix laplacian2d(int k, double weak = 0.0, int multipliers = 0) {
    const int n = k * k;
    std::vector<std::vector<std::pair<int, double>>> rows(static_cast<size_t>(n + multipliers));
    auto add = [&](int i, int j, double v) { rows[size_t(i)].push_back({j, v}); };
    for (int a = 0; a < n; ++a) {
        add(a, a, 4.0 + 4.0 * weak);
        if ((a % k) + 1 < k) add(a, a + 1, -1.0), add(a + 1, a, -1.0);
        if (a + k < n) add(a, a + k, -1.0), add(a + k, a, -1.0);
        if (weak > 0.0 && a + 2 < n) add(a, a + 2, -weak), add(a + 2, a, -weak);
    }
    for (int r = 0; r < multipliers; ++r)
        for (auto [node, c] : {std::pair{2 * r, 1.0}, std::pair{2 * r + 1, -1.0}})
            add(n + r, node, c), add(node, n + r, c);
    return ma::test::fromRows(std::move(rows));
}

// 1D Laplacian with Dirichlet ends: condition number ~ 4 n^2 / pi^2 (4e9 at n = 1e5).
CsrMatrix laplacian1d(int n) {
    std::vector<std::vector<std::pair<int, double>>> rows(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        rows[size_t(i)].push_back({i, 2.0});
        if (i + 1 < n) rows[size_t(i)].push_back({i + 1, -1.0}), rows[size_t(i + 1)].push_back({i, -1.0});
    }
    return ma::test::fromRows(std::move(rows));
}

SolverOptions mixed() {
    SolverOptions o;
    o.mixedPrecision = true;
    return o;
}

}  // namespace

TEST(SolverMixedPrecision, SingleFactorsRefinedToDoubleAccuracy) {
    msg().setEcho(false);
    const CsrMatrix A = laplacian2d(40);
    const Solved s = solveKnown(A, mixed(), MatrixKind::SymmetricPositiveDefinite);
    EXPECT_LT(s.error, 1e-12) << s.mess;
    EXPECT_LT(s.residual, 1e-15) << s.mess;
    EXPECT_NE(s.mess.find("MUMPS (single-precision factors) solve"), std::string::npos) << s.mess;
    // A single-precision solve alone leaves ~1e-7: at least two steps were needed.
    EXPECT_NE(s.mess.find("refinement step(s) (before: "), std::string::npos) << s.mess;
    const Solved d = solveKnown(A, SolverOptions{}, MatrixKind::SymmetricPositiveDefinite);
    EXPECT_LT(std::abs(s.error - d.error), 1e-12);
}

TEST(SolverMixedPrecision, SaddlePointWithMultipliers) {
    msg().setEcho(false);
    const CsrMatrix A = laplacian2d(30, 0.0, 100);
    const Solved s = solveKnown(A, mixed(), MatrixKind::SymmetricIndefinite);
    EXPECT_LT(s.error, 1e-12) << s.mess;
    EXPECT_NE(s.mess.find("MUMPS: 100 negative pivots"), std::string::npos) << s.mess;
}

TEST(SolverMixedPrecision, RefinementThatCannotConvergeIsAnErrorNamingTheSolver) {
    msg().setEcho(false);
    // cond ~ 4e9: single-precision factors (eps 6e-8) cannot be refined to a double answer.
    const CsrMatrix A = laplacian1d(100000);
    try {
        solveKnown(A, mixed(), MatrixKind::SymmetricPositiveDefinite);
        FAIL() << "an unconverged refinement gave an answer";
    } catch (const NumericalError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("linear solver MUMPS (single-precision factors)"), std::string::npos) << what;
        EXPECT_NE(what.find("MIXER_PRECISION='NON'"), std::string::npos) << what;
    }
    // The same system in double precision: solved (cond * 1e-16 ~ 1e-6 of forward error).
    const Solved d = solveKnown(A, SolverOptions{}, MatrixKind::SymmetricPositiveDefinite);
    EXPECT_LT(d.residual, 1e-12);
}

TEST(SolverMixedPrecision, ResiRelaIsMetOrTheSolveIsAnError) {
    msg().setEcho(false);
    const CsrMatrix A = laplacian2d(20);
    SolverOptions o = mixed();
    o.resiRela = 1e-10;
    EXPECT_LT(solveKnown(A, o, MatrixKind::SymmetricPositiveDefinite).residual, 1e-10);
    // No solve in double reaches 1e-300: the check is an error naming the solver, not an alarm.
    SolverOptions strict;
    strict.resiRela = 1e-300;
    try {
        solveKnown(A, strict, MatrixKind::SymmetricPositiveDefinite);
        FAIL() << "RESI_RELA not checked";
    } catch (const NumericalError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("linear solver MUMPS: the relative residual"), std::string::npos) << what;
        EXPECT_NE(what.find("SOLVEUR/RESI_RELA = 1e-300"), std::string::npos) << what;
    }
}

TEST(SolverMixedPrecision, FiltrageMatriceLeavesWeakCouplingsOutAndTheRefinementRestoresThem) {
    msg().setEcho(false);
    const int k = 30, n = k * k;
    const CsrMatrix A = laplacian2d(k, 1e-8);
    for (bool single : {false, true}) {
        SolverOptions o;
        o.mixedPrecision = single;
        o.matrixFilter = 1e-6;
        const Solved s = solveKnown(A, o, MatrixKind::SymmetricPositiveDefinite);
        // Upper triangle: n diagonal, 2 k (k - 1) neighbours, n - 2 weak couplings left out.
        const long long kept = n + 2LL * k * (k - 1), all = kept + n - 2;
        EXPECT_NE(s.mess.find(fmt::format("FILTRAGE_MATRICE=1e-06: {} of the {} entries", kept, all)),
                  std::string::npos)
            << s.mess;
        EXPECT_LT(s.error, 1e-12) << s.mess;
        EXPECT_LT(s.residual, 1e-15) << s.mess;
    }
}

TEST(SolverMixedPrecision, OutOfCoreFactorsOnDiskSameAnswer) {
    msg().setEcho(false);
    mpi::initialise();  // before TMPDIR changes: OpenMPI keeps its session folder in the TMPDIR of MPI_Init
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "miniaster_ooc_test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const char* before = std::getenv("TMPDIR");
    const std::string saved = before ? before : "";
    setenv("TMPDIR", dir.c_str(), 1);
    const CsrMatrix A = laplacian2d(40);
    SolverOptions o;
    o.memory = "OUT_OF_CORE";
    const Solved s = solveKnown(A, o, MatrixKind::SymmetricPositiveDefinite);
    if (before) setenv("TMPDIR", saved.c_str(), 1);
    else unsetenv("TMPDIR");
    EXPECT_LT(s.error, 1e-12) << s.mess;
    EXPECT_NE(s.mess.find("MUMPS out of core (ICNTL(22)=1): factors written under " + dir.string()), std::string::npos)
        << s.mess;
    // MUMPS removes its factor files when the instance ends.
    std::string left;
    for (const auto& e : std::filesystem::directory_iterator(dir)) left += " " + e.path().filename().string();
    EXPECT_TRUE(left.empty()) << "left in " << dir << ":" << left;
    std::filesystem::remove_all(dir);
}

TEST(SolverMixedPrecision, GestionMemoireEvalGivesTheEstimatesThenStops) {
    msg().setEcho(false);
    const CsrMatrix A = laplacian2d(20);
    SolverOptions o;
    o.memory = "EVAL";
    const size_t from = msg().messText().size();
    auto solver = makeLinearSolver(o);
    try {
        solver->factorize(A, MatrixKind::SymmetricPositiveDefinite);
        FAIL() << "EVAL factorised";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("GESTION_MEMOIRE='EVAL'"), std::string::npos) << e.what();
    }
    const std::string evalText = msg().messText().substr(from);
    EXPECT_NE(evalText.find("MB in core (INFOG(17))"), std::string::npos);
    // The analysis' prediction is given too, the same as a run that factorises prints.
    const std::regex predicted(R"(([0-9.]+e[+-][0-9]+) (flops )?\(RINFOG\(1\)\))");
    std::smatch evalFlops, runFlops;
    ASSERT_TRUE(std::regex_search(evalText, evalFlops, predicted)) << evalText;
    o.memory = "AUTO";
    const size_t runFrom = msg().messText().size();
    makeLinearSolver(o)->factorize(A, MatrixKind::SymmetricPositiveDefinite);
    const std::string runText = msg().messText().substr(runFrom);
    ASSERT_TRUE(std::regex_search(runText, runFlops, predicted)) << runText;
    EXPECT_GT(std::stod(evalFlops[1]), 0.0);
    EXPECT_EQ(evalFlops[1].str(), runFlops[1].str());
}
