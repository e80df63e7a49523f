#pragma once
// Small sparse matrices for the solver tests, written row by row.
#include <algorithm>
#include <utility>
#include <vector>

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

}  // namespace ma::test
