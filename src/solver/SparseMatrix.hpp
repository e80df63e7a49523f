#pragma once
// Compressed sparse rows with a pattern fixed before assembly (no insertion while assembling).
// Symmetric matrices are stored in full (both triangles): residuals and Eigen need it, MUMPS
// receives the upper triangle.
#include <span>
#include <vector>

namespace ma {

struct CsrMatrix {
    int rows = 0;
    std::vector<long long> rowStart{0};  // rows + 1 offsets into cols/values
    std::vector<int> cols;               // sorted within each row
    std::vector<double> values;

    long long nonZeros() const { return static_cast<long long>(cols.size()); }
    // Position of (row, col) in values; -1 when outside the pattern.
    long long find(int row, int col) const;
    void setZero();
    // y = A x
    void multiply(std::span<const double> x, std::span<double> y) const;
};

}  // namespace ma
