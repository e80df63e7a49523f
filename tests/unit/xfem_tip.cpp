// Crack-tip enrichment pieces (src/xfem/TipEnrichment): the Williams fields and their gradients,
// the Gauss-Legendre and collapsed triangle rules that integrate the tip elements.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

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
}  // namespace
}  // namespace ma::xfem
