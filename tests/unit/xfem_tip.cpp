// Crack-tip enrichment pieces (src/xfem/TipEnrichment): the Williams fields and their gradients,
// the Gauss-Legendre and collapsed triangle rules that integrate the tip elements, the fields of an
// element's tip nodes (each its own tip's, 2D).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "mesh/ShapeFunctions.hpp"
#include "scenes/Ssnv511Mesh.hpp"
#include "xfem/TipEnrichment.hpp"

namespace ma::xfem {
namespace {

// The fields against code_aster's xdeffk formulas and their derivatives against central differences
// in the local Cartesian coordinates, on both sides of the crack.
TEST(XfemTip, WilliamsFieldsAndGradients) {
    const double kappa = 1.8, mu = 76923.0;
    for (double theta : {-3.0, -2.0, -0.7, 0.0, 0.4, 1.9, 3.1}) {
        for (double r : {0.01, 0.3, 2.0}) {
            const AsymptoticFields f = asymptoticFields(r, theta, 3);
            const double rr = std::sqrt(r) / (2 * mu * std::sqrt(2 * std::numbers::pi));
            auto F = [&](int m, int k) { return (kappa * f.A[m][k] + f.B[m][k]) / (2 * mu); };
            EXPECT_NEAR(F(0, 0), rr * (kappa - std::cos(theta)) * std::cos(theta / 2), 1e-15);
            EXPECT_NEAR(F(0, 1), rr * (kappa - std::cos(theta)) * std::sin(theta / 2), 1e-15);
            EXPECT_NEAR(F(1, 0), rr * (kappa + 2 + std::cos(theta)) * std::sin(theta / 2), 1e-15);
            EXPECT_NEAR(F(1, 1), rr * (2 - kappa - std::cos(theta)) * std::cos(theta / 2), 1e-15);
            EXPECT_NEAR(F(2, 2), 4 * rr * std::sin(theta / 2), 1e-15);
            const double x1 = r * std::cos(theta), x2 = r * std::sin(theta), h = 1e-6 * r;
            for (int l = 0; l < 2; ++l) {
                const double ya = x1 + (l == 0 ? h : 0), yb = x2 + (l == 1 ? h : 0);
                const double za = x1 - (l == 0 ? h : 0), zb = x2 - (l == 1 ? h : 0);
                const auto p = asymptoticFields(std::hypot(ya, yb), std::atan2(yb, ya), 3);
                const auto q = asymptoticFields(std::hypot(za, zb), std::atan2(zb, za), 3);
                for (int m = 0; m < 3; ++m)
                    for (int k = 0; k < 3; ++k) {
                        const double scale = std::sqrt(1.0 / r);
                        EXPECT_NEAR(f.dA[m][k][l], (p.A[m][k] - q.A[m][k]) / (2 * h), 1e-7 * scale) << m << k << l;
                        EXPECT_NEAR(f.dB[m][k][l], (p.B[m][k] - q.B[m][k]) / (2 * h), 1e-7 * scale) << m << k << l;
                    }
            }
        }
    }
}

TEST(XfemTip, GaussLegendreIsExactToDegree2nMinus1) {
    for (int n : {1, 2, 5, 12, 20}) {
        std::vector<double> x, w;
        gaussLegendre01(n, x, w);
        for (int d = 0; d <= 2 * n - 1; ++d) {
            double sum = 0;
            for (int i = 0; i < n; ++i) sum += w[size_t(i)] * std::pow(x[size_t(i)], d);
            EXPECT_NEAR(sum, 1.0 / (d + 1), 1e-14) << n << " " << d;
        }
    }
}

// The rule collapsed at a vertex integrates the triangle's polynomials, and with rho = s^2 the
// singular 1/r and r^-1/2 about that vertex: the right triangle (0,0), (1,0), (0,1) gives
// int 1/r = sqrt(2) ln(1 + sqrt(2)); int r^-1/2 = int_0^{pi/2} (2/3) rho(theta)^{3/2} dtheta with
// rho = 1 / (cos + sin), by a 2000-point midpoint sum of the smooth angular integral. 48 points per
// direction as the engine's fans (XfemModel::kTipGaussPoints x 4); 12 leave 2.2e-10 on int 1/r (the
// angular factor 1/|P(t)| is smooth, not polynomial).
TEST(XfemTip, CollapsedRuleIntegratesTheTipSingularity) {
    std::vector<std::array<double, 3>> pts;
    std::vector<double> w;
    collapsedTriangleRule({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 48, true, pts, w);
    double one = 0, xy = 0, inv = 0, invSqrt = 0;
    for (size_t i = 0; i < w.size(); ++i) {
        const double r = std::hypot(pts[i][0], pts[i][1]);
        one += w[i], xy += w[i] * pts[i][0] * pts[i][1] * pts[i][1];
        inv += w[i] / r, invSqrt += w[i] / std::sqrt(r);
    }
    EXPECT_NEAR(one, 0.5, 1e-14);
    EXPECT_NEAR(xy, 1.0 / 60, 1e-14);
    EXPECT_NEAR(inv, std::sqrt(2.0) * std::log(1 + std::sqrt(2.0)), 1e-13);
    double ref = 0;
    const int n = 2000;
    for (int i = 0; i < n; ++i) {
        const double t = (i + 0.5) * (std::numbers::pi / 2) / n;
        ref += (2.0 / 3.0) * std::pow(1.0 / (std::cos(t) + std::sin(t)), 1.5) * (std::numbers::pi / 2) / n;
    }
    EXPECT_NEAR(invSqrt, ref, 1e-7);
    // The plain collapsed rule (rho linear) integrates a degree-11 polynomial of the triangle.
    pts.clear(), w.clear();
    collapsedTriangleRule({0.2, 0.1, 0}, {1, 0.3, 0}, {0.4, 1, 0}, 6, false, pts, w);
    double area = 0;
    for (double v : w) area += v;
    EXPECT_NEAR(area, 0.5 * std::abs(0.8 * 0.9 - 0.2 * 0.2), 1e-15);
}

// The fanned rule of a 3D tip sub-cell (fannedTetrahedronRule): exact volume and second moment
// whether the front line crosses the tetrahedron, lies along an edge, in a face's plane or outside
// it; and the 1/r singularity of an edge on the line against its closed form.
TEST(XfemTip, FannedTetrahedronRuleIntegratesTheFrontSingularity) {
    const std::array<std::array<double, 3>, 4> T{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    struct Line {
        Vec3 O, t;
    };
    const double s3 = 1.0 / std::sqrt(3.0);
    const Line lines[] = {{{0.2, 0.2, 0}, {0, 0, 1}},         // through the inside
                          {{0, 0, 0}, {0, 0, 1}},             // along an edge
                          {{0.3, 0, 0}, {0, 0, 1}},           // in the plane of a face
                          {{2.0, -1.0, 0.5}, {s3, s3, s3}}};  // outside
    for (const Line& l : lines) {
        std::vector<std::array<double, 3>> pts;
        std::vector<double> w;
        fannedTetrahedronRule(T, l.O, l.t, 6, 10, pts, w);
        double volume = 0, xx = 0;
        for (size_t q = 0; q < w.size(); ++q) volume += w[q], xx += w[q] * pts[q][0] * pts[q][0];
        EXPECT_NEAR(volume, 1.0 / 6.0, 1e-14);
        EXPECT_NEAR(xx, 1.0 / 60.0, 1e-14);
    }
    // Edge (0,0,0)-(0,0,1) on the line: int 1/r = int_0^{pi/2} dphi / (2 (cos + sin)) = ln(1 + sqrt 2) / sqrt 2.
    for (int n : {4, 8}) {
        std::vector<std::array<double, 3>> pts;
        std::vector<double> w;
        fannedTetrahedronRule(T, {0, 0, 0}, {0, 0, 1}, n, 2 * n, pts, w);
        double sum = 0;
        for (size_t q = 0; q < w.size(); ++q) sum += w[q] / std::hypot(pts[q][0], pts[q][1]);
        EXPECT_NEAR(sum, std::log(1.0 + std::sqrt(2.0)) / std::sqrt(2.0), n == 4 ? 1e-6 : 1e-12) << n;
    }
}

// With the line parallel to faces of the tetrahedron (and crossing none of them within reach), the
// distance to the line is polynomial in the radial variables times an angular factor: the radial
// count does not change a (polynomial) / r integral once it is exact for the polynomial's degree.
TEST(XfemTip, FannedRuleIsExactAlongTheRaysOfFacesParallelToTheLine) {
    const std::array<std::array<double, 3>, 4> T{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    const Vec3 O{-0.3, 0.4, 0.0}, t{0, 0, 1};  // parallel to the faces x = 0 and y = 0
    auto integral = [&](int nRadial) {
        std::vector<std::array<double, 3>> pts;
        std::vector<double> w;
        fannedTetrahedronRule(T, O, t, nRadial, 8, pts, w);
        double sum = 0;
        for (size_t q = 0; q < w.size(); ++q) {
            const double x = pts[q][0], y = pts[q][1], z = pts[q][2];
            sum += w[q] * (1 + x * y + z * z) / std::hypot(x - O[0], y - O[1]);
        }
        return sum;
    };
    EXPECT_NEAR(integral(6), integral(12), 1e-14);
}

// A centre crack y = 0.1, |x| < 0.3, on a 4 x 4 grid of [-1, 1]^2 whose every node is a tip node:
// the nodes with x <= 0 take tip 1's basis, the others tip 2's. A cell holding both has two groups;
// each group's Phi is its tip's field minus its interpolation at all the cell's nodes, and a node's
// enrichment is the same seen from either cell of a shared edge.
TEST(XfemTip, EachTipNodeTakesItsOwnTipsFieldsInEveryCell) {
    Ssnv511MeshOptions o;
    o.divisions = 4;
    o.xmin = o.ymin = -1, o.xmax = o.ymax = 1;
    const auto mesh = buildSsnv511Mesh(o);
    const std::vector<FrontBasis> points = {{{-0.3, 0.1, 0}, {-1, 0, 0}, {0, 1, 0}},
                                            {{0.3, 0.1, 0}, {1, 0, 0}, {0, 1, 0}}};
    std::vector<int> front(size_t(mesh->nodeCount()));
    for (int n = 0; n < mesh->nodeCount(); ++n) front[size_t(n)] = mesh->coords[size_t(n)][0] <= 0 ? 0 : 1;
    const std::vector<unsigned char> status(size_t(mesh->nodeCount()), 2);
    const std::vector<char> tipNodes(size_t(mesh->nodeCount()), 1);
    const TipBases bases{nullptr, &points, &front};
    auto cellAt = [&](double x, double y) {  // the QUAD4 whose centre is (x, y)
        for (int c = 0; c < mesh->cellCount(); ++c) {
            if (mesh->cellTypes[size_t(c)] != CellType::QUAD4) continue;
            Vec3 m{};
            for (int n : mesh->cellNodes(c))
                for (int j = 0; j < 3; ++j) m[size_t(j)] += 0.25 * mesh->coords[size_t(n)][size_t(j)];
            if (distance(m, {x, y, 0}) < 1e-12) return c;
        }
        return -1;
    };
    // Phi of local node a (A part, [c][m]) at x in `cell`, and the cell's group count.
    auto phiAt = [&](int cell, int node, const Vec3& x, int& groups) {
        ElementIntegration ei;
        ei.cell = cell;
        ei.refPoints = {referenceCoordinates(*mesh, cell, x)};
        tipElementFields(*mesh, cell, 2, bases, status, tipNodes, {1}, ei);
        groups = ei.tipGroups;
        const auto nodes = mesh->cellNodes(cell);
        const size_t a = size_t(std::find(nodes.begin(), nodes.end(), node) - nodes.begin());
        EXPECT_LT(a, nodes.size());
        return std::vector<double>(ei.tipA.begin() + long(size_t(ei.tipGroupOf(int(a))) * 36),
                                   ei.tipA.begin() + long(size_t(ei.tipGroupOf(int(a))) * 36 + 9));
    };
    const int left = cellAt(-0.25, 0.25), right = cellAt(0.25, 0.25), far = cellAt(-0.75, 0.25);
    ASSERT_GE(left, 0);
    ASSERT_GE(right, 0);
    ASSERT_GE(far, 0);
    int node0 = -1;  // (0, 0.5): tip 1's, shared by both cells
    for (int n = 0; n < mesh->nodeCount(); ++n)
        if (distance(mesh->coords[size_t(n)], {0, 0.5, 0}) < 1e-12) node0 = n;
    ASSERT_GE(node0, 0);
    const Vec3 onEdge{0.0, 0.3, 0.0};
    int gl = 0, gr = 0, gf = 0;
    const auto fromLeft = phiAt(left, node0, onEdge, gl), fromRight = phiAt(right, node0, onEdge, gr);
    phiAt(far, mesh->cellNodes(far)[0], {-0.7, 0.3, 0}, gf);
    EXPECT_EQ(gl, 1);  // nodes x <= 0 only
    EXPECT_EQ(gr, 2);  // x = 0 and x = 0.5
    EXPECT_EQ(gf, 1);
    double largest = 0.0;
    for (int i = 0; i < 9; ++i) {
        EXPECT_NEAR(fromLeft[size_t(i)], fromRight[size_t(i)], 1e-14) << i;
        largest = std::max(largest, std::abs(fromLeft[size_t(i)]));
    }
    EXPECT_GT(largest, 1e-3);  // not zero on the edge: the nodal shift does not cancel the field there

    // Against the definition in the right cell: tip 2's node (0.5, 0.5) takes tip 2's field.
    int node1 = -1;
    for (int n = 0; n < mesh->nodeCount(); ++n)
        if (distance(mesh->coords[size_t(n)], {0.5, 0.5, 0}) < 1e-12) node1 = n;
    const Vec3 x{0.2, 0.35, 0.0};
    const auto phi1 = phiAt(right, node1, x, gr), phi0 = phiAt(right, node0, x, gr);
    const auto nodes = mesh->cellNodes(right);
    std::vector<double> N(4);
    shapeValues(CellType::QUAD4, referenceCoordinates(*mesh, right, x), N);
    for (int t = 0; t < 2; ++t) {
        const FrontBasis& b = points[size_t(t)];
        auto local = [&](const Vec3& y) {  // the A part of the fields in t's basis, [m][k]
            const Vec3 d = difference(y, b.origin);
            const double x1 = dot(d, b.e1), x2 = dot(d, b.e2);
            return asymptoticFields(std::hypot(x1, x2), std::atan2(x2, x1), 2);
        };
        const AsymptoticFields f = local(x);
        for (int m = 0; m < 2; ++m)
            for (int c = 0; c < 2; ++c) {
                double expected = 0.0;
                for (int k = 0; k < 2; ++k) {
                    double shifted = f.A[m][k];
                    for (size_t n = 0; n < 4; ++n)
                        shifted -= N[n] * local(mesh->coords[size_t(nodes[n])]).A[m][size_t(k)];
                    expected += (k == 0 ? b.e1 : b.e2)[size_t(c)] * shifted;
                }
                EXPECT_NEAR((t == 0 ? phi0 : phi1)[size_t(c * 3 + m)], expected, 1e-13) << t << " " << c << m;
            }
    }
}
}  // namespace
}  // namespace ma::xfem
