// The piece basis shared between processes (solver/PieceShares.hpp): on ssnv511c's flat slab the
// shares cut across the longest extent, never through the thickness; each share's equations read
// only its copies; the shares' rows of T^T K T and of T^T r, stacked, are the whole ones bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "fe/PieceCopies.hpp"
#include "solver/PieceShares.hpp"
#include "xfem_free_model.hpp"
#include "xfem_test_meshes.hpp"

using namespace ma;

namespace {

// The rows `equations` of A (global columns).
CsrMatrix rowsOf(const CsrMatrix& A, const std::vector<int>& equations) {
    CsrMatrix rows;
    rows.rows = int(equations.size());
    for (int i : equations) {
        for (long long k = A.rowStart[size_t(i)]; k < A.rowStart[size_t(i) + 1]; ++k)
            rows.cols.push_back(A.cols[size_t(k)]), rows.values.push_back(A.values[size_t(k)]);
        rows.rowStart.push_back(static_cast<long long>(rows.cols.size()));
    }
    return rows;
}

// min and max of coordinate `axis` over the copies of a share.
std::pair<double, double> extent(const PieceBasis& basis, const PieceShare& share, int axis) {
    double lo = 1e300, hi = -1e300;
    for (int c = share.copyBegin; c < share.copyEnd; ++c) {
        const double x = basis.coordinates[size_t(c * basis.blockSize + axis)];
        lo = std::min(lo, x), hi = std::max(hi, x);
    }
    return {lo, hi};
}

}  // namespace

TEST(PieceShares, AFlatSlabIsCutAcrossItsLongestExtentIntoSharesThatReadOnlyTheirCopies) {
    const xfemtest::FreeModel f =
        xfemtest::freeModel(xfemtest::slab(8, CellType::HEXA8, 8), xfemtest::junction(0.3, -0.4, true));
    PieceBasis basis = pieceBasisOf(*f.space, f.constraints, f.K.rows);
    ASSERT_GT(basis.copies, 0) << basis.refusal;
    const std::vector<PieceShare> shares = shareCopies(basis, bisectCopies(basis, 2), 2);
    ASSERT_EQ(shares.size(), 2u);
    EXPECT_EQ(shares[0].copyBegin, 0);
    EXPECT_EQ(shares[0].copyEnd, shares[1].copyBegin);
    EXPECT_EQ(shares[1].copyEnd, basis.copies);
    EXPECT_NEAR(shares[0].copyEnd, basis.copies / 2, basis.copies / 10);
    // Every equation in exactly one share, reading only that share's copies.
    std::vector<int> shareOf(size_t(f.K.rows), -1);
    for (int p = 0; p < 2; ++p)
        for (int i : shares[size_t(p)].equations) {
            EXPECT_EQ(shareOf[size_t(i)], -1);
            shareOf[size_t(i)] = p;
            for (long long k = basis.T.rowStart[size_t(i)]; k < basis.T.rowStart[size_t(i) + 1]; ++k) {
                const int copy = basis.T.cols[size_t(k)] / basis.blockSize;
                EXPECT_GE(copy, shares[size_t(p)].copyBegin);
                EXPECT_LT(copy, shares[size_t(p)].copyEnd);
            }
        }
    EXPECT_EQ(std::count(shareOf.begin(), shareOf.end(), -1), 0);
    // The cut is across x or y (the slab is 10 x 10 x 1): both shares span the whole thickness and
    // lie on either side of one plane.
    for (const PieceShare& share : shares) {
        EXPECT_EQ(extent(basis, share, 2).first, 0.0);
        EXPECT_EQ(extent(basis, share, 2).second, 1.0);
    }
    const bool alongX = extent(basis, shares[0], 0).second <= extent(basis, shares[1], 0).first;
    const bool alongY = extent(basis, shares[0], 1).second <= extent(basis, shares[1], 1).first;
    EXPECT_TRUE(alongX || alongY);
    // The shares' rows, stacked, are the renumbered basis's whole matrix; likewise T^T r.
    const CsrMatrix whole = pieceBasisMatrix(f.K, basis, 1e-10);
    std::vector<double> diagonal(size_t(basis.size()));
    for (int k = 0; k < whole.rows; ++k)
        for (long long a = whole.rowStart[size_t(k)]; a < whole.rowStart[size_t(k) + 1]; ++a)
            if (whole.cols[size_t(a)] == k) diagonal[size_t(k)] = std::abs(whole.values[size_t(a)]);
    std::vector<double> r(size_t(f.K.rows)), wholePieces(size_t(basis.size()));
    for (size_t i = 0; i < r.size(); ++i) r[i] = std::sin(0.7 * double(i) + 0.1);
    toPieces(basis, r.data(), wholePieces.data());
    for (const PieceShare& share : shares) {
        const CsrMatrix shareRows = rowsOf(f.K, share.equations);
        EXPECT_EQ(pieceBasisDiagonal(shareRows, share, basis),
                  std::vector<double>(diagonal.begin() + share.copyBegin * 3, diagonal.begin() + share.copyEnd * 3));
        const CsrMatrix part = pieceBasisRows(shareRows, share, basis, diagonal, 1e-10);
        const long long first = whole.rowStart[size_t(share.copyBegin * 3)];
        const long long last = whole.rowStart[size_t(share.copyEnd * 3)];
        EXPECT_EQ(part.cols, std::vector<int>(whole.cols.begin() + first, whole.cols.begin() + last));
        EXPECT_EQ(part.values, std::vector<double>(whole.values.begin() + first, whole.values.begin() + last));
        std::vector<double> mine, pieces(size_t(share.unknowns(3)));
        for (int i : share.equations) mine.push_back(r[size_t(i)]);
        toPieces(basis, share, mine.data(), pieces.data());
        EXPECT_EQ(pieces, std::vector<double>(wholePieces.begin() + share.copyBegin * 3,
                                              wholePieces.begin() + share.copyEnd * 3));
    }
}

// The renumbered modes are still null modes of T^T K T (they followed the copies).
TEST(PieceShares, RenumberedCopiesKeepTheirRigidModes) {
    const xfemtest::FreeModel f =
        xfemtest::freeModel(xfemtest::slab(5, CellType::HEXA8, 3), xfemtest::junction(0.3, -0.4, true));
    PieceBasis basis = pieceBasisOf(*f.space, f.constraints, f.K.rows);
    ASSERT_EQ(shareCopies(basis, bisectCopies(basis, 3), 3).size(), 3u);
    const CsrMatrix B = pieceBasisMatrix(f.K, basis, 0.0);
    const size_t n = size_t(B.rows);
    std::vector<double> y(n);
    double scale = 0.0;
    for (double v : B.values) scale = std::max(scale, std::abs(v));
    for (size_t m = 0; m < 6; ++m) {
        const std::span<const double> mode(basis.modes.data() + m * n, n);
        B.multiply(mode, y);
        double worst = 0.0, size = 0.0;
        for (size_t i = 0; i < n; ++i)
            worst = std::max(worst, std::abs(y[i])), size = std::max(size, std::abs(mode[i]));
        EXPECT_GT(size, 0.0);
        EXPECT_LT(worst / (scale * size), 1e-13) << "mode " << m;
    }
}
