// The X-FEM sub-cell rules and their expert override (`miniaster run --subcell-quadrature`,
// src/xfem/SubcellQuadrature.hpp): the rule chosen per degree, the rule each X-FEM cell of a model
// uses, the parent measure integrated exactly with every degree, and element stiffnesses that do not
// depend on the rule where the integrand is of low degree.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"
#include "fe/ElementKinematics.hpp"
#include "fe/Quadrature.hpp"
#include "xfem/CellGeometry.hpp"
#include "xfem_test_meshes.hpp"

using namespace ma;
using namespace ma::xfem;

namespace {

// Element stiffness of plane-strain / 3D isotropic elasticity (lambda = 1, mu = 1) on the points of
// `ei`: K[(a,k,i), (b,l,j)] = sum_p w psi_ak psi_bl (lambda dN_a/dx_i dN_b/dx_j + mu (delta_ij
// gradN_a . gradN_b + dN_a/dx_j dN_b/dx_i)). Rows in (node, slot, component) order.
std::vector<double> stiffness(const Mesh& mesh, int cell, int dim, const ElementIntegration& ei) {
    PointGeometry geo;
    computePointGeometry(mesh, cell, dim, false, ei, geo);
    const int n = ei.nodeCount;
    std::vector<int> first(n + 1, 0);
    for (int a = 0; a < n; ++a) first[a + 1] = first[a] + ei.slots[a] * dim;
    const int size = first[n];
    std::vector<double> K(size_t(size) * size, 0.0);
    const double lambda = 1.0, mu = 1.0;
    for (size_t p = 0; p < ei.refPoints.size(); ++p) {
        const double* g = &geo.gradN[p * n * 3];
        for (int a = 0; a < n; ++a)
            for (int k = 0; k < ei.slots[a]; ++k)
                for (int b = 0; b < n; ++b)
                    for (int l = 0; l < ei.slots[b]; ++l) {
                        const double w = geo.weight[p] * ei.multiplier(int(p), a, k) * ei.multiplier(int(p), b, l);
                        if (w == 0.0) continue;
                        double dot = 0;
                        for (int m = 0; m < dim; ++m) dot += g[3 * a + m] * g[3 * b + m];
                        for (int i = 0; i < dim; ++i)
                            for (int j = 0; j < dim; ++j) {
                                const double v = lambda * g[3 * a + i] * g[3 * b + j] +
                                                 mu * ((i == j ? dot : 0.0) + g[3 * a + j] * g[3 * b + i]);
                                K[size_t(first[a] + k * dim + i) * size + first[b] + l * dim + j] += w * v;
                            }
                    }
    }
    return K;
}

double maxAbs(const std::vector<double>& v) {
    double m = 0;
    for (double x : v) m = std::max(m, std::abs(x));
    return m;
}

double maxDifference(const std::vector<double>& a, const std::vector<double>& b) {
    double m = 0;
    for (size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
    return m;
}

// Physical measure of a parent cell from its primary simplices.
double cellMeasure(const Mesh& m, int cell) {
    const CellType t = m.cellTypes[cell];
    std::vector<std::array<double, 3>> x;
    for (int n : m.cellNodes(cell)) x.push_back(m.coords[n]);
    double sum = 0;
    for (const auto& s : primarySimplices(t)) {
        std::vector<std::array<double, 3>> v;
        for (int i : s) v.push_back(x[i]);
        sum += std::abs(simplexMeasure(cellDimension(t), v));
    }
    return sum;
}

// The four ssnv511-type X-FEM models, with their skin (boundary) elements.
struct Scene {
    std::shared_ptr<Mesh> mesh;
    xfemtest::Junction3 cracks;
    Model model;
};

Scene scene(CellType kind, int n, double x0 = 0, double y0 = 0) {
    Scene s;
    s.mesh = cellDimension(kind) == 2 ? xfemtest::square(n, kind) : xfemtest::slab(n, kind);
    s.cracks = xfemtest::ssnv511Cracks(s.mesh, x0, y0);
    s.model = xfemtest::model(s.mesh, true);
    return s;
}

XfemModel xfemModel(const Scene& s, int degree) {
    return XfemModel(s.model, {s.cracks.fiss1, s.cracks.fiss2, s.cracks.fiss3}, XfemContact::None, 1e-15, degree);
}

}  // namespace

TEST(XfemSubcellQuadrature, LowestRuleOfEachDegree) {
    const std::vector<std::string> tria{"FPG1", "FPG3", "FPG4", "FPG6", "FPG7", "FPG12"};
    const std::vector<std::string> tetra{"FPG1", "FPG4", "FPG5", "FPG15", "FPG15", "FPG24"};
    ASSERT_EQ(kMaxSubcellDegree, 6);  // the range the supervisor accepts (parser/Supervisor.cpp)
    for (int d = 1; d <= kMaxSubcellDegree; ++d) {
        EXPECT_EQ(lowestRuleOfDegree(CellType::TRIA3, d), tria[d - 1]) << d;
        EXPECT_EQ(lowestRuleOfDegree(CellType::TETRA4, d), tetra[d - 1]) << d;
        for (CellType t : {CellType::TRIA3, CellType::TETRA4}) {
            const auto& rule = quadratureRule(t, lowestRuleOfDegree(t, d));
            EXPECT_GE(rule.degree, d);
            if (d > 1) {  // the rule of degree d - 1 is not enough, or it is the same rule
                const auto& lower = quadratureRule(t, lowestRuleOfDegree(t, d - 1));
                EXPECT_TRUE(lower.degree < d || lower.family == rule.family) << cellTypeName(t) << " " << d;
            }
        }
    }
    EXPECT_THROW(lowestRuleOfDegree(CellType::TRIA3, 0), UserError);
    EXPECT_THROW(lowestRuleOfDegree(CellType::TETRA4, kMaxSubcellDegree + 1), UserError);
}

TEST(XfemSubcellQuadrature, CatalogueAndOverridePerKind) {
    // Catalogue (xfem_spec §3.6).
    EXPECT_EQ(subcellRule({2, false, false}, 0), "FPG12");
    EXPECT_EQ(subcellRule({2, false, true}, 0), "FPG4");
    EXPECT_EQ(subcellRule({3, false, false}, 0), "FPG15");
    EXPECT_EQ(subcellRule({3, false, true}, 0), "FPG5");
    EXPECT_EQ(subcellRule({1, true, false}, 0), "FPG4");
    EXPECT_EQ(subcellRule({1, true, true}, 0), "FPG2");
    EXPECT_EQ(subcellRule({2, true, false}, 0), "FPG12");
    EXPECT_EQ(subcellRule({2, true, true}, 0), "FPG12");
    for (int d = 1; d <= kMaxSubcellDegree; ++d)
        for (bool several : {false, true}) {
            // Volume sub-cells follow the degree, whatever the number of interfaces.
            EXPECT_EQ(subcellRule({2, false, several}, d), lowestRuleOfDegree(CellType::TRIA3, d));
            EXPECT_EQ(subcellRule({3, false, several}, d), lowestRuleOfDegree(CellType::TETRA4, d));
            // Skin sub-cells keep the catalogue's rule.
            EXPECT_EQ(subcellRule({1, true, several}, d), catalogueSubcellRule({1, true, several}));
            EXPECT_EQ(subcellRule({2, true, several}, d), "FPG12");
        }
}

TEST(XfemSubcellQuadrature, EveryCellOfTheModelUsesTheRuleOfTheDegree) {
    for (CellType kind : {CellType::TRIA3, CellType::QUAD4, CellType::TETRA4, CellType::HEXA8}) {
        const Scene s = scene(kind, 5);
        const CellType simplex = cellDimension(kind) == 2 ? CellType::TRIA3 : CellType::TETRA4;
        for (int d = 0; d <= kMaxSubcellDegree; ++d) {
            const XfemModel xm = xfemModel(s, d);
            EXPECT_EQ(xm.subcellDegree(), d);
            int skin = 0, volume = 0;
            ElementIntegration ei;
            for (int c : xm.xfemCells()) {
                const CellCut* cut = xm.cut(c);
                const SubcellKind k = xm.subcellKind(c);
                EXPECT_EQ(k.skin, cut->skin);
                EXPECT_EQ(k.severalCracks, cut->cracks.size() > 1);
                const std::string expected =
                    d == 0 || cut->skin ? catalogueSubcellRule(k) : lowestRuleOfDegree(simplex, d);
                EXPECT_EQ(xm.subcellRule(c), expected) << cellTypeName(kind) << " degree " << d << " cell " << c;
                xm.integration(c, ei);
                const int perSubcell = quadratureRule(subcellType(k), expected).size();
                EXPECT_EQ(ei.refPoints.size(), cut->subcells.size() * perSubcell);
                (cut->skin ? skin : volume) += 1;
            }
            EXPECT_GT(volume, 0);
            // The 2D squares have boundary segments (the 3D test slab has no skin faces).
            if (cellDimension(kind) == 2) { EXPECT_GT(skin, 0) << "the scene has cut boundary cells"; }
        }
    }
    EXPECT_THROW(xfemModel(scene(CellType::QUAD4, 5), kMaxSubcellDegree + 1), UserError);
    EXPECT_THROW(xfemModel(scene(CellType::QUAD4, 5), -1), UserError);
}

TEST(XfemSubcellQuadrature, ParentMeasureIsIntegratedExactlyWithEveryDegree) {
    // Junction off the node rows and off the cell centres: sub-cells of every shape.
    for (CellType kind : {CellType::TRIA3, CellType::QUAD4, CellType::TETRA4, CellType::HEXA8}) {
        const Scene s = scene(kind, cellDimension(kind) == 2 ? 7 : 5, 0.37, -0.61);
        for (int d = 0; d <= kMaxSubcellDegree; ++d) {
            const XfemModel xm = xfemModel(s, d);
            ElementIntegration ei;
            PointGeometry geo;
            int checked = 0;
            for (int c : xm.xfemCells()) {
                if (xm.cut(c)->skin) continue;
                xm.integration(c, ei);
                computePointGeometry(*s.mesh, c, s.model.dim, false, ei, geo);
                double measure = 0;
                for (double w : geo.weight) measure += w;
                const double exact = cellMeasure(*s.mesh, c);
                EXPECT_NEAR(measure, exact, 1e-13 * exact) << cellTypeName(kind) << " degree " << d << " cell " << c;
                ++checked;
            }
            EXPECT_GT(checked, 10);
        }
    }
}

TEST(XfemSubcellQuadrature, CutCellStiffnessDoesNotDependOnTheRuleWhereTheIntegrandAllows) {
    // TRIA3 parent: constant strains, every rule is exact. QUAD4 parent (squares): the integrand is
    // quadratic in the reference coordinates of a sub-triangle, so degree 2 is exact and degree 1
    // is not (the test would not see a rule that is ignored).
    struct Case {
        CellType kind;
        int low;
        bool lowIsExact;
    };
    for (const Case& t : {Case{CellType::TRIA3, 1, true}, Case{CellType::TRIA3, 2, true},
                          Case{CellType::QUAD4, 2, true}, Case{CellType::QUAD4, 1, false}}) {
        const Scene s = scene(t.kind, 7, 0.37, -0.61);
        const XfemModel low = xfemModel(s, t.low), high = xfemModel(s, 6), catalogue = xfemModel(s, 0);
        int cutCells = 0;
        double worst = 0;
        ElementIntegration a, b, c;
        for (int cell : low.xfemCells()) {
            if (low.cut(cell)->skin || low.cut(cell)->subcells.size() < 3) continue;  // cut volume cells
            low.integration(cell, a);
            high.integration(cell, b);
            catalogue.integration(cell, c);
            ASSERT_LT(a.refPoints.size(), b.refPoints.size());  // the rules differ
            const auto Ka = stiffness(*s.mesh, cell, 2, a), Kb = stiffness(*s.mesh, cell, 2, b);
            const auto Kc = stiffness(*s.mesh, cell, 2, c);
            const double scale = maxAbs(Kb);
            ASSERT_GT(scale, 0.1);
            EXPECT_LE(maxDifference(Kb, Kc), 1e-13 * scale) << "degree 6 vs catalogue, cell " << cell;
            worst = std::max(worst, maxDifference(Ka, Kb) / scale);
            ++cutCells;
        }
        EXPECT_GT(cutCells, 5);
        if (t.lowIsExact) {
            EXPECT_LE(worst, 1e-13) << cellTypeName(t.kind) << " degree " << t.low << " vs 6";
        } else {
            EXPECT_GT(worst, 1e-3) << cellTypeName(t.kind) << " degree " << t.low << " vs 6";
        }
    }
}
