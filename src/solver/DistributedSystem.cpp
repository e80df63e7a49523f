// Scaling and residuals of a matrix distributed over the MPI processes (solver/LinearSolverImpl.hpp,
// docs/mpi.md).
#include <algorithm>
#include <cmath>

#include "core/Mpi.hpp"
#include "solver/LinearSolverImpl.hpp"

namespace ma {

std::vector<double> summedDiagonal(const CsrMatrix& A) {
    std::vector<double> d = diagonalOf(A);
    mpi::sum(d);
    return d;
}

std::vector<double> distributedDiagonalScaling(const CsrMatrix& A, std::span<const double> diagonal) {
    std::vector<double> s(size_t(A.rows), 0.0);
    std::vector<int> zeroDiagonal;
    for (int i = 0; i < A.rows; ++i) {
        const double d = std::abs(diagonal[size_t(i)]);
        if (d > 0.0 && std::isfinite(d)) s[size_t(i)] = 1.0 / std::sqrt(d);
        else zeroDiagonal.push_back(i);
    }
    std::vector<double> largest(zeroDiagonal.size(), 0.0);
    for (size_t z = 0; z < zeroDiagonal.size(); ++z) {
        const int i = zeroDiagonal[z];
        for (long long k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k)
            if (s[size_t(A.cols[k])] > 0.0)
                largest[z] = std::max(largest[z], std::abs(A.values[k]) * s[size_t(A.cols[k])]);
    }
    mpi::max(largest);
    for (size_t z = 0; z < zeroDiagonal.size(); ++z)
        s[size_t(zeroDiagonal[z])] = largest[z] > 0.0 && std::isfinite(largest[z]) ? 1.0 / largest[z] : 1.0;
    return s;
}

ResidualInfo distributedResidualOf(const CsrMatrix& A, std::span<const double> x, std::span<const double> b,
                                   std::vector<double>& r) {
    const size_t n = size_t(A.rows);
    // A x, then |A| |x|, then the row's largest |a_ij|: this process's part (the sum over the
    // processes of the last bounds the summed row's largest entry).
    std::vector<long double> sums(3 * n, 0.0L);
    for (int i = 0; i < A.rows; ++i) {
        long double ax = 0.0L, absAx = 0.0L;  // in registers: the row's sums stay in x87 precision
        double rowMax = 0.0;
        for (long long k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) {
            const long double p = static_cast<long double>(A.values[k]) * x[size_t(A.cols[k])];
            ax += p;
            absAx += std::abs(p);
            rowMax = std::max(rowMax, std::abs(A.values[k]));
        }
        sums[size_t(i)] = ax, sums[n + size_t(i)] = absAx, sums[2 * n + size_t(i)] = rowMax;
    }
    mpi::sum(sums);
    double xMax = 0.0;
    for (double v : x) xMax = std::max(xMax, std::abs(v));
    r.resize(n);
    ResidualNorms norms(A.rows);
    for (size_t i = 0; i < n; ++i) {
        const long double ri = b[i] - sums[i], scale = std::abs(b[i]) + sums[n + i];
        r[i] = static_cast<double>(ri);
        norms.add(ri, scale, b[i], sums[2 * n + i] * xMax);
    }
    return norms.info();
}

}  // namespace ma
