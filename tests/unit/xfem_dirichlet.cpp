// DDL_IMPO on enriched nodes (xfem_spec §4): the relations of ssnv511a's left edge (§4.3 worked
// case), real values on nodes off and on the interface, H-components, and the skin sub-cells that
// carry PRES_REP on cut boundary edges (§3.11).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "mesh/ShapeFunctions.hpp"
#include "xfem/XfemDirichlet.hpp"
#include "xfem_test_meshes.hpp"

using namespace ma;
using namespace ma::xfem;

namespace {

// depx of ssnv511a: the block values by quadrant (0 exactly on the axes).
class BlockFunction : public Function {
public:
    std::string typeName() const override { return "formule"; }
    const std::vector<std::string>& parameters() const override { return params_; }
    double evaluate(std::span<const double> a) const override {
        const double x = a[0], y = a[1];
        if (y > 0 && x < 0) return -0.25;
        if (y < 0 && x < 0) return -0.5;
        if (y > 0 && x > 0) return 0.75;
        if (y < 0 && x > 0) return 1.0;
        return 0.0;
    }

private:
    std::vector<std::string> params_{"X", "Y"};
};

int nodeAt(const Mesh& m, double x, double y) {
    for (int n = 0; n < m.nodeCount(); ++n)
        if (std::abs(m.coords[n][0] - x) < 1e-12 && std::abs(m.coords[n][1] - y) < 1e-12) return n;
    return -1;
}

std::vector<int> groupNodes(const Mesh& m, const std::vector<std::string>& groups) {
    std::vector<int> out;
    for (const auto& g : groups)
        for (int c : m.cellGroups.get(g))
            for (int n : m.cellNodes(c))
                if (std::find(out.begin(), out.end(), n) == out.end()) out.push_back(n);
    return out;
}

// Value of the single-term relation on (node, component), NaN when absent.
double single(const std::vector<LinearRelation>& rel, int node, const std::string& comp) {
    for (const auto& r : rel)
        if (r.terms.size() == 1 && r.terms[0].node == node && r.terms[0].component == comp)
            return r.value / r.terms[0].coef;
    return std::nan("");
}

}  // namespace

TEST(XfemDirichlet, Ssnv511aLeftEdgeFunction) {
    msg().setEcho(false);
    auto mesh = xfemtest::square(5, CellType::QUAD4);
    auto j = xfemtest::ssnv511Cracks(mesh);
    XfemModel xm(xfemtest::model(mesh), {j.fiss1, j.fiss2, j.fiss3});
    ImposedDof req;
    req.path = "DDL_IMPO[1]/DX";
    req.component = "DX";
    req.nodes = groupNodes(*mesh, {"LD", "LG"});
    req.function = std::make_shared<BlockFunction>();
    const auto rel = xfemDirichlet(xm, req, 0.0);
    const int up = nodeAt(*mesh, -5, 1), down = nodeAt(*mesh, -5, -1);
    // xfem_spec §4.3: DX(-5,1) = -0.25, H1X(-5,1) = 0.125; DX(-5,-1) = -0.5, H1X(-5,-1) = 0.125.
    EXPECT_DOUBLE_EQ(single(rel, up, "DX"), -0.25);
    EXPECT_NEAR(single(rel, up, "H1X"), 0.125, 1e-15);
    EXPECT_DOUBLE_EQ(single(rel, down, "DX"), -0.5);
    EXPECT_NEAR(single(rel, down, "H1X"), 0.125, 1e-15);
    // Right edge: 0.75 above, 1 below; H1X = (f+ - f-)/2 with the shifted convention.
    EXPECT_DOUBLE_EQ(single(rel, nodeAt(*mesh, 5, 1), "DX"), 0.75);
    EXPECT_NEAR(single(rel, nodeAt(*mesh, 5, 1), "H1X"), -(0.75 - 1.0) / -2.0, 1e-15);
    EXPECT_NEAR(single(rel, nodeAt(*mesh, 5, -1), "H1X"), (0.75 - 1.0) / 2.0, 1e-15);
    // Other nodes: DX = f(node), nothing else.
    EXPECT_DOUBLE_EQ(single(rel, nodeAt(*mesh, -5, 3), "DX"), -0.25);
    EXPECT_TRUE(std::isnan(single(rel, nodeAt(*mesh, -5, 3), "H1X")));
    EXPECT_EQ(rel.size(), 12u + 4u);
    // Check of the meaning: the lower lip at (-5, 1) is DX + psi * H1X with psi = -2 -> -0.5.
    const double psi = xm.node(up)->slotValue[0];
    EXPECT_EQ(psi, -2.0);
    EXPECT_NEAR(single(rel, up, "DX") + psi * single(rel, up, "H1X"), -0.5, 1e-15);
}

