// X-FEM geometry and enrichment (src/xfem): level sets, cut cells, node status with junctions,
// Heaviside slots, sub-cells and the rigid-block invariant of ssnv511a-d.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "mesh/ShapeFunctions.hpp"
#include "xfem/CellGeometry.hpp"
#include "xfem_test_meshes.hpp"

using namespace ma;
using namespace ma::xfem;
using xfemtest::levelSet;

namespace {

int nodeAt(const Mesh& m, double x, double y, double z = 0) {
    for (int n = 0; n < m.nodeCount(); ++n)
        if (std::abs(m.coords[n][0] - x) < 1e-12 && std::abs(m.coords[n][1] - y) < 1e-12 &&
            std::abs(m.coords[n][2] - z) < 1e-12)
            return n;
    return -1;
}

std::set<std::pair<double, double>> enrichedXY(const Crack& c) {
    std::set<std::pair<double, double>> out;
    for (int n = 0; n < c.mesh->nodeCount(); ++n)
        if (c.nodeStatus[n]) out.insert({c.mesh->coords[n][0], c.mesh->coords[n][1]});
    return out;
}

// Physical measure of a parent cell.
double cellMeasure(const Mesh& m, int cell) {
    const CellType t = m.cellTypes[cell];
    const auto nodes = m.cellNodes(cell);
    std::vector<std::array<double, 3>> x;
    for (int n : nodes) x.push_back(m.coords[n]);
    double sum = 0;
    for (const auto& s : primarySimplices(t)) {
        std::vector<std::array<double, 3>> v;
        for (int i : s) v.push_back(x[i]);
        sum += std::abs(simplexMeasure(cellDimension(t), v));
    }
    return sum;
}

double detJ(const Mesh& m, int cell, const std::array<double, 3>& xi) {
    const CellType t = m.cellTypes[cell];
    const auto nodes = m.cellNodes(cell);
    std::array<double, 24> dN{};
    shapeDerivatives(t, xi, dN);
    const int d = cellDimension(t);
    double J[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    for (size_t a = 0; a < nodes.size(); ++a)
        for (int i = 0; i < d; ++i)
            for (int j = 0; j < d; ++j) J[i][j] += m.coords[nodes[a]][i] * dN[3 * a + j];
    if (d == 2) return J[0][0] * J[1][1] - J[0][1] * J[1][0];
    return J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
           J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
}

// Block of ssnv511 (junction at (x0, y0)): 0 = x<x0,y>y0; 1 = x<x0,y<y0; 2 = x>x0,y>y0; 3 = x>x0,y<y0.
int blockOf(double x, double y, double x0, double y0) { return (x > x0 ? 2 : 0) + (y < y0 ? 1 : 0); }

// The four-block rigid translation represented with the enrichment: standard dofs = own block,
// Heaviside dofs = (other block - own block) / psi. Checks it is reproduced exactly at every
// integration point of every X-FEM element. Returns the number of points checked.
int checkRigidBlocks(const XfemModel& xm, double x0, double y0) {
    const Mesh& m = xm.mesh();
    const std::array<std::array<double, 3>, 4> t{
        {{-0.25, 0.1, 0.3}, {-0.5, -0.2, 0.7}, {0.75, 0.4, -0.1}, {1.0, -0.6, 0.2}}};
    // Block of each (node, slot): slot 0 from the node position (+ side when on an interface).
    auto domainBlock = [&](int node, const std::vector<signed char>& key) {
        // Find a sub-cell of that domain in the support and take its centroid.
        for (int c : xm.xfemCells()) {
            const CellCut* cut = xm.cut(c);
            if (cut->skin) continue;
            const auto cn = m.cellNodes(c);
            if (std::find(cn.begin(), cn.end(), node) == cn.end()) continue;
            for (int s = 0; s < int(cut->subcells.size()); ++s) {
                if (xm.domainKey(node, *cut, s) != key) continue;
                std::array<double, 3> bary{0, 0, 0};
                for (int v = 0; v < cut->vertexCount(); ++v)
                    for (int j = 0; j < 3; ++j)
                        bary[j] += cut->points[cut->subcells[s].vertices[v]].ref[j] / cut->vertexCount();
                std::vector<std::array<double, 3>> xs;
                for (int n : cn) xs.push_back(m.coords[n]);
                const auto x = mapToPhysical(m.cellTypes[c], xs, bary);
                return blockOf(x[0], x[1], x0, y0);
            }
        }
        ADD_FAILURE() << "domain not found";
        return 0;
    };
    std::map<std::pair<int, int>, std::array<double, 3>> U;  // (node, slot) -> value
    for (int n = 0; n < m.nodeCount(); ++n) {
        const double x = m.coords[n][0], y = m.coords[n][1];
        int own = blockOf(x == x0 ? x + 1e-9 : x, y == y0 ? y + 1e-9 : y, x0, y0);  // LSN >= 0: + side
        const NodeEnrichment* e = xm.node(n);
        if (e && e->activeCracks.size() && !e->ownMissing) own = domainBlock(n, e->own);
        U[{n, 0}] = t[own];
        for (int k = 1; k <= xm.activeSlots(n); ++k) {
            const int b = domainBlock(n, e->slotDomain[k - 1]);
            std::array<double, 3> v;
            for (int j = 0; j < 3; ++j) v[j] = (t[b][j] - t[own][j]) / e->slotValue[k - 1];
            U[{n, k}] = v;
        }
    }
    int points = 0;
    ElementIntegration ei;
    for (int c : xm.xfemCells()) {
        xm.integration(c, ei);
        const auto cn = m.cellNodes(c);
        std::vector<std::array<double, 3>> xs;
        for (int n : cn) xs.push_back(m.coords[n]);
        std::array<double, 8> N{};
        for (size_t p = 0; p < ei.refPoints.size(); ++p) {
            shapeValues(m.cellTypes[c], ei.refPoints[p], N);
            std::array<double, 3> u{0, 0, 0};
            for (int a = 0; a < ei.nodeCount; ++a)
                for (int k = 0; k < ei.slots[a]; ++k)
                    for (int j = 0; j < 3; ++j) u[j] += N[a] * ei.multiplier(int(p), a, k) * U[{cn[a], k}][j];
            const auto x = mapToPhysical(m.cellTypes[c], xs, ei.refPoints[p]);
            const int b = blockOf(x[0], x[1], x0, y0);
            for (int j = 0; j < 3; ++j)
                EXPECT_NEAR(u[j], t[b][j], 1e-14) << "cell " << c << " point (" << x[0] << "," << x[1] << ")";
            ++points;
        }
    }
    return points;
}

// Sub-cells tile their parent and the weights integrate the parent measure.
void checkTiling(const XfemModel& xm) {
    const Mesh& m = xm.mesh();
    ElementIntegration ei;
    for (int c : xm.xfemCells()) {
        const CellCut* cut = xm.cut(c);
        EXPECT_EQ(cut->droppedDegenerate, 0);
        xm.integration(c, ei);
        double area = 0;
        if (cut->dim == cellDimension(m.cellTypes[c]) && !cut->skin) {
            for (size_t p = 0; p < ei.refPoints.size(); ++p)
                area += ei.refWeights[p] * std::abs(detJ(m, c, ei.refPoints[p]));
            EXPECT_NEAR(area, cellMeasure(m, c), 1e-13 * cellMeasure(m, c)) << "cell " << c;
        }
        for (int s = 0; s < int(cut->subcells.size()); ++s) EXPECT_GT(cut->referenceMeasure(s), 1e-14);
    }
}

// No sub-cell straddles an interface where the interface exists.
void checkSides(const XfemModel& xm) {
    for (int c : xm.xfemCells()) {
        const CellCut* cut = xm.cut(c);
        for (size_t j = 0; j < cut->cracks.size(); ++j)
            for (const auto& sub : cut->subcells) {
                if (sub.heaviside[j] == 0) continue;
                for (int v = 0; v < cut->vertexCount(); ++v) {
                    const double l = cut->points[sub.vertices[v]].lsn[j];
                    EXPECT_GE(l * sub.heaviside[j], -1e-12) << "cell " << c << " crack " << j;
                }
            }
    }
}

}  // namespace

TEST(XfemLevelSet, SnappingMovesNearbyNodesOntoTheInterface) {
    auto mesh = xfemtest::square(5, CellType::QUAD4);
    msg().setEcho(false);
    // Interface at 1e-7 (relative to h = 2) below the row y = 1: snapped; 1e-5: kept.
    for (double eps : {1e-7, 1e-5}) {
        auto ls = levelSet(*mesh, [&](double, double y, double) { return y - (1 - 2 * eps); });
        auto c = buildCrack(mesh, ls, nullptr);
        const int n = nodeAt(*mesh, 3, 1);
        if (eps < 1e-6) {
            EXPECT_EQ(c->lsn[n], 0.0);
            EXPECT_EQ(c->adjustedLevelSets, 6);
        } else {
            EXPECT_NEAR(c->lsn[n], 2 * eps, 1e-15);
            EXPECT_EQ(c->adjustedLevelSets, 0);
        }
    }
}

TEST(XfemCrack, Ssnv511QuadStatusesAndJunction) {
    auto mesh = xfemtest::square(5, CellType::QUAD4);
    auto j = xfemtest::ssnv511Cracks(mesh);
    // FISS1 cuts the row of 5 QUAD4 and the 2 boundary segments crossing y = 0.
    EXPECT_EQ(j.fiss1->cutCells.size(), 7u);
    std::set<std::pair<double, double>> f1, f2, f3;
    for (double x : {-5, -3, -1, 1, 3, 5})
        for (double y : {-1, 1}) f1.insert({x, y});
    for (double y : {-1, 1, 3, 5})
        for (double x : {-1, 1}) f2.insert({x, y});
    for (double y : {-5, -3, -1, 1})
        for (double x : {-1, 1}) f3.insert({x, y});
    EXPECT_EQ(enrichedXY(*j.fiss1), f1);
    EXPECT_EQ(enrichedXY(*j.fiss2), f2);
    EXPECT_EQ(enrichedXY(*j.fiss3), f3);
    ASSERT_EQ(j.fiss2->masters.size(), 1u);
    EXPECT_EQ(j.fiss2->masters[0].coef, -1.0);
    EXPECT_EQ(j.fiss3->masters[0].coef, 1.0);
    // Heaviside cells of FISS1: the three rows around y = 0 (15 QUAD4) and 3 + 3 segments of LG/LD
    // touching an enriched node.
    EXPECT_EQ(j.fiss1->heavisideCells.size(), 15u + 6u);
}

TEST(XfemCrack, Errors) {
    auto mesh = xfemtest::square(5, CellType::QUAD4);
    EXPECT_THROW(buildCrack(mesh, levelSet(*mesh, [](double, double y, double) { return y - 20; }), nullptr),
                 UserError);
    auto f1 = buildCrack(mesh, levelSet(*mesh, [](double, double y, double) { return y - 1; }), nullptr);
    JunctionInput in;
    in.masters = {f1};
    auto lsn2 = [&] { return levelSet(*mesh, [](double x, double, double) { return x; }); };
    in.point = {0.1, 1.0, 0};  // on FISS1
    EXPECT_THROW(buildCrack(mesh, lsn2(), &in), UserError);
    in.point = {0.1, 5.5, 0};  // outside the mesh
    EXPECT_THROW(buildCrack(mesh, lsn2(), &in), UserError);
    // Above FISS1, though its closest node (1, 1) lies on it: the side is the level set's at the point.
    in.point = {0.1, 1.2, 0};
    const auto branch = buildCrack(mesh, lsn2(), &in);
    ASSERT_EQ(branch->masters.size(), 1u);
    EXPECT_EQ(branch->masters[0].coef, -1.0);
}

TEST(XfemModel, Ssnv511QuadSlotsAndSubcells) {
    auto mesh = xfemtest::square(5, CellType::QUAD4);
    auto j = xfemtest::ssnv511Cracks(mesh);
    const Model mo = xfemtest::model(mesh);
    XfemModel xm(mo, {j.fiss1, j.fiss2, j.fiss3});
    // 21 X-FEM QUAD4: all but the 4 corners.
    EXPECT_EQ(xm.xfemCells().size(), 21u);
    for (double x : {-1, 1})
        for (double y : {-1, 1}) EXPECT_EQ(xm.activeSlots(nodeAt(*mesh, x, y)), 3) << x << "," << y;
    EXPECT_EQ(xm.activeSlots(nodeAt(*mesh, -3, 1)), 1);
    EXPECT_EQ(xm.nodeSlots(nodeAt(*mesh, -3, 1)), 4);  // in an XH3 element: H1..H3, two inactive
    EXPECT_EQ(xm.activeSlots(nodeAt(*mesh, -1, 3)), 1);
    EXPECT_EQ(xm.nodeSlots(nodeAt(*mesh, -1, 5)), 2);  // only in XH elements
    EXPECT_EQ(xm.nodeSlots(nodeAt(*mesh, -5, 5)), 1);  // corner: classical
    EXPECT_EQ(xm.nodeSlots(nodeAt(*mesh, -5, 3)), 2);  // in an XH element, inactive H1
    // Central cell: 3x3 multi-crack block, element types XH3 / XH.
    int central = -1;
    for (int c : xm.xfemCells()) {
        const auto cn = mesh->cellNodes(c);
        if (cn[0] == nodeAt(*mesh, -1, -1)) central = c;
    }
    ASSERT_GE(central, 0);
    EXPECT_EQ(xm.cellHeavisideCount(central), 3);
    EXPECT_EQ(xm.cut(central)->cracks.size(), 3u);
    EXPECT_EQ(xm.subcellRule(central), "FPG4");
    // Mono node on the - side of FISS1 below the left edge: psi = +2 above.
    const auto* e = xm.node(nodeAt(*mesh, -5, -1));
    ASSERT_TRUE(e);
    ASSERT_EQ(e->slotValue.size(), 1u);
    EXPECT_EQ(e->slotValue[0], 2.0);
    EXPECT_EQ(xm.node(nodeAt(*mesh, -5, 1))->slotValue[0], -2.0);
    // Inactive slots: nodes of XH3 elements with fewer active cracks.
    const auto inactive = xm.inactiveSlots();
    EXPECT_TRUE(std::count(inactive.begin(), inactive.end(), std::make_pair(nodeAt(*mesh, -3, 1), 2)));
    EXPECT_TRUE(std::count(inactive.begin(), inactive.end(), std::make_pair(nodeAt(*mesh, -5, 3), 1)));
    EXPECT_FALSE(std::count(inactive.begin(), inactive.end(), std::make_pair(nodeAt(*mesh, 1, 1), 1)));
    EXPECT_GT(xm.smallestRetainedFraction(), 0.01) << "smallest retained fraction";
    checkTiling(xm);
    checkSides(xm);
    EXPECT_GT(checkRigidBlocks(xm, 0, 0), 500);
}

TEST(XfemModel, OrderRule) {
    auto mesh = xfemtest::square(5, CellType::QUAD4);
    auto j = xfemtest::ssnv511Cracks(mesh);
    const Model mo = xfemtest::model(mesh);
    EXPECT_THROW(XfemModel(mo, {j.fiss2, j.fiss1, j.fiss3}), UserError);
    EXPECT_THROW(XfemModel(mo, {j.fiss2, j.fiss3}), UserError);
    EXPECT_THROW(XfemModel(mo, {j.fiss1, j.fiss1}), UserError);
}

TEST(XfemModel, RigidBlocksOnEveryCellType) {
    for (auto kind : {CellType::TRIA3, CellType::QUAD4}) {
        for (int n : {5, 6, 7, 12}) {
            auto mesh = xfemtest::square(n, kind);
            for (auto [x0, y0] : {std::pair{0.0, 0.0}, std::pair{0.37, -0.61}}) {
                auto j = xfemtest::ssnv511Cracks(mesh, x0, y0);
                XfemModel xm(xfemtest::model(mesh), {j.fiss1, j.fiss2, j.fiss3});
                checkTiling(xm);
                checkSides(xm);
                EXPECT_GT(checkRigidBlocks(xm, x0, y0), 100) << cellTypeName(kind) << " n=" << n;
            }
        }
    }
    for (auto kind : {CellType::HEXA8, CellType::TETRA4}) {
        for (int n : {5, 6}) {
            auto mesh = xfemtest::slab(n, kind);
            auto j = xfemtest::ssnv511Cracks(mesh);
            XfemModel xm(xfemtest::model(mesh), {j.fiss1, j.fiss2, j.fiss3});
            checkTiling(xm);
            checkSides(xm);
            EXPECT_GT(checkRigidBlocks(xm, 0, 0), 100) << cellTypeName(kind) << " n=" << n;
            if (kind == CellType::HEXA8) {
                // The central hexahedron: rule FPG5 on sub-tetrahedra (multi-crack element).
                for (int c : xm.xfemCells())
                    if (xm.cut(c)->cracks.size() == 3) { EXPECT_EQ(xm.subcellRule(c), "FPG5"); }
            }
        }
    }
}

TEST(XfemModel, InterfaceThroughNodesAndNearNodes) {
    // n even: x = 0 and y = 0 are node rows; the junction point is a node.
    auto mesh = xfemtest::square(6, CellType::QUAD4);
    auto j = xfemtest::ssnv511Cracks(mesh);
    XfemModel xm(xfemtest::model(mesh), {j.fiss1, j.fiss2, j.fiss3});
    // Only the nodes on the interfaces are enriched; the junction node carries 3 enrichments.
    EXPECT_EQ(xm.activeSlots(nodeAt(*mesh, 0, 0)), 3);
    EXPECT_EQ(xm.activeSlots(nodeAt(*mesh, 10.0 / 6 - 5 + 5 - 10.0 / 6, 10.0 / 6)), 1);
    EXPECT_EQ(j.fiss1->nodeStatus[nodeAt(*mesh, 5 - 10.0 / 6 * 6, 10.0 / 6)], 0);
    checkTiling(xm);
    checkSides(xm);
    EXPECT_GT(checkRigidBlocks(xm, 0, 0), 100);
    // An interface at eps * h from a row of nodes, eps = 1e-1 ... 1e-9: FISS1 moved up (junction
    // eps * h above the node (0, 0)), or FISS2/FISS3 moved left. (Both at once would put the
    // junction within code_aster's 1e-4 L_ref snapping of intersection points, which moves the
    // discrete junction by up to 1e-4 h: the blocks stay exact but not at their exact place.)
    for (int e = 1; e <= 9; ++e) {
        const double eps = std::pow(10.0, -e);
        const double h = 10.0 / 6;
        for (int variant = 0; variant < 2; ++variant) {
            const double y0 = variant == 0 ? h * eps : 0.0, x0 = variant == 1 ? -h * eps : 0.0;
            for (auto kind : {CellType::QUAD4, CellType::TRIA3}) {
                auto m2 = xfemtest::square(6, kind);
                auto jj = xfemtest::ssnv511Cracks(m2, x0, y0);
                XfemModel xm2(xfemtest::model(m2), {jj.fiss1, jj.fiss2, jj.fiss3});
                checkTiling(xm2);
                checkSides(xm2);
                // Snapped (eps < 1e-6): the blocks are bounded by the node rows.
                const bool snapped = eps < 1e-6;
                EXPECT_GT(checkRigidBlocks(xm2, snapped ? 0.0 : x0, snapped ? 0.0 : y0), 100) << "eps " << eps;
                EXPECT_GT(xm2.smallestRetainedFraction(), 0.0);
                EXPECT_LE(xm2.smallestRetainedFraction(), 1.0);
                if (!snapped && eps > 1e-6) { EXPECT_LT(xm2.smallestRetainedFraction(), 10 * eps) << "eps " << eps; }
            }
        }
    }
}

// Interfaces eps*h from the node rows in both directions (the stability sweep's offsets): the
// junction sits eps*h from a node in a corner of its cell, where the branch's cut meets sub-cell
// edges at angles of ~eps. The cut must stay exact there: no piece dropped, the sub-cells tile the
// parent, and every vertex lies on the side of each interface that its sub-cell's digit says. Before,
// CellCut merged the junction point with a point of another edge eps^2 h off the master (QUAD4: a
// vertex of the - side 1e-10 above FISS1) or moved a zero off its edge (TRIA3, TETRA4: holes of 1e-10
// of the cell), and dropped real slivers below 1e-14 of the cell (HEXA8, TETRA4: up to 4e-15 of the
// cell, a relative part of the eps^2 corner block): energy errors up to 5e-9 with contact.
TEST(XfemModel, JunctionNextToANodeIsCutExactly) {
    for (CellType type : {CellType::QUAD4, CellType::TRIA3, CellType::HEXA8, CellType::TETRA4})
        for (double eps : {1e-4, 3e-5, 1e-5, 3e-6}) {  // (1e-6: DEFI_FISS_XFEM snaps the level set to the nodes)
            SCOPED_TRACE(std::string(cellTypeName(type)) + " eps=" + std::to_string(eps));
            const bool threeD = type == CellType::HEXA8 || type == CellType::TETRA4;
            auto mesh = threeD ? xfemtest::slab(10, type) : xfemtest::square(10, type);  // node rows on the integers
            const auto j = xfemtest::ssnv511Cracks(mesh, -eps, -eps);
            XfemModel xm(xfemtest::model(mesh), {j.fiss1, j.fiss2, j.fiss3});
            const double parent = type == CellType::QUAD4   ? 4.0
                                  : type == CellType::TRIA3 ? 0.5
                                  : type == CellType::HEXA8 ? 8.0
                                                            : 1.0 / 6.0;
            double smallest = 1.0;
            int junctionPoints = 0;
            for (int c : xm.xfemCells()) {
                const CellCut* cut = xm.cut(c);
                EXPECT_EQ(cut->droppedDegenerate, 0) << "cell " << c;
                double sum = 0.0;
                for (int s = 0; s < int(cut->subcells.size()); ++s) {
                    sum += cut->referenceMeasure(s);
                    smallest = std::min(smallest, cut->referenceMeasure(s) / parent);
                }
                EXPECT_NEAR(sum, parent, 1e-14 * parent) << "cell " << c;
                std::vector<std::array<double, 3>> nodes;
                for (int n : mesh->cellNodes(c)) nodes.push_back(mesh->coords[n]);
                // exact level sets: FISS1 y + eps, FISS2 and FISS3 x + eps (cell's crack order)
                auto level = [&](int k, const std::array<double, 3>& x) {
                    return cut->cracks[k] == 0 ? x[1] + eps : x[0] + eps;
                };
                for (const auto& sub : cut->subcells)
                    for (int v = 0; v < cut->vertexCount(); ++v) {
                        const auto x = mapToPhysical(cut->type, nodes, cut->points[sub.vertices[v]].ref);
                        for (size_t k = 0; k < cut->cracks.size(); ++k)
                            if (sub.heaviside[k] != 0) {
                                EXPECT_GE(sub.heaviside[k] * level(int(k), x), -1e-14)
                                    << "cell " << c << " crack " << k;
                            }
                    }
                for (const auto& p : cut->points)
                    if (cut->cracks.size() == 3 && p.lsn[0] == 0.0 && p.lsn[1] == 0.0) {
                        ++junctionPoints;
                        const auto x = mapToPhysical(cut->type, nodes, p.ref);
                        EXPECT_NEAR(x[0], -eps, 1e-15);
                        EXPECT_NEAR(x[1], -eps, 1e-15);
                    }
            }
            // the corner block (eps^2 of the cell) and the slivers next to it are kept, and the
            // junction point is there
            EXPECT_LE(smallest, 1.01 * eps * eps);
            EXPECT_GT(junctionPoints, 0);
        }
}
