#pragma once
// Small sparse matrices for the solver tests, written row by row, and a solve of a known answer.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/Messages.hpp"
#include "solver/LinearSolver.hpp"

namespace ma::test {

// Rows given as (column, value) lists -> CSR (columns sorted).
inline CsrMatrix fromRows(std::vector<std::vector<std::pair<int, double>>> rows) {
    CsrMatrix A;
    A.rows = int(rows.size());
    A.rowStart.assign(1, 0);
    for (auto& row : rows) {
        std::sort(row.begin(), row.end());
        for (auto [c, v] : row) A.cols.push_back(c), A.values.push_back(v);
        A.rowStart.push_back(static_cast<long long>(A.cols.size()));
    }
    return A;
}

struct Solved {
    double error = 0.0;     // max |x - x0|
    double residual = 0.0;  // ||A x - b|| / ||b|| as the solver returns it
    std::string mess;       // what the solve wrote to the .mess
};

// Solves A x = A x0 (x0_i = cos(0.1 i) + 1) with `o`.
inline Solved solveKnown(const CsrMatrix& A, const SolverOptions& o, MatrixKind kind) {
    const size_t from = msg().messText().size();
    auto solver = makeLinearSolver(o);
    solver->factorize(A, kind);
    std::vector<double> x0(size_t(A.rows)), b(size_t(A.rows));
    for (int i = 0; i < A.rows; ++i) x0[size_t(i)] = std::cos(0.1 * i) + 1.0;
    A.multiply(x0, b);
    Solved s;
    s.residual = solver->solve(b);
    for (int i = 0; i < A.rows; ++i) s.error = std::max(s.error, std::abs(b[size_t(i)] - x0[size_t(i)]));
    s.mess = msg().messText().substr(from);
    return s;
}

}  // namespace ma::test
