// core/SharedVector: the point geometry that the integration-point fields of one model share. A
// change through one owner never shows through another (copy on write); a watched storage is
// adopted only while an owner keeps it.
#include <gtest/gtest.h>

#include <array>

#include "core/SharedVector.hpp"
#include "fields/Fields.hpp"

using ma::SharedVector;

TEST(SharedVector, CopiesShareUntilOneChanges) {
    SharedVector<double> a = std::vector<double>{1.0, 2.0, 3.0};
    SharedVector<double> b = a;
    EXPECT_EQ(a.watch().lock(), b.watch().lock());  // one storage
    b.push_back(4.0);
    EXPECT_NE(a.watch().lock(), b.watch().lock());
    EXPECT_EQ(a.get(), (std::vector<double>{1.0, 2.0, 3.0}));
    EXPECT_EQ(b.get(), (std::vector<double>{1.0, 2.0, 3.0, 4.0}));
    SharedVector<double> c = a;
    c.mut()[0] = -1.0;
    EXPECT_EQ(a[0], 1.0);
    EXPECT_EQ(c[0], -1.0);
    c.insert(c.begin() + 1, size_t(2), 7.0);
    EXPECT_EQ(c.get(), (std::vector<double>{-1.0, 7.0, 7.0, 2.0, 3.0}));
    EXPECT_EQ(a.size(), 3u);
}

TEST(SharedVector, AdoptsAWatchedStorageWhileItLives) {
    SharedVector<std::array<double, 3>> first = std::vector<std::array<double, 3>>{{0.0, 1.0, 2.0}, {3.0, 4.0, 5.0}};
    SharedVector<std::array<double, 3>> later;
    EXPECT_TRUE(later.adopt(first.watch()));
    EXPECT_EQ(later.watch().lock(), first.watch().lock());
    EXPECT_EQ(later[1][2], 5.0);
    // Changing the adopted copy leaves the first owner's values.
    later.mut()[0][0] = 9.0;
    EXPECT_EQ(first[0][0], 0.0);
    EXPECT_EQ(later[0][0], 9.0);
    // A watched storage whose owners are gone gives nothing.
    SharedVector<double> gone = std::vector<double>{1.0};
    const auto lost = gone.watch();
    gone.clear();
    SharedVector<double> none;
    EXPECT_FALSE(none.adopt(lost));
    EXPECT_TRUE(none.empty());
    EXPECT_TRUE(gone.empty());
}

TEST(SharedVector, GaussFieldCopiesKeepTheirOwnValues) {
    ma::GaussField f;
    f.pointWeights = {0.5, 0.25};
    f.pointCoords.push_back({1.0, 2.0, 3.0});
    f.pointCoords.push_back({4.0, 5.0, 6.0});
    ma::GaussField g = f;
    g.pointWeights.mut()[1] = 2.0;
    EXPECT_EQ(f.pointWeights[1], 0.25);
    EXPECT_EQ(g.pointWeights[1], 2.0);
    EXPECT_EQ(f.pointCoords.watch().lock(), g.pointCoords.watch().lock());
    EXPECT_EQ(g.pointCount(), 2);
}

// Overwriting a shared storage whole leaves it to its other owners (no copy first); an owner's
// own storage is overwritten in place (a reused scratch keeps its capacity).
TEST(SharedVector, AssignLeavesASharedStorageToTheOthers) {
    SharedVector<int> stored = std::vector<int>{1, 2, 3, 4};
    SharedVector<int> scratch = stored;
    const std::vector<int> four{5, 6, 7, 8};
    scratch.assign(four.begin(), four.end());
    EXPECT_EQ(stored.get(), (std::vector<int>{1, 2, 3, 4}));
    EXPECT_EQ(scratch.get(), four);
    EXPECT_NE(stored.watch().lock(), scratch.watch().lock());
    const int* own = scratch.data();
    scratch.assign(size_t(3), 9);
    EXPECT_EQ(scratch.data(), own);  // its own storage, reused
    EXPECT_EQ(scratch.get(), (std::vector<int>{9, 9, 9}));
    scratch = stored;
    scratch.assign(size_t(2), 0);
    EXPECT_EQ(stored.get(), (std::vector<int>{1, 2, 3, 4}));
    EXPECT_EQ(scratch.get(), (std::vector<int>{0, 0}));
}
