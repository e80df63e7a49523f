// MUMPS's workspace retry: when the factorisation needs more real workspace than the analysis
// estimated (delayed pivots of a saddle-point system), JOB=2 runs again with a larger ICNTL(14),
// the analysis kept, and the answer is the same as without the retry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/Messages.hpp"
#include "csr_test_support.hpp"
#include "solver/LinearSolver.hpp"

using namespace ma;

namespace {

// k x k 5-point Laplacian, plus one Lagrange multiplier per pair of nodes (2a, 2a+1) tying their
// values: zero-diagonal rows whose pivots METIS's order (blind to them) delays.
CsrMatrix saddlePoint(int k) {
    const int n = k * k;
    std::vector<std::vector<std::pair<int, double>>> rows(size_t(n + n / 2));
    auto add = [&](int i, int j, double v) { rows[i].push_back({j, v}); };
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
            const int a = i * k + j;
            add(a, a, 4.0);
            if (j + 1 < k) add(a, a + 1, -1.0), add(a + 1, a, -1.0);
            if (i + 1 < k) add(a, a + k, -1.0), add(a + k, a, -1.0);
        }
    for (int r = 0; 2 * r + 1 < n; ++r)
        for (auto [node, c] : {std::pair{2 * r, 1.0}, std::pair{2 * r + 1, -1.0}})
            add(n + r, node, c), add(node, n + r, c);
    return ma::test::fromRows(std::move(rows));
}

// Solves A x = A x0 with PCENT_PIVOT `relaxation`; returns max |x - x0| and the .mess it wrote.
std::pair<double, std::string> solveWithRelaxation(const CsrMatrix& A, int relaxation) {
    const size_t from = msg().messText().size();
    SolverOptions o;
    o.renum = "METIS";
    o.pcentPivot = relaxation;
    auto solver = makeLinearSolver(o);
    solver->factorize(A, MatrixKind::SymmetricIndefinite);
    std::vector<double> x0(A.rows), b(A.rows);
    for (int i = 0; i < A.rows; ++i) x0[i] = std::cos(0.1 * i);
    A.multiply(x0, b);
    solver->solve(b);
    double error = 0.0;
    for (int i = 0; i < A.rows; ++i) error = std::max(error, std::abs(b[i] - x0[i]));
    return {error, msg().messText().substr(from)};
}

size_t occurrences(const std::string& text, const std::string& what) {
    size_t count = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++count;
    return count;
}

}  // namespace

TEST(SolverWorkspace, TooSmallWorkspaceRefactorisesWithTheAnalysisKept) {
    msg().setEcho(false);
    // 24 x 24: the smallest of these grids whose delayed pivots overflow ICNTL(14)=0's workspace under
    // the column-count symbolic factorisation (ICNTL(58)=2; 20 x 20 did under the quotient graph's).
    const CsrMatrix A = saddlePoint(24);
    const auto [error, mess] = solveWithRelaxation(A, 0);
    EXPECT_NE(mess.find("MUMPS workspace too small (INFOG(1)=-9"), std::string::npos) << mess;
    EXPECT_NE(mess.find("factorisation again (JOB=2, the analysis kept) with ICNTL(14)="), std::string::npos) << mess;
    EXPECT_EQ(occurrences(mess, "MUMPS analysis "), 1u) << mess;
    EXPECT_NE(mess.find("MUMPS: 288 negative pivots (expected: one per Lagrange multiplier)"), std::string::npos)
        << mess;
    EXPECT_LT(error, 1e-13);
    // With code_aster's default relaxation (20 %) the first factorisation fits: the same answer.
    const auto [defaultError, defaultMess] = solveWithRelaxation(A, 20);
    EXPECT_EQ(defaultMess.find("workspace too small"), std::string::npos) << defaultMess;
    EXPECT_LT(defaultError, 1e-13);
}
