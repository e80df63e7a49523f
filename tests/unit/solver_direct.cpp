// The direct solvers on small matrices with known solutions: SPD and indefinite (saddle point)
// systems, MUMPS orderings, singular matrices reported as such.
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "solver/LinearSolver.hpp"

using namespace ma;

namespace {

// 1D Laplacian (n x n) with Dirichlet at both ends when `anchored`, else pure Neumann (singular).
CsrMatrix laplacian(int n, bool anchored) {
    CsrMatrix A;
    A.rows = n;
    A.rowStart.assign(1, 0);
    for (int i = 0; i < n; ++i) {
        if (i > 0) A.cols.push_back(i - 1), A.values.push_back(-1.0);
        double d = 2.0;
        if (!anchored && (i == 0 || i == n - 1)) d = 1.0;
        A.cols.push_back(i), A.values.push_back(d);
        if (i < n - 1) A.cols.push_back(i + 1), A.values.push_back(-1.0);
        A.rowStart.push_back(static_cast<long long>(A.cols.size()));
    }
    return A;
}

// [[2, 1], [1, 0]]-like saddle point: Laplacian plus a multiplier tying x0 + x_{n-1} = 1.
CsrMatrix saddle(int n) {
    CsrMatrix L = laplacian(n, false), A;
    A.rows = n + 1;
    A.rowStart.assign(1, 0);
    for (int i = 0; i < n; ++i) {
        for (long long k = L.rowStart[i]; k < L.rowStart[i + 1]; ++k)
            A.cols.push_back(L.cols[k]), A.values.push_back(L.values[k]);
        if (i == 0 || i == n - 1) A.cols.push_back(n), A.values.push_back(1.0);
        A.rowStart.push_back(static_cast<long long>(A.cols.size()));
    }
    A.cols.push_back(0), A.values.push_back(1.0);
    A.cols.push_back(n - 1), A.values.push_back(1.0);
    A.rowStart.push_back(static_cast<long long>(A.cols.size()));
    return A;
}

}  // namespace

TEST(SolverDirect, SpdSystemAllMethodsAndOrderings) {
    msg().setEcho(false);
    const int n = 50;
    CsrMatrix A = laplacian(n, true);
    std::vector<double> x(n), b(n);
    for (int i = 0; i < n; ++i) x[i] = std::sin(0.3 * i) + 0.1 * i;
    A.multiply(x, b);
    struct Case {
        const char* method;
        const char* renum;
    };
    for (const auto& c : {Case{"MUMPS", "AUTO"}, Case{"MUMPS", "AMD"}, Case{"MUMPS", "AMF"}, Case{"MUMPS", "QAMD"},
                          Case{"MUMPS", "PORD"}, Case{"MUMPS", "SCOTCH"}, Case{"MUMPS", "METIS"},
                          Case{"MULT_FRONT", "AUTO"}, Case{"LDLT", "AUTO"}}) {
        SolverOptions o;
        o.method = c.method;
        o.renum = c.renum;
        auto solver = makeLinearSolver(o);
        solver->factorize(A, MatrixKind::SymmetricPositiveDefinite);
        std::vector<double> rhs = b;
        const double residual = solver->solve(rhs);
        EXPECT_LT(residual, 1e-13) << c.method << " " << c.renum;
        for (int i = 0; i < n; ++i) EXPECT_NEAR(rhs[i], x[i], 1e-10) << c.method << " " << c.renum;
    }
}

TEST(SolverDirect, IndefiniteSaddlePoint) {
    msg().setEcho(false);
    const int n = 20;
    CsrMatrix A = saddle(n);
    // Solution: any x with x0 + x_{n-1} = 1 minimising the energy with zero load -> x = 1/2
    // everywhere, multiplier 0; with the load b = A [x; lambda] for a chosen pair it is recovered.
    std::vector<double> x(n + 1), b(n + 1);
    for (int i = 0; i < n; ++i) x[i] = 0.05 * i;
    x[n] = 0.7;
    A.multiply(x, b);
    for (const char* method : {"MUMPS", "MULT_FRONT"}) {
        SolverOptions o;
        o.method = method;
        auto solver = makeLinearSolver(o);
        solver->factorize(A, MatrixKind::SymmetricIndefinite);
        std::vector<double> rhs = b;
        EXPECT_LT(solver->solve(rhs), 1e-12) << method;
        for (int i = 0; i <= n; ++i) EXPECT_NEAR(rhs[i], x[i], 1e-10) << method;
    }
}

TEST(SolverDirect, SingularMatrixIsReported) {
    msg().setEcho(false);
    CsrMatrix A = laplacian(30, false);  // constants are in the kernel
    for (const char* method : {"MUMPS", "MULT_FRONT"}) {
        SolverOptions o;
        o.method = method;
        auto solver = makeLinearSolver(o);
        try {
            solver->factorize(A, MatrixKind::SymmetricPositiveDefinite);
            std::vector<double> rhs(30, 0.0);
            rhs[0] = 1.0, rhs[29] = -1.0;
            solver->solve(rhs);
            ADD_FAILURE() << method << ": singular matrix not reported";
        } catch (const NumericalError& e) {
            EXPECT_NE(std::string(e.what()).find("singular"), std::string::npos) << e.what();
        }
    }
}

TEST(SolverDirect, UnknownMethod) {
    SolverOptions o;
    o.method = "CHOLESKY";
    EXPECT_THROW(makeLinearSolver(o), UserError);
    // PETSC and GCPC are solvers now (tests/unit/solver_krylov.cpp); what is not built is refused.
    o.method = "PETSC";
    o.preconditioner = "BLOC_LAGR";
    EXPECT_THROW(makeLinearSolver(o), NotImplemented);
}
