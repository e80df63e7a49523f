// core/SharedVector: the point geometry that the integration-point fields of one model share. A
// change through one owner never shows through another (copy on write), and sharing happens only
// between equal contents.
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

TEST(SharedVector, SharesOnlyEqualContents) {
    SharedVector<std::array<double, 3>> first = std::vector<std::array<double, 3>>{{0.0, 1.0, 2.0}, {3.0, 4.0, 5.0}};
    const auto watched = first.watch();
    SharedVector<std::array<double, 3>> same = std::vector<std::array<double, 3>>{{0.0, 1.0, 2.0}, {3.0, 4.0, 5.0}};
    SharedVector<std::array<double, 3>> other = std::vector<std::array<double, 3>>{{0.0, 1.0, 2.0}, {3.0, 4.0, 5.5}};
    EXPECT_TRUE(same.shareIfEqual(watched));
    EXPECT_EQ(same.watch().lock(), first.watch().lock());
    EXPECT_FALSE(other.shareIfEqual(watched));
    EXPECT_EQ(other[1][2], 5.5);
    // Changing the shared copy leaves the first owner's values.
    same.mut()[0][0] = 9.0;
    EXPECT_EQ(first[0][0], 0.0);
    // A watched storage whose owners are gone shares nothing.
    SharedVector<double> gone = std::vector<double>{1.0};
    const auto lost = gone.watch();
    gone.clear();
    SharedVector<double> later = std::vector<double>{1.0};
    EXPECT_FALSE(later.shareIfEqual(lost));
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
