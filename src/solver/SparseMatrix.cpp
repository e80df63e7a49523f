#include "solver/SparseMatrix.hpp"

#include <algorithm>

namespace ma {

long long CsrMatrix::find(int row, int col) const {
    const auto begin = cols.begin() + rowStart[row], end = cols.begin() + rowStart[row + 1];
    const auto it = std::lower_bound(begin, end, col);
    return it != end && *it == col ? static_cast<long long>(it - cols.begin()) : -1;
}

void CsrMatrix::setZero() { std::fill(values.begin(), values.end(), 0.0); }

void CsrMatrix::multiply(std::span<const double> x, std::span<double> y) const {
    for (int i = 0; i < rows; ++i) {
        double s = 0.0;
        for (long long k = rowStart[i]; k < rowStart[i + 1]; ++k) s += values[k] * x[cols[k]];
        y[i] = s;
    }
}

}  // namespace ma
