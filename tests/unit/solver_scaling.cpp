// Symmetric diagonal scaling and iterative refinement inside the direct solvers: transparent to
// the caller (unscaled A, b, x), accurate on rows whose stiffness is tiny, multiplier rows scaled
// by their entries, singular matrices still reported.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "solver/LinearSolver.hpp"
#include "solver/LinearSolverImpl.hpp"

using namespace ma;

namespace {

// The anchored 1D Laplacian on n "standard" unknowns, each coupled to one "enriched" unknown
// of stiffness f_k = 10^-k (k = 1 .. n): rows [.. 2 + f, -f] and [-f, 2f], as the rows of
// enrichments whose support is cut in a vanishing fraction (the diagonal spans n orders).
CsrMatrix weaklyCoupled(int n) {
    CsrMatrix A;
    A.rows = 2 * n;
    A.rowStart.assign(1, 0);
    for (int i = 0; i < n; ++i) {
        const double f = std::pow(10.0, -(i + 1));
        if (i > 0) A.cols.push_back(i - 1), A.values.push_back(-1.0);
        A.cols.push_back(i), A.values.push_back(2.0 + f);
        if (i < n - 1) A.cols.push_back(i + 1), A.values.push_back(-1.0);
        A.cols.push_back(n + i), A.values.push_back(-f);
        A.rowStart.push_back(static_cast<long long>(A.cols.size()));
    }
    for (int i = 0; i < n; ++i) {
        const double f = std::pow(10.0, -(i + 1));
        A.cols.push_back(i), A.values.push_back(-f);
        A.cols.push_back(n + i), A.values.push_back(2.0 * f);
        A.rowStart.push_back(static_cast<long long>(A.cols.size()));
    }
    return A;
}

// The n x n tridiagonal Laplacian (2 on the diagonal, -1 beside it).
CsrMatrix tridiagonalLaplacian(int n) {
    CsrMatrix A;
    A.rows = n;
    A.rowStart.assign(1, 0);
    for (int i = 0; i < n; ++i) {
        if (i > 0) A.cols.push_back(i - 1), A.values.push_back(-1.0);
        A.cols.push_back(i), A.values.push_back(2.0);
        if (i < n - 1) A.cols.push_back(i + 1), A.values.push_back(-1.0);
        A.rowStart.push_back(static_cast<long long>(A.cols.size()));
    }
    return A;
}

}  // namespace

TEST(SolverScaling, ScalingHasUnitDiagonalAndScalesMultiplierRows) {
    // [[4, 2], [2, 0]]: s0 = 1/2, multiplier row: 1 / (2 * 1/2) = 1.
    CsrMatrix A;
    A.rows = 2;
    A.rowStart = {0, 2, 3};
    A.cols = {0, 1, 0};
    A.values = {4.0, 2.0, 2.0};
    const auto s = symmetricDiagonalScaling(A);
    EXPECT_DOUBLE_EQ(s[0], 0.5);
    EXPECT_DOUBLE_EQ(s[1], 1.0);
}

TEST(SolverScaling, TinyRowsAreSolvedToTheirOwnPrecision) {
    msg().setEcho(false);
    const int n = 2 * 20;
    const CsrMatrix A = weaklyCoupled(n / 2);
    std::vector<double> x(n), b(n);
    for (int i = 0; i < n; ++i) x[i] = 1.0 + 0.25 * std::sin(0.7 * i);
    A.multiply(x, b);
    for (const char* method : {"MUMPS", "MULT_FRONT"}) {
        SolverOptions o;
        o.method = method;
        auto solver = makeLinearSolver(o);
        solver->factorize(A, MatrixKind::SymmetricPositiveDefinite);  // no null pivot after scaling
        std::vector<double> u = b;
        solver->solve(u);
        for (int i = 0; i < n; ++i) EXPECT_NEAR(u[i], x[i], 1e-12 * std::abs(x[i])) << method << " row " << i;
        std::vector<double> r;
        EXPECT_LT(residualOf(A, u, b, r).componentwise, 1e-15) << method;
    }
}

