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
// the sum over the equations i reading v_k of T_ik (row i of A) T. A holds all the equations, or a
// share's (localRow: equation -> its row in A).
struct RowBuilder {
    const CsrMatrix& A;
    std::vector<int> localRow;
    const CsrMatrix& T;
    const CsrMatrix Tt;
    std::vector<double> row;
    std::vector<char> seen;
    std::vector<int> touched;

    void build(int k) {
        touched.clear();
        for (long long a = Tt.rowStart[size_t(k)]; a < Tt.rowStart[size_t(k) + 1]; ++a) {
            const int i = localRow.empty() ? Tt.cols[size_t(a)] : localRow[size_t(Tt.cols[size_t(a)])];
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

RowBuilder rowBuilder(const CsrMatrix& A, const PieceShare* share, const PieceBasis& basis) {
    const int n = basis.size();
    std::vector<int> localRow;
    if (share) {
        localRow.assign(size_t(basis.T.rows), -1);
        for (size_t k = 0; k < share->equations.size(); ++k) localRow[size_t(share->equations[k])] = int(k);
    }
    return RowBuilder{A,
                      std::move(localRow),
                      basis.T,
                      transposed(basis.T, n),
                      std::vector<double>(size_t(n), 0.0),
                      std::vector<char>(size_t(n), 0),
                      {}};
}

// |diagonal| of T^T A T on the unknowns [begin, end) (1 where no equation reads one): entry k is
// the sum of T_ik A_ij T_jk over the few equations i, j that read v_k (T is node-local), so only
// their couplings with each other are looked up, not whole rows.
std::vector<double> pieceDiagonalOf(const RowBuilder& rows, int begin, int end) {
    const CsrMatrix& Tt = rows.Tt;
    std::vector<double> diagonal(size_t(end - begin), 1.0);
    for (int k = begin; k < end; ++k) {
        const long long first = Tt.rowStart[size_t(k)], last = Tt.rowStart[size_t(k) + 1];
        if (first == last) continue;
        double d = 0.0;
        for (long long a = first; a < last; ++a) {
            const int i = Tt.cols[size_t(a)];
            const int row = rows.localRow.empty() ? i : rows.localRow[size_t(i)];
            for (long long b = first; b < last; ++b) {
                const long long at = rows.A.find(row, Tt.cols[size_t(b)]);
                if (at >= 0) d += Tt.values[size_t(a)] * rows.A.values[size_t(at)] * Tt.values[size_t(b)];
            }
        }
        diagonal[size_t(k - begin)] = std::abs(d);
    }
    return diagonal;
}

// Row k of T^T A T appended to B when v_k is read by one equation i whose couplings j each read one
// unknown, in increasing order (the nodes with one piece): T_ik A_ij T_jl, A's row mapped, with no
// accumulator and no sort. False, B unchanged, otherwise.
template <class Kept>
bool directRow(const RowBuilder& rows, int k, const Kept& kept, CsrMatrix& B) {
    const CsrMatrix &A = rows.A, &T = rows.T, &Tt = rows.Tt;
    const size_t reader = size_t(Tt.rowStart[size_t(k)]);  // the one (equation, T_ik) reading v_k
    if (Tt.rowStart[size_t(k) + 1] != static_cast<long long>(reader) + 1) return false;
    const size_t start = B.cols.size();
    const int i = rows.localRow.empty() ? Tt.cols[reader] : rows.localRow[size_t(Tt.cols[reader])];
    const double tik = Tt.values[reader];
    int last = -1;
    for (long long b = A.rowStart[size_t(i)]; b < A.rowStart[size_t(i) + 1]; ++b) {
        const size_t j = size_t(A.cols[size_t(b)]);
        const long long c = T.rowStart[j];
        if (T.rowStart[j + 1] - c != 1 || T.cols[size_t(c)] <= last) {
            B.cols.resize(start), B.values.resize(start);
            return false;
        }
        last = T.cols[size_t(c)];
        const double value = tik * A.values[size_t(b)] * T.values[size_t(c)];
        if (kept(k, last, value)) B.cols.push_back(last), B.values.push_back(value);
    }
    return true;
}

// Rows [begin, end) of T^T A T, columns global, the drop test against the whole diagonal.
CsrMatrix pieceRowsOf(RowBuilder& rows, const PieceBasis& basis, int begin, int end, std::span<const double> diagonal,
                      double dropTolerance) {
    CsrMatrix B;
    B.rows = end - begin;
    B.rowStart.reserve(size_t(B.rows) + 1);
    B.cols.reserve(rows.A.cols.size());
    B.values.reserve(rows.A.cols.size());
    const auto kept = [&](int k, int l, double value) {
        return l == k || std::abs(value) > dropTolerance * std::sqrt(diagonal[size_t(k)] * diagonal[size_t(l)]);
    };
    for (int k = begin; k < end; ++k) {
        if (directRow(rows, k, kept, B)) {
            B.rowStart.push_back(static_cast<long long>(B.cols.size()));
            continue;
        }
        rows.build(k);
        if (basis.padding[size_t(k)] && !rows.seen[size_t(k)]) {
            rows.seen[size_t(k)] = 1, rows.touched.push_back(k);
            rows.row[size_t(k)] = 1.0;
        }
        std::sort(rows.touched.begin(), rows.touched.end());
        for (int l : rows.touched) {
            const double value = rows.row[size_t(l)];
            if (kept(k, l, value)) {
                B.cols.push_back(l);
                B.values.push_back(value);
            }
        }
        rows.clear();
        B.rowStart.push_back(static_cast<long long>(B.cols.size()));
    }
    return B;
}

}  // namespace

CsrMatrix pieceBasisMatrix(const CsrMatrix& A, const PieceBasis& basis, double dropTolerance) {
    RowBuilder rows = rowBuilder(A, nullptr, basis);
    const std::vector<double> diagonal = pieceDiagonalOf(rows, 0, basis.size());  // the drop test compares with it
    return pieceRowsOf(rows, basis, 0, basis.size(), diagonal, dropTolerance);
}

std::vector<double> pieceBasisDiagonal(const CsrMatrix& shareRows, const PieceShare& share, const PieceBasis& basis) {
    RowBuilder rows = rowBuilder(shareRows, &share, basis);
    return pieceDiagonalOf(rows, share.copyBegin * basis.blockSize, share.copyEnd * basis.blockSize);
}

CsrMatrix pieceBasisRows(const CsrMatrix& shareRows, const PieceShare& share, const PieceBasis& basis,
                         std::span<const double> diagonal, double dropTolerance) {
    RowBuilder rows = rowBuilder(shareRows, &share, basis);
    return pieceRowsOf(rows, basis, share.copyBegin * basis.blockSize, share.copyEnd * basis.blockSize, diagonal,
                       dropTolerance);
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

void toPieces(const PieceBasis& basis, const PieceShare& share, const double* r, double* w) {
    const CsrMatrix& T = basis.T;
    const int first = basis.blockSize * share.copyBegin;
    std::fill(w, w + share.unknowns(basis.blockSize), 0.0);
    for (size_t e = 0; e < share.equations.size(); ++e) {
        const size_t i = size_t(share.equations[e]);
        for (long long k = T.rowStart[i]; k < T.rowStart[i + 1]; ++k)
            w[T.cols[size_t(k)] - first] += T.values[size_t(k)] * r[e];
    }
}

}  // namespace ma