TEST(XfemDirichlet, RealValuesAndHeavisideComponents) {
    msg().setEcho(false);
    auto mesh = xfemtest::square(5, CellType::QUAD4);
    auto j = xfemtest::ssnv511Cracks(mesh);
    XfemModel xm(xfemtest::model(mesh), {j.fiss1, j.fiss2, j.fiss3});
    ImposedDof req;
    req.path = "DDL_IMPO[1]";
    req.nodes = groupNodes(*mesh, {"LG"});
    req.component = "DX";
    req.value = 0.0;
    auto rel = xfemDirichlet(xm, req, 0.0);
    EXPECT_EQ(rel.size(), 6u);  // DX = 0 on each node (own side)
    req.component = "H1X";
    rel = xfemDirichlet(xm, req, 0.0);
    ASSERT_EQ(rel.size(), 2u);  // only the two enriched nodes carry an active H1X
    EXPECT_EQ(rel[0].terms[0].component, "H1X");
    req.component = "DZ";
    EXPECT_TRUE(xfemDirichlet(xm, req, 0.0).empty());

    // Interface through the nodes (n = 6): a node ON the interface prescribed with neighbours on
    // both sides gets both lips.
    auto m6 = xfemtest::square(6, CellType::QUAD4);
    auto j6 = xfemtest::ssnv511Cracks(m6);
    XfemModel xm6(xfemtest::model(m6), {j6.fiss1, j6.fiss2, j6.fiss3});
    req.nodes = groupNodes(*m6, {"LG"});
    req.component = "DX";
    req.value = 0.5;
    rel = xfemDirichlet(xm6, req, 0.0);
    const int mid = nodeAt(*m6, -5, 0);
    int onMid = 0;
    for (const auto& r : rel)
        if (r.terms[0].node == mid) {
            ++onMid;
            EXPECT_EQ(r.value, 0.5);
            if (r.terms.size() == 2) { EXPECT_EQ(r.terms[1].coef, xm6.node(mid)->slotValue[0]); }
        }
    EXPECT_EQ(onMid, 2);
}

TEST(XfemSkin, CutBoundarySegments) {
    msg().setEcho(false);
    auto mesh = xfemtest::square(5, CellType::QUAD4);
    auto j = xfemtest::ssnv511Cracks(mesh);
    XfemModel xm(xfemtest::model(mesh, true), {j.fiss1, j.fiss2, j.fiss3});
    ElementIntegration ei;
    int cutSegments = 0;
    for (int c : xm.xfemCells()) {
        const CellCut* cut = xm.cut(c);
        if (!cut->skin) continue;
        EXPECT_EQ(mesh->cellTypes[c], CellType::SEG2);
        xm.integration(c, ei);
        double length = 0;
        for (double w : ei.refWeights) length += w;
        EXPECT_NEAR(length, 2.0, 1e-14);  // reference length of SEG2
        EXPECT_EQ(xm.subcellRule(c), cut->cracks.size() == 1 ? "FPG4" : "FPG2");
        if (cut->subcells.size() == 2) {
            ++cutSegments;
            // The two halves of a segment crossed at its middle are on opposite sides.
            EXPECT_EQ(cut->subcells[0].heaviside[0], -cut->subcells[1].heaviside[0]);
            EXPECT_GE(xm.adjacentVolume(c), 0);
        }
    }
    // LG and LD at y = 0, LH and LB at x = 0.
    EXPECT_EQ(cutSegments, 4);
}

TEST(XfemSkin, CutBoundaryFaces3D) {
    msg().setEcho(false);
    const int n = 5;
    auto mesh = xfemtest::slab(n, CellType::HEXA8);
    auto id = [&](int i, int j, int k) { return k * (n + 1) * (n + 1) + j * (n + 1) + i; };
    std::vector<int> sd;
    for (int j = 0; j < n; ++j)
        sd.push_back(mesh->addCell(CellType::QUAD4,
                                   std::vector<int>{id(n, j, 0), id(n, j + 1, 0), id(n, j + 1, 1), id(n, j, 1)}));
    mesh->cellGroups.set("SD", sd);
    auto j = xfemtest::ssnv511Cracks(mesh);
    XfemModel xm(xfemtest::model(mesh, true), {j.fiss1, j.fiss2, j.fiss3});
    ElementIntegration ei;
    int faces = 0, cutFaces = 0;
    for (int c : xm.xfemCells()) {
        const CellCut* cut = xm.cut(c);
        if (!cut->skin) continue;
        ++faces;
        EXPECT_EQ(xm.subcellRule(c), "FPG12");
        xm.integration(c, ei);
        double area = 0;
        for (double w : ei.refWeights) area += w;
        EXPECT_NEAR(area, 4.0, 1e-13);  // reference area of QUAD4 (FPG12 weights sum to 1/2 within 4e-15)
        std::set<int> sides;
        for (const auto& s : cut->subcells) sides.insert(s.heaviside[0]);
        if (sides.size() == 2) ++cutFaces;
    }
    EXPECT_EQ(faces, 3);     // the faces of SD touching the nodes y = +-1
    EXPECT_EQ(cutFaces, 1);  // the face crossed by y = 0
}
