#include "solver/PieceBasis.hpp"

#include <algorithm>
#include <cmath>

namespace ma {

namespace {

// T transposed: per v unknown, the (equation, T_ik) that read it.
CsrMatrix transposed(const CsrMatrix& T, int columns) {
    CsrMatrix Tt;
    Tt.rows = columns;
    Tt.rowStart.assign(static_cast<size_t>(columns) + 1, 0);
    for (int c : T.cols) ++Tt.rowStart[static_cast<size_t>(c) + 1];
    for (size_t k = 0; k < static_cast<size_t>(columns); ++k) Tt.rowStart[k + 1] += Tt.rowStart[k];
    Tt.cols.resize(T.cols.size());
    Tt.values.resize(T.cols.size());
    std::vector<long long> next(Tt.rowStart.begin(), Tt.rowStart.end() - 1);
    for (int i = 0; i < T.rows; ++i)
        for (long long k = T.rowStart[static_cast<size_t>(i)]; k < T.rowStart[static_cast<size_t>(i) + 1]; ++k) {
            const size_t at = static_cast<size_t>(next[static_cast<size_t>(T.cols[static_cast<size_t>(k)])]++);
            Tt.cols[at] = i;
            Tt.values[at] = T.values[static_cast<size_t>(k)];
        }
    return Tt;
}

}  // namespace

namespace {

// Row k of T^T A T into row (indexed by v unknown), its columns appended to touched (unsorted):
// the sum over the equations i reading v_k of T_ik (row i of A) T.
struct RowBuilder {
    const CsrMatrix& A;
    const CsrMatrix& T;
    const CsrMatrix Tt;
    std::vector<double> row;
    std::vector<char> seen;
    std::vector<int> touched;

    void build(int k) {
        touched.clear();
        for (long long a = Tt.rowStart[size_t(k)]; a < Tt.rowStart[size_t(k) + 1]; ++a) {
            const int i = Tt.cols[size_t(a)];
            const double tik = Tt.values[size_t(a)];
            for (long long b = A.rowStart[size_t(i)]; b < A.rowStart[size_t(i) + 1]; ++b) {
                const int j = A.cols[size_t(b)];
                const double aij = tik * A.values[size_t(b)];
                for (long long c = T.rowStart[size_t(j)]; c < T.rowStart[size_t(j) + 1]; ++c) {
                    const size_t l = size_t(T.cols[size_t(c)]);
                    if (!seen[l]) seen[l] = 1, touched.push_back(int(l));
                    row[l] += aij * T.values[size_t(c)];
                }
            }
        }
    }
    void clear() {
        for (int l : touched) row[size_t(l)] = 0.0, seen[size_t(l)] = 0;
    }
};

}  // namespace

CsrMatrix pieceBasisMatrix(const CsrMatrix& A, const PieceBasis& basis, double dropTolerance) {
    const int n = basis.size();
    RowBuilder rows{
        A, basis.T, transposed(basis.T, n), std::vector<double>(size_t(n), 0.0), std::vector<char>(size_t(n), 0), {}};
    // The diagonal first (the drop test compares with it), then the rows.
    std::vector<double> diagonal(size_t(n), 1.0);
    for (int k = 0; k < n; ++k) {
        rows.build(k);
        if (rows.seen[size_t(k)]) diagonal[size_t(k)] = std::abs(rows.row[size_t(k)]);
        rows.clear();
    }
    CsrMatrix B;
    B.rows = n;
    B.rowStart.reserve(size_t(n) + 1);
    B.cols.reserve(A.cols.size());
    B.values.reserve(A.cols.size());
    for (int k = 0; k < n; ++k) {
        rows.build(k);
        if (basis.padding[size_t(k)] && !rows.seen[size_t(k)]) {
            rows.seen[size_t(k)] = 1, rows.touched.push_back(k);
            rows.row[size_t(k)] = 1.0;
        }
        std::sort(rows.touched.begin(), rows.touched.end());
        for (int l : rows.touched) {
            const double value = rows.row[size_t(l)];
            if (l == k || std::abs(value) > dropTolerance * std::sqrt(diagonal[size_t(k)] * diagonal[size_t(l)])) {
                B.cols.push_back(l);
                B.values.push_back(value);
            }
        }
        rows.clear();
        B.rowStart.push_back(static_cast<long long>(B.cols.size()));
    }
    return B;
}

void toEquations(const PieceBasis& basis, const double* v, double* u) {
    const CsrMatrix& T = basis.T;
    for (int i = 0; i < T.rows; ++i) {
        double s = 0.0;
        for (long long k = T.rowStart[static_cast<size_t>(i)]; k < T.rowStart[static_cast<size_t>(i) + 1]; ++k)
            s += T.values[static_cast<size_t>(k)] * v[T.cols[static_cast<size_t>(k)]];
        u[i] = s;
    }
}

void toPieces(const PieceBasis& basis, const double* r, double* w) {
    const CsrMatrix& T = basis.T;
    std::fill(w, w + basis.size(), 0.0);
    for (int i = 0; i < T.rows; ++i)
        for (long long k = T.rowStart[static_cast<size_t>(i)]; k < T.rowStart[static_cast<size_t>(i) + 1]; ++k)
            w[T.cols[static_cast<size_t>(k)]] += T.values[static_cast<size_t>(k)] * r[i];
}

}  // namespace ma
