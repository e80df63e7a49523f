// The nested-dissection orderings (METIS, and coordinate bisection when the rows have points;
// PERM_IN to MUMPS): permutations with each node's unknowns together, reproducible, cheaper to
// factorise than minimum degree on a grid; RENUM='AUTO' uses them; the other orderings stay
// selectable.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <string>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "solver/CoordinateOrdering.hpp"
#include "solver/LinearSolver.hpp"
#include "solver/MetisOrdering.hpp"
#include "solver/OrderingGraph.hpp"

using namespace ma;

namespace {

// Plane-elasticity-like pattern: k x k nodes (node (i, j) at x = j, y = i), 2 unknowns per node
// (consecutive), `heavy` unknowns on the nodes of column `heavyColumn` (an X-FEM interface's
// enriched nodes), 9-point node stencil; SPD values (diagonally dominant). Points per row in
// `points` when given.
CsrMatrix gridMatrix(int k, int heavyColumn = -1, int heavy = 2, std::vector<RowPoint>* points = nullptr) {
    auto unknowns = [&](int j) { return j == heavyColumn ? heavy : 2; };
    std::vector<int> first(size_t(k * k) + 1, 0);
    for (int n = 0; n < k * k; ++n) first[n + 1] = first[n] + unknowns(n % k);
    CsrMatrix A;
    A.rows = first.back();
    A.rowStart.assign(1, 0);
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j)
            for (int c = 0; c < unknowns(j); ++c) {
                const int row = first[i * k + j] + c;
                if (points) points->push_back({float(j), float(i), 0.0f});
                for (int di = -1; di <= 1; ++di)
                    for (int dj = -1; dj <= 1; ++dj) {
                        const int a = i + di, b = j + dj;
                        if (a < 0 || b < 0 || a >= k || b >= k) continue;
                        for (int d = 0; d < unknowns(b); ++d) {
                            const int col = first[a * k + b] + d;
                            A.cols.push_back(col);
                            A.values.push_back(col == row ? 40.0 : (di == 0 && dj == 0) ? 0.5 : -1.0);
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

double factoriseAndSolve(const CsrMatrix& A, const std::string& renum, int pcentPivot = 20,
                         std::span<const RowPoint> points = {}) {
    SolverOptions o;
    o.renum = renum;
    o.pcentPivot = pcentPivot;
    auto solver = makeLinearSolver(o);
    solver->factorize(A, MatrixKind::SymmetricPositiveDefinite, points);
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

// The graph of the supervariables (a node's unknowns, 2 or 4 here): each node joined to its 8 grid
// neighbours once, in increasing order, whatever the number of rows of either.
TEST(SolverOrdering, SupervariableGraphJoinsEachNodeToItsNeighboursOnce) {
    const int k = 7;
    const CsrMatrix A = gridMatrix(k, 3, 4);
    const Supervariables s = consecutiveIdenticalRows(A);
    ASSERT_EQ(s.size.size(), size_t(k * k));
    const OrderingGraph g = supervariableGraph(A, s);
    for (int n = 0; n < k * k; ++n) {
        std::vector<idx_t> expected;
        for (int di = -1; di <= 1; ++di)
            for (int dj = -1; dj <= 1; ++dj)
                if (const int a = n / k + di, b = n % k + dj; (di || dj) && a >= 0 && b >= 0 && a < k && b < k)
                    expected.push_back(a * k + b);
        const std::vector<idx_t> got(g.neighbours.begin() + g.start[n], g.neighbours.begin() + g.start[n + 1]);
        EXPECT_EQ(got, expected) << "node " << n;
    }
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
    EXPECT_NE(
        msg().messText().rfind(
            "RENUM='PARMETIS': MUMPS's analysis runs on the host alone, ordered by the sequential counterpart METIS"),
        std::string::npos);
}

TEST(SolverOrdering, CoordinateBisectionIsAReproduciblePermutationKeepingNodesTogether) {
    std::vector<RowPoint> points;
    const CsrMatrix A = gridMatrix(30, -1, 2, &points);
    const FillReducingOrdering o = coordinateNestedDissection(A, points);
    expectNodeBlockPermutation(o, A.rows);
    EXPECT_EQ(o.vertices, 900);
    EXPECT_EQ(o.graphEdges, 2 * 29 * 30 + 2 * 29 * 29);
    EXPECT_EQ(coordinateNestedDissection(A, points).pivotRank, o.pivotRank);
    for (int threads : {2, 4})
        EXPECT_EQ(coordinateNestedDissection(A, points, threads).pivotRank, o.pivotRank) << threads;
}

// With a point per row, AUTO bisects by coordinates: on a grid it meets George's
// nested-dissection count (~158 k^3 flops) where METIS lands above it; METIS stays METIS.
TEST(SolverOrdering, AutoWithPointsBisectsByCoordinatesAtTheNestedDissectionCount) {
    msg().setEcho(false);
    std::vector<RowPoint> points;
    const CsrMatrix A = gridMatrix(81, -1, 2, &points);
    const double coordinates = factoriseAndSolve(A, "AUTO", 20, points);
    EXPECT_NE(msg().messText().rfind("ordering COORDINATES (PERM_IN) (asked AUTO): nested dissection by coordinate"),
              std::string::npos);
    const double metis = factoriseAndSolve(A, "METIS", 20, points);
    EXPECT_NE(msg().messText().rfind("ordering METIS (PERM_IN) (asked METIS)"), std::string::npos);
    EXPECT_LT(coordinates, 1.1 * 158.0 * 81 * 81 * 81);
    EXPECT_LE(coordinates, metis);
}

// Flat cells (y spacing 1/20 of x): the planes go across the axis the part spans the most cells
// along, not the longest extent, which would cut the 81 x 81 grid into ever thinner strips of 81
// rows; the count stays the square grid's.
TEST(SolverOrdering, CoordinateBisectionOfFlatCellsCountsCellsNotLengths) {
    msg().setEcho(false);
    std::vector<RowPoint> points;
    const CsrMatrix A = gridMatrix(81, -1, 2, &points);
    for (RowPoint& p : points) p[1] *= 0.05f;
    EXPECT_LT(factoriseAndSolve(A, "AUTO", 20, points), 1.1 * 158.0 * 81 * 81 * 81);
}

// The top separator (the last ranks) avoids a column of heavy nodes at the median, taking the
// light column beside it: a separator three times heavier would cost 27 times the root's flops.
TEST(SolverOrdering, CoordinateBisectionCutsBesideHeavyNodes) {
    const int k = 41, heavyColumn = 20, heavy = 6;
    std::vector<RowPoint> points;
    const CsrMatrix A = gridMatrix(k, heavyColumn, heavy, &points);
    const FillReducingOrdering o = coordinateNestedDissection(A, points);
    int topRows = 0;
    for (int r = 0; r < A.rows; ++r)
        if (o.pivotRank[r] >= A.rows - 2 * k) {
            ++topRows;
            EXPECT_NE(points[r][0], float(heavyColumn)) << "row " << r;
            EXPECT_LE(std::abs(points[r][0] - float(heavyColumn)), 1.0f) << "row " << r;
        }
    EXPECT_EQ(topRows, 2 * k);
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
