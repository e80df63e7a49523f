// DEFI_GROUP selections on small hand-made meshes: BANDE criteria, FACE_NORMALE tolerance and
// sign, CRIT_NOEUD on quadratic cells, set operations keeping order.
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.hpp"
#include "mesh/GroupSelection.hpp"

using namespace ma;

namespace {

// Two QUAD8 side by side on [0,2]x[0,1] plus their boundary SEG3 edges (counter-clockwise).
Mesh twoQuad8() {
    Mesh m;
    m.dim = 2;
    // vertices 0..5: (0,0) (1,0) (2,0) (0,1) (1,1) (2,1)
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i) m.addNode({double(i), double(j), 0});
    auto mid = [&](int a, int b) {
        return m.addNode({(m.coords[a][0] + m.coords[b][0]) / 2, (m.coords[a][1] + m.coords[b][1]) / 2, 0});
    };
    const int m01 = mid(0, 1), m14 = mid(1, 4), m43 = mid(4, 3), m30 = mid(3, 0);
    const int m12 = mid(1, 2), m25 = mid(2, 5), m54 = mid(5, 4);
    std::vector<int> q1{0, 1, 4, 3, m01, m14, m43, m30}, q2{1, 2, 5, 4, m12, m25, m54, m14};
    m.addCell(CellType::QUAD8, q1);
    m.addCell(CellType::QUAD8, q2);
    std::vector<int> bottom{0, 1, m01}, right{2, 5, m25}, slanted{5, 4, m54};
    m.addCell(CellType::SEG3, bottom);
    m.addCell(CellType::SEG3, right);
    m.addCell(CellType::SEG3, slanted);
    return m;
}

}  // namespace

TEST(GroupSelection, NodeCriteriaOnQuadraticCells) {
    Mesh m = twoQuad8();
    EXPECT_EQ(nodesOfCells(m, {0}, NodeCriterion::Vertices), (std::vector<int>{0, 1, 3, 4}));
    EXPECT_EQ(nodesOfCells(m, {0}, NodeCriterion::MidNodes), (std::vector<int>{6, 7, 8, 9}));
    EXPECT_EQ(nodesOfCells(m, {0, 1}, NodeCriterion::All).size(), 13u);
    EXPECT_TRUE(nodesOfCells(m, {0}, NodeCriterion::Centres).empty());
}

TEST(GroupSelection, BandeCriteria) {
    Mesh m = twoQuad8();
    // Band |x - 2| <= 0.1: nodes 2, 5 and the mid-node of edge 2-5.
    const Vec3 p{2, 0, 0}, n{1, 0, 0};
    EXPECT_EQ(cellsInBand(m, p, n, 0.1, "AU_MOINS_UN"), (std::vector<int>{1, 3, 4}));
    EXPECT_EQ(cellsInBand(m, p, n, 0.1, "TOUS"), (std::vector<int>{3}));
    // MAJORITE: at least half of the nodes (the slanted SEG3 has 1 of 3: out).
    EXPECT_EQ(cellsInBand(m, p, n, 0.1, "MAJORITE"), (std::vector<int>{3}));
    // Wider band |x - 2| <= 0.6: q2 has 2+1+... nodes x>=1.5: 2, 5, 10(2,0.5), 11(1.5,0), 12(1.5,1) = 5 of 8.
    EXPECT_EQ(cellsInBand(m, p, n, 0.6, "MAJORITE"), (std::vector<int>{1, 3, 4}));
    EXPECT_THROW(cellsInBand(m, p, Vec3{0, 0, 0}, 0.1, "TOUS"), UserError);
}

TEST(GroupSelection, FaceNormaleToleranceAndSign) {
    Mesh m = twoQuad8();
    // Normals (dy, -dx): bottom edge (0,-1), right edge (0,1)->(1,0)... right edge 2->5 is (0,1): n=(1,0).
    EXPECT_EQ(cellsWithNormal(m, {0, -1, 0}, 0.5, true), (std::vector<int>{2}));
    EXPECT_EQ(cellsWithNormal(m, {0, 1, 0}, 0.5, true), (std::vector<int>{4}));  // 5->4 goes -x: n=(0,1)
    EXPECT_EQ(cellsWithNormal(m, {0, 1, 0}, 0.5, false), (std::vector<int>{2, 4}));
    // 0.5 degree: a direction tilted by 0.4 degree is accepted, by 0.6 degree rejected.
    const double a4 = 0.4 * M_PI / 180, a6 = 0.6 * M_PI / 180;
    EXPECT_EQ(cellsWithNormal(m, {std::cos(a4), std::sin(a4), 0}, 0.5, true), (std::vector<int>{3}));
    EXPECT_TRUE(cellsWithNormal(m, {std::cos(a6), std::sin(a6), 0}, 0.5, true).empty());
    EXPECT_EQ(cellsWithNormal(m, {std::cos(a6), std::sin(a6), 0}, 1.0, true), (std::vector<int>{3}));
}

TEST(GroupSelection, SetOperationsKeepTheFirstListOrder) {
    const std::vector<int> a{5, 3, 9, 1}, b{1, 9, 7}, c{3};
    EXPECT_EQ(intersectionOf({&a, &b}), (std::vector<int>{9, 1}));
    EXPECT_EQ(unionOf({&a, &b, &c}), (std::vector<int>{5, 3, 9, 1, 7}));
    EXPECT_EQ(differenceOf({&a, &b, &c}), (std::vector<int>{5}));
    Mesh m = twoQuad8();
    EXPECT_EQ(filterCellType(m, {0, 1, 2, 3, 4}, "1D"), (std::vector<int>{2, 3, 4}));
    EXPECT_EQ(filterCellType(m, {4, 1, 0}, "QUAD8"), (std::vector<int>{1, 0}));
    EXPECT_THROW(filterCellType(m, {0}, "CUBE8"), UserError);
}
