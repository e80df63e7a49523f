// The nested-dissection ordering (METIS on the matrix graph, PERM_IN to MUMPS): a permutation
// with each node's unknowns together, reproducible, cheaper to factorise than
// minimum degree on a grid; RENUM='AUTO' uses it; the other orderings stay selectable.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <string>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "solver/LinearSolver.hpp"
#include "solver/MetisOrdering.hpp"

using namespace ma;

namespace {

// Plane-elasticity-like pattern: k x k nodes, 2 unknowns per node (consecutive), 9-point node
// stencil; SPD values (diagonally dominant).
CsrMatrix gridMatrix(int k) {
    CsrMatrix A;
    A.rows = 2 * k * k;
    A.rowStart.assign(1, 0);
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j)
            for (int c = 0; c < 2; ++c) {
                const int row = 2 * (i * k + j) + c;
                for (int di = -1; di <= 1; ++di)
                    for (int dj = -1; dj <= 1; ++dj) {
                        const int a = i + di, b = j + dj;
                        if (a < 0 || b < 0 || a >= k || b >= k) continue;
                        for (int d = 0; d < 2; ++d) {
                            const int col = 2 * (a * k + b) + d;
                            A.cols.push_back(col);
                            A.values.push_back(col == row ? 20.0 : (di == 0 && dj == 0) ? 0.5 : -1.0);
                        }
                    }
                A.rowStart.push_back(static_cast<long long>(A.cols.size()));
            }
    return A;
}

void expectNodeBlockPermutation(const FillReducingOrdering& o, int rows) {
    ASSERT_EQ(o.pivotRank.size(), size_t(rows));
    std::vector<int> sorted = o.pivotRank;
    std::sort(sorted.begin(), sorted.end());
    for (int i = 0; i < rows; ++i) ASSERT_EQ(sorted[i], i);
    for (int i = 0; i < rows; i += 2) EXPECT_EQ(o.pivotRank[i + 1], o.pivotRank[i] + 1) << "node " << i / 2;
}

// The number after `label` in the last .mess line that has it.
double loggedNumber(const std::string& label) {
    const std::string& text = msg().messText();
    const auto at = text.rfind(label);
    if (at == std::string::npos) return NAN;
    return std::stod(text.substr(at + label.size()));
}

double factoriseAndSolve(const CsrMatrix& A, const std::string& renum, int pcentPivot = 20) {
    SolverOptions o;
    o.renum = renum;
    o.pcentPivot = pcentPivot;
    auto solver = makeLinearSolver(o);
    solver->factorize(A, MatrixKind::SymmetricPositiveDefinite);
    std::vector<double> x(A.rows), b(A.rows);
    for (int i = 0; i < A.rows; ++i) x[i] = std::cos(0.01 * i);
    A.multiply(x, b);
    EXPECT_LT(solver->solve(b), 1e-14) << renum;
    for (int i = 0; i < A.rows; ++i) EXPECT_NEAR(b[i], x[i], 1e-12) << renum;
    return loggedNumber("predicted flops ");
}

}  // namespace

TEST(SolverOrdering, NestedDissectionIsAPermutationKeepingNodesTogether) {
    const CsrMatrix A = gridMatrix(30);
    const FillReducingOrdering o = nestedDissectionOrdering(A);
    expectNodeBlockPermutation(o, A.rows);
    EXPECT_EQ(o.vertices, 900);
    EXPECT_EQ(o.graphEdges, 2 * 29 * 30 + 2 * 29 * 29);  // 9-point stencil: 4 edges per cell, shared
}

TEST(SolverOrdering, OrderingIsReproducible) {
    const CsrMatrix A = gridMatrix(60);
    EXPECT_EQ(nestedDissectionOrdering(A).pivotRank, nestedDissectionOrdering(A).pivotRank);
}

// Above 1e5 vertices the top separator comes first and the halves are ordered apart, the second
// in a child process with two threads: the same ranks as on one.
TEST(SolverOrdering, SplitOrderingDoesNotDependOnTheThreads) {
    const CsrMatrix A = gridMatrix(320);
    const FillReducingOrdering one = nestedDissectionOrdering(A, 1), two = nestedDissectionOrdering(A, 2);
    expectNodeBlockPermutation(two, A.rows);
    EXPECT_EQ(one.pivotRank, two.pivotRank);
}

TEST(SolverOrdering, AutoIsMetisAndBeatsMinimumDegreeOnAGrid) {
    msg().setEcho(false);
    const CsrMatrix A = gridMatrix(80);
    const double metis = factoriseAndSolve(A, "METIS");
    EXPECT_NE(msg().messText().rfind("ordering METIS (PERM_IN) (asked METIS): METIS_NodeND"), std::string::npos);
    const double automatic = factoriseAndSolve(A, "AUTO");
    EXPECT_NE(msg().messText().rfind("ordering METIS (PERM_IN) (asked AUTO)"), std::string::npos);
    EXPECT_EQ(automatic, metis);
    const double amd = factoriseAndSolve(A, "AMD");
    EXPECT_NE(msg().messText().rfind("ordering AMD (asked AMD)"), std::string::npos);
    // George's nested-dissection count for a k x k 9-point grid, 2 unknowns per node: ~158 k^3.
    EXPECT_LT(metis, 0.9 * amd);
    EXPECT_LT(metis, 1.3 * 158.0 * 80 * 80 * 80);
    for (const char* renum : {"AMF", "SCOTCH", "PORD", "QAMD", "PTSCOTCH", "PARMETIS"}) factoriseAndSolve(A, renum);
    EXPECT_NE(msg().messText().rfind("RENUM='PARMETIS': the sequential solver uses its sequential counterpart METIS"),
              std::string::npos);
}

// ACCELERATION='LR*' is refused with the reason (this MUMPS's low-rank clustering writes out of
// bounds); AUTO and FR are full rank.
TEST(SolverLowRank, LowRankFactorsAreRefused) {
    msg().setEcho(false);
    const CsrMatrix A = gridMatrix(10);
    SolverOptions o;
    o.acceleration = "LR+";
    try {
        makeLinearSolver(o)->factorize(A, MatrixKind::SymmetricPositiveDefinite);
        FAIL() << "ACCELERATION='LR+' accepted";
    } catch (const NotImplemented& e) {
        EXPECT_NE(std::string(e.what()).find("SOLVEUR/ACCELERATION='LR+': block low-rank factors are not available"),
                  std::string::npos)
            << e.what();
    }
    for (const char* acceleration : {"AUTO", "FR", "FR++"}) {
        o.acceleration = acceleration;
        EXPECT_NO_THROW(makeLinearSolver(o)->factorize(A, MatrixKind::SymmetricPositiveDefinite)) << acceleration;
    }
}
