// CALC_CHAMP's engine (post/NodeValues.hpp): ELNO by extrapolation of the integration points
// (classical cells) or by the mean of the sub-cells around each parent node (X-FEM cells, as
// code_aster's te0289/xselno), NOEU as the mean over the cells around a node, and the GROUP_MA
// restriction; against values set by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/ShapeFunctions.hpp"
#include "post/NodeValues.hpp"

namespace {

using namespace ma;

// Two QUAD4 side by side on [0,2]x[0,1] (cells 0 and 1) and a TRIA3 above the first (cell 2).
std::shared_ptr<Mesh> threeCells() {
    auto m = std::make_shared<Mesh>();
    m->dim = 2;
    for (auto xy : {std::array<double, 3>{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {0, 2, 0}})
        m->addNode(xy);
    const int q0[] = {0, 1, 4, 3}, q1[] = {1, 2, 5, 4}, t[] = {3, 4, 6};
    m->addCell(CellType::QUAD4, q0);
    m->addCell(CellType::QUAD4, q1);
    m->addCell(CellType::TRIA3, t);
    return m;
}

// One element on `cell` with these reference points, one component.
void addElement(GaussField& f, int cell, const std::vector<std::array<double, 3>>& ref,
                const std::vector<double>& values, const std::vector<int>& subcell = {}) {
    f.cells.push_back(cell);
    f.pointOffsets.push_back(f.pointOffsets.back() + int(ref.size()));
    for (size_t p = 0; p < ref.size(); ++p) {
        f.pointRefCoords.push_back(ref[p]);
        f.pointCoords.push_back({0, 0, 0});
        f.pointWeights.push_back(1.0);
        f.pointSubcell.push_back(subcell.empty() ? 0 : subcell[p]);
        f.values.push_back(values[p]);
    }
}

GaussField emptyField(const std::shared_ptr<Mesh>& mesh) {
    GaussField f;
    f.mesh = mesh;
    f.components = {"SIXX"};
    return f;
}

double bilinear(const std::array<double, 3>& xi) { return 1 + 2 * xi[0] + 3 * xi[1] + 4 * xi[0] * xi[1]; }

TEST(NodeValues, ClassicalQuadExtrapolatesItsFourPointsExactly) {
    auto mesh = threeCells();
    GaussField f = emptyField(mesh);
    const double g = 1 / std::sqrt(3.0);
    std::vector<std::array<double, 3>> pts{{-g, -g, 0}, {g, -g, 0}, {g, g, 0}, {-g, g, 0}};
    std::vector<double> v;
    for (const auto& p : pts) v.push_back(bilinear(p));
    addElement(f, 0, pts, v);
    addElement(f, 2, {{1.0 / 3, 1.0 / 3, 0}}, {7.5});  // one point: the constant
    const auto elno = post::nodeValues(f, nullptr);
    ASSERT_TRUE(elno->atNodes);
    ASSERT_EQ(elno->pointOffsets, (std::vector<int>{0, 4, 7}));
    const auto ref = referenceNodes(CellType::QUAD4);
    for (int a = 0; a < 4; ++a) EXPECT_NEAR(elno->values[size_t(a)], bilinear(ref[size_t(a)]), 1e-12) << a;
    for (int a = 4; a < 7; ++a) EXPECT_DOUBLE_EQ(elno->values[size_t(a)], 7.5);
    // Reference coordinates are the nodes' (MED), physical ones the mesh nodes'.
    EXPECT_EQ(elno->pointCoords[2], mesh->coords[4]);
}

// Cell 0 cut by a vertical interface: sub-cell 0 has parent nodes 0 and 3, sub-cell 1 nodes 1, 2;
// sub-cell 2 (a sliver, no parent node) must not count.
class CutQuad : public Enrichment {
public:
    int nodeSlots(int) const override { return 1; }
    bool isEnriched(int cell) const override { return cell == 0; }
    void integration(int, ElementIntegration&) const override {}
    std::vector<std::vector<int>> subcellParentNodes(int cell) const override {
        if (cell != 0) return {};
        return {{0, 3}, {1, 2}, {}};
    }
};

TEST(NodeValues, XfemNodesTakeTheMeanOfTheirSubcellsLinearFits) {
    auto mesh = threeCells();
    GaussField f = emptyField(mesh);
    // Sub-cell 0: linear field 10 + xi + eta on the left; sub-cell 1: the constant 20 on the right.
    std::vector<std::array<double, 3>> pts{{-0.5, -0.5, 0}, {-0.2, 0.3, 0}, {-0.7, 0.6, 0}, {0.5, -0.5, 0},
                                           {0.4, 0.5, 0},   {0.1, 0.0, 0},  {0.0, 0.9, 0}};
    std::vector<double> v;
    for (int p = 0; p < 3; ++p) v.push_back(10 + pts[size_t(p)][0] + pts[size_t(p)][1]);
    v.insert(v.end(), {20, 20, 20, 1000});
    addElement(f, 0, pts, v, {0, 0, 0, 1, 1, 1, 2});
    CutQuad cut;
    const auto elno = post::nodeValues(f, &cut);
    EXPECT_NEAR(elno->values[0], 10 - 1 - 1, 1e-12);  // node 0 at (-1, -1)
    EXPECT_NEAR(elno->values[3], 10 - 1 + 1, 1e-12);  // node 3 at (-1, 1)
    EXPECT_NEAR(elno->values[1], 20, 1e-12);
    EXPECT_NEAR(elno->values[2], 20, 1e-12);
}

TEST(NodeValues, NodalAverageOverTheCellsAroundEachNode) {
    auto mesh = threeCells();
    GaussField f = emptyField(mesh);
    addElement(f, 0, {{0, 0, 0}}, {1.0});
    addElement(f, 1, {{0, 0, 0}}, {3.0});
    addElement(f, 2, {{0.3, 0.3, 0}}, {8.0});
    const auto noeu = post::nodalAverage(*post::nodeValues(f, nullptr));
    EXPECT_DOUBLE_EQ(noeu->at(0, 0), 1.0);
    EXPECT_DOUBLE_EQ(noeu->at(1, 0), 2.0);  // cells 0, 1
    EXPECT_DOUBLE_EQ(noeu->at(4, 0), 4.0);  // cells 0, 1, 2
    EXPECT_DOUBLE_EQ(noeu->at(3, 0), 4.5);  // cells 0, 2
    EXPECT_DOUBLE_EQ(noeu->at(2, 0), 3.0);
    EXPECT_DOUBLE_EQ(noeu->at(6, 0), 8.0);
    // Only cell 1 kept (GROUP_MA): the other nodes carry nothing.
    std::vector<char> keep{0, 1, 0};
    const auto part = post::nodalAverage(*post::nodeValues(*post::restrictToCells(f, keep), nullptr));
    EXPECT_TRUE(part->has(1, 0));
    EXPECT_FALSE(part->has(0, 0));
    EXPECT_FALSE(part->has(6, 0));
    EXPECT_DOUBLE_EQ(part->at(5, 0), 3.0);
}

}  // namespace