TEST(SolverScaling, SingularMatrixStillReportedAfterScaling) {
    msg().setEcho(false);
    // A floating 1D Laplacian (constants in the kernel) of small magnitude.
    CsrMatrix L;
    L.rows = 20;
    L.rowStart.assign(1, 0);
    for (int i = 0; i < 20; ++i) {
        if (i > 0) L.cols.push_back(i - 1), L.values.push_back(-1e-6);
        L.cols.push_back(i), L.values.push_back(i == 0 || i == 19 ? 1e-6 : 2e-6);
        if (i < 19) L.cols.push_back(i + 1), L.values.push_back(-1e-6);
        L.rowStart.push_back(static_cast<long long>(L.cols.size()));
    }
    for (const char* method : {"MUMPS", "MULT_FRONT"}) {
        SolverOptions o;
        o.method = method;
        auto solver = makeLinearSolver(o);
        auto run = [&] {
            solver->factorize(L, MatrixKind::SymmetricPositiveDefinite);
            std::vector<double> rhs(20, 0.0);
            rhs[0] = 1.0, rhs[19] = -1.0;
            solver->solve(rhs);
        };
        EXPECT_THROW(run(), NumericalError) << method;
    }
}

// The residual is summed by fixed blocks of rows: the same bits on one thread and on three, over
// several blocks (2e5 rows of the tridiagonal Laplacian, a rough x).
TEST(SolverResidual, SameBitsForAnyNumberOfThreads) {
    const int n = 200000;
    const CsrMatrix A = tridiagonalLaplacian(n);
    std::vector<double> x(n), b(n, 1.0), r1, r3;
    for (int i = 0; i < n; ++i) x[i] = std::sin(0.37 * i) + 1e-3 * i;
    const ResidualInfo one = residualOf(A, x, b, r1, 1), three = residualOf(A, x, b, r3, 3);
    EXPECT_EQ(r1, r3);
    EXPECT_EQ(one.normwise, three.normwise);
    EXPECT_EQ(one.componentwise, three.componentwise);
    EXPECT_EQ(one.omega, three.omega);
    // Row 7: b - (2 x_7 - x_6 - x_8), and the norm from every row.
    EXPECT_DOUBLE_EQ(r1[7], 1.0 - (2.0 * x[7] - x[6] - x[8]));
    long double num = 0.0L;
    for (double v : r1) num += static_cast<long double>(v) * v;
    EXPECT_NEAR(one.normwise, std::sqrt(double(num) / n), 1e-12 * one.normwise);
    EXPECT_GT(one.componentwise, 0.0);
}

// A block held at zero: x = 1 on rows 0-49 of the tridiagonal Laplacian, 0 beyond, computed with
// alternating noise of 1e-17 there. Those rows' own scale |A| |x| is the noise itself, so the plain
// componentwise backward error is of order 1; Arioli, Demmel and Duff's omega measures them against
// ||A_i|| ||x|| (their scale is below 1000 n eps of it) and sees round-off.
TEST(SolverResidual, OmegaMeasuresRowsAroundABlockHeldAtZero) {
    const int n = 100;
    const CsrMatrix A = tridiagonalLaplacian(n);
    std::vector<double> exact(n, 0.0), x(n), b(n, 0.0), r;
    for (int i = 0; i < 50; ++i) exact[i] = 1.0;
    b[0] = 1.0, b[49] = 1.0, b[50] = -1.0;  // A exact
    for (int i = 0; i < n; ++i) x[i] = exact[i] + (i >= 50 ? (i % 2 ? 1e-17 : -1e-17) : 0.0);
    const ResidualInfo noisy = residualOf(A, x, b, r);
    EXPECT_GT(noisy.componentwise, 0.5);
    EXPECT_LT(noisy.omega, 1e-16);
    const ResidualInfo clean = residualOf(A, exact, b, r);
    EXPECT_EQ(clean.componentwise, 0.0);
    EXPECT_EQ(clean.omega, 0.0);
}
