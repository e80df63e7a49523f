// Crack geometry (issue 26, step 1): the level sets of every FORM_FISS against closed forms at the
// nodes of generated meshes, the node status and the cells containing the front, and the front of
// a straight and of a circular crack against the analytic front (docs/cracks.md).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/Error.hpp"
#include "xfem/Crack.hpp"
#include "xfem/CrackShapes.hpp"
#include "xfem_test_meshes.hpp"

using namespace ma;
using namespace ma::xfem;

namespace {

// [0,1]^3 in n^3 HEXA8 cells, or the annulus r0 <= r <= r1 (nr rings, nt sectors) x [0, 1]
// (nz layers) in HEXA8 cells whose vertical faces lie on rays from the axis.
std::shared_ptr<Mesh> box(int n) {
    auto m = std::make_shared<Mesh>();
    m->name = "BOX";
    auto id = [&](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) m->addNode({double(i) / n, double(j) / n, double(k) / n});
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                m->addCell(CellType::HEXA8, std::vector<int>{id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k),
                                                             id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1),
                                                             id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
    return m;
}

std::shared_ptr<Mesh> annulus(double r0, double r1, int nr, int nt, int nz) {
    auto m = std::make_shared<Mesh>();
    m->name = "ANNULUS";
    auto id = [&](int i, int t, int k) { return (k * nt + t % nt) * (nr + 1) + i; };
    for (int k = 0; k <= nz; ++k)
        for (int t = 0; t < nt; ++t)
            for (int i = 0; i <= nr; ++i) {
                const double r = r0 + (r1 - r0) * i / nr, a = 2 * std::numbers::pi * t / nt;
                m->addNode({r * std::cos(a), r * std::sin(a), double(k) / nz});
            }
    for (int k = 0; k < nz; ++k)
        for (int t = 0; t < nt; ++t)
            for (int i = 0; i < nr; ++i)
                m->addCell(CellType::HEXA8, std::vector<int>{id(i, t, k), id(i + 1, t, k), id(i + 1, t + 1, k),
                                                             id(i, t + 1, k), id(i, t, k + 1), id(i + 1, t, k + 1),
                                                             id(i + 1, t + 1, k + 1), id(i, t + 1, k + 1)});
    return m;
}

Vec3 unitVec(Vec3 v) {
    const double n = norm(v);
    return {v[0] / n, v[1] / n, v[2] / n};
}

// The signed distance to a rectangle with rounded corners written the other way round: the
// outside part of |p| - (a - r, b - r) plus the inside part, minus r.
double roundedBox(double x, double y, double a, double b, double r) {
    const double qx = std::abs(x) - (a - r), qy = std::abs(y) - (b - r);
    return std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) + std::min(std::max(qx, qy), 0.0) - r;
}

// Distance to the ellipse by brute force: the closest of 20000 parameters, then a ternary search
// of the distance around it.
double ellipseByNewton(double x, double y, double a, double b) {
    auto dist = [&](double t) { return std::hypot(x - a * std::cos(t), y - b * std::sin(t)); };
    const double step = 2 * std::numbers::pi / 20000;
    double best = 0, bestD = INFINITY;
    for (int k = 0; k < 20000; ++k)
        if (dist(k * step) < bestD) bestD = dist(k * step), best = k * step;
    double lo = best - step, hi = best + step;
    for (int it = 0; it < 200; ++it) {
        const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
        (dist(m1) < dist(m2) ? hi : lo) = dist(m1) < dist(m2) ? m2 : m1;
    }
    const double d = dist(0.5 * (lo + hi));
    return (x / a) * (x / a) + (y / b) * (y / b) < 1 ? -d : d;
}

CrackShape planar(const std::string& form, double a, double b, double r) {
    CrackShape s;
    s.form = form, s.semiMajor = a, s.semiMinor = b, s.filletRadius = r;
    s.centre = {0.45, 0.52, 0.61};
    s.vectX = {1, 2, 0};  // rotated frame: VECT_X x VECT_Y = (2, -1, 5) / sqrt(30)
    s.vectY = {-2, 1, 1};
    return s;
}

// The local coordinates of node n in the frame of `s`.
Vec3 local(const Mesh& m, int n, const CrackShape& s) {
    const Vec3 x = unitVec(s.vectX), y = unitVec(s.vectY), z = unitVec(cross(s.vectX, s.vectY));
    const Vec3 d = difference(m.coords[size_t(n)], s.centre);
    return {dot(x, d), dot(y, d), dot(z, d)};
}

}  // namespace

TEST(CrackShapes, EllipseRectangleCylinderAgainstClosedForms) {
    const auto m = box(6);
    for (bool outside : {false, true}) {
        auto s = planar("ELLIPSE", 0.3, 0.3, 0);  // a circle: LST = r - R exactly
        s.outside = outside;
        auto ls = shapeLevelSets(*m, s, true);
        for (int n = 0; n < m->nodeCount(); ++n) {
            const Vec3 p = local(*m, n, s);
            EXPECT_NEAR(ls.lsn[size_t(n)], p[2], 1e-15);
            EXPECT_NEAR(ls.lst[size_t(n)], (outside ? -1 : 1) * (std::hypot(p[0], p[1]) - 0.3), 1e-15);
        }
    }
    auto s = planar("ELLIPSE", 0.4, 0.15, 0);
    auto ls = shapeLevelSets(*m, s, true);
    for (int n = 0; n < m->nodeCount(); ++n) {
        const Vec3 p = local(*m, n, s);
        EXPECT_NEAR(ls.lst[size_t(n)], ellipseByNewton(p[0], p[1], 0.4, 0.15), 1e-13) << n;
    }
    for (double r : {0.0, 0.05, 0.15}) {
        s = planar("RECTANGLE", 0.3, 0.15, r);
        ls = shapeLevelSets(*m, s, true);
        for (int n = 0; n < m->nodeCount(); ++n) {
            const Vec3 p = local(*m, n, s);
            EXPECT_NEAR(ls.lst[size_t(n)], roundedBox(p[0], p[1], 0.3, 0.15, r), 1e-15) << n << " r " << r;
            EXPECT_NEAR(ls.lsn[size_t(n)], p[2], 1e-15);
        }
    }
    s = planar("CYLINDRE", 0.25, 0.25, 0);
    ls = shapeLevelSets(*m, s, true);
    for (int n = 0; n < m->nodeCount(); ++n) {
        const Vec3 p = local(*m, n, s);
        EXPECT_NEAR(ls.lsn[size_t(n)], std::hypot(p[0], p[1]) - 0.25, 1e-15);
        EXPECT_NEAR(ls.lst[size_t(n)], p[2], 1e-15);
    }
    // Interfaces: LSN is the distance to the closed curve, LST = -1.
    for (const char* form : {"ELLIPSE", "RECTANGLE", "ENTAILLE"}) {
        s = planar(form, 0.35, 0.2, 0.1);
        ls = shapeLevelSets(*m, s, false);
        for (int n = 0; n < m->nodeCount(); ++n) {
            const Vec3 p = local(*m, n, s);
            const double expected = std::string(form) == "ELLIPSE"     ? ellipseByNewton(p[0], p[1], 0.35, 0.2)
                                    : std::string(form) == "RECTANGLE" ? roundedBox(p[0], p[1], 0.35, 0.2, 0.1)
                                                                       : roundedBox(p[0], p[1], 0.35, 0.1, 0.1);
            EXPECT_NEAR(ls.lsn[size_t(n)], expected, 1e-13) << form << " node " << n;
            EXPECT_EQ(ls.lst[size_t(n)], -1.0);
        }
    }
}

TEST(CrackShapes, HalfPlaneSegmentHalfLineLineAgainstClosedForms) {
    const auto m3 = box(5);
    CrackShape s;
    s.form = "DEMI_PLAN", s.point = {0.3, 0.4, 0.5}, s.normal = {0, 3, 4}, s.tangent = {5, 0, 0};
    auto ls = shapeLevelSets(*m3, s, true);
    for (int n = 0; n < m3->nodeCount(); ++n) {
        const Vec3 d = difference(m3->coords[size_t(n)], s.point);
        EXPECT_NEAR(ls.lsn[size_t(n)], (3 * d[1] + 4 * d[2]) / 5, 1e-15);
        EXPECT_NEAR(ls.lst[size_t(n)], d[0], 1e-15);
    }
    const auto m2 = xfemtest::square(6, CellType::QUAD4);
    s = {};
    s.form = "SEGMENT", s.point = {-2, -1, 0}, s.end = {2, 2, 0};  // length 5, direction (0.8, 0.6)
    ls = shapeLevelSets(*m2, s, true);
    for (int n = 0; n < m2->nodeCount(); ++n) {
        const double dx = m2->coords[size_t(n)][0], dy = m2->coords[size_t(n)][1] - 0.5;  // from the middle
        EXPECT_NEAR(ls.lsn[size_t(n)], -0.6 * dx + 0.8 * dy, 1e-14);
        EXPECT_NEAR(ls.lst[size_t(n)], std::abs(0.8 * dx + 0.6 * dy) - 2.5, 1e-14);
    }
    for (const char* form : {"DEMI_DROITE", "DROITE"}) {
        s = {};
        s.form = form, s.point = {1, -1, 0}, s.tangent = {0, -2, 0};  // towards -y: normal (+x)
        const bool crack = std::string(form) == "DEMI_DROITE";
        ls = shapeLevelSets(*m2, s, crack);
        for (int n = 0; n < m2->nodeCount(); ++n) {
            const double dx = m2->coords[size_t(n)][0] - 1, dy = m2->coords[size_t(n)][1] + 1;
            EXPECT_NEAR(ls.lsn[size_t(n)], dx, 1e-15);
            EXPECT_NEAR(ls.lst[size_t(n)], crack ? -dy : -1.0, 1e-15);
        }
    }
}

TEST(CrackShapes, FormsThatDoNotFitAreRefused) {
    const auto m3 = box(2);
    const auto m2 = xfemtest::square(2, CellType::QUAD4);
    auto s = planar("ENTAILLE", 0.3, 0.1, 0.1);
    EXPECT_THROW(shapeLevelSets(*m3, s, true), UserError);  // a notch is an interface
    s.form = "CYLINDRE";
    EXPECT_THROW(shapeLevelSets(*m3, s, false), UserError);  // a cylinder is a crack
    s.form = "ELLIPSE";
    EXPECT_THROW(shapeLevelSets(*m2, s, true), UserError);  // a 3D crack on a 2D mesh
    s.vectY = {1, 0, 0.1};
    EXPECT_THROW(shapeLevelSets(*m3, s, true), UserError);  // VECT_X not orthogonal to VECT_Y
    CrackShape seg;
    seg.form = "SEGMENT", seg.point = {0, 0, 0}, seg.end = {1, 0, 0};
    EXPECT_THROW(shapeLevelSets(*m3, seg, true), UserError);  // a 2D form on a 3D mesh
}

// A straight front x = 0.461, y = 0.537 through [0,1]^3: one point per horizontal face it crosses,
// exactly on the line, the abscissa is z; the tip cells are the column around it.
TEST(CrackFronts, StraightFrontOnTheLine) {
    const int n = 8;
    const auto m = box(n);
    CrackShape s;
    s.form = "DEMI_PLAN", s.point = {0.461, 0.537, 0.3}, s.normal = {0, 1, 0}, s.tangent = {1, 0, 0};
    auto ls = shapeLevelSets(*m, s, true);
    const auto crack = buildCrackWithFront(m, ls.lsn, ls.lst);
    ASSERT_EQ(crack->fronts.size(), 1u);
    const auto& f = crack->fronts[0];
    EXPECT_FALSE(f.closed);
    ASSERT_EQ(f.points.size(), size_t(n + 1));
    const double z0 = f.points[0][2];
    EXPECT_TRUE(z0 == 0.0 || z0 == 1.0);
    for (size_t i = 0; i < f.points.size(); ++i) {
        EXPECT_NEAR(f.points[i][0], 0.461, 1e-15);
        EXPECT_NEAR(f.points[i][1], 0.537, 1e-15);
        EXPECT_NEAR(f.points[i][2], z0 == 0.0 ? double(i) / n : 1.0 - double(i) / n, 1e-15);
        EXPECT_NEAR(f.abscissa[i], double(i) / n, 1e-15);
    }
    EXPECT_EQ(crack->tipCells.size(), size_t(n));
    // Status: behind the front 1 (x <= 0.375, the nodes on both sides of y = 0.537), around it 2/3,
    // ahead of it 0.
    int heaviside = 0, tip = 0;
    for (int k = 0; k < m->nodeCount(); ++k) {
        const auto& x = m->coords[size_t(k)];
        const int status = crack->nodeStatus[size_t(k)];
        const bool nearPlane = x[1] == 0.5 || x[1] == 0.625;
        if (!nearPlane || x[0] > 0.5) {
            EXPECT_EQ(status, 0) << k;
        } else if (x[0] <= 0.25) {
            EXPECT_EQ(status, 1) << k;
            heaviside += status == 1;
        } else {
            EXPECT_GE(status, 2) << k;
            tip += status >= 2;
        }
    }
    EXPECT_EQ(heaviside, 3 * 2 * (n + 1));
    EXPECT_EQ(tip, 2 * 2 * (n + 1));
}

// An inclined straight front: DTAN at 30 degrees in the plane y = 0.537. The points lie on the
// line, and the abscissa is the distance from the first point.
TEST(CrackFronts, InclinedFrontAbscissaIsTheDistance) {
    const auto m = box(7);
    CrackShape s;
    const double c = std::cos(std::numbers::pi / 6), sn = std::sin(std::numbers::pi / 6);
    s.form = "DEMI_PLAN", s.point = {0.5, 0.537, 0.5}, s.normal = {0, 1, 0}, s.tangent = {c, 0, sn};
    auto ls = shapeLevelSets(*m, s, true);
    const auto crack = buildCrackWithFront(m, ls.lsn, ls.lst);
    ASSERT_EQ(crack->fronts.size(), 1u);
    const auto& f = crack->fronts[0];
    ASSERT_GE(f.points.size(), 8u);
    for (size_t i = 0; i < f.points.size(); ++i) {
        const Vec3 d = difference(f.points[i], s.point);
        EXPECT_NEAR(d[1], 0.0, 1e-15);
        EXPECT_NEAR(c * d[0] + sn * d[2], 0.0, 1e-14);  // LST = 0
        EXPECT_NEAR(f.abscissa[i], distance(f.points[i], f.points[0]), 1e-14);
    }
    // The line x = 0.5 - t sin30, z = 0.5 + t cos30 leaves the box at z = 0 and z = 1: length 1/cos30.
    EXPECT_NEAR(f.abscissa.back(), 1.0 / c, 1e-14);
}

// A penny-shaped crack (ELLIPSE with equal axes, radius R) in an annulus whose vertical faces are
// on rays: every front point is on the circle to round-off, the front is closed (its first point
// repeated) and the abscissa is the length of the inscribed polygon, within the polygon's error of
// the arc length R theta.
TEST(CrackFronts, CircularFrontOnTheCircle) {
    const int nt = 48;
    const double R = 0.537, z0 = 0.4321;
    const auto m = annulus(0.2, 1.0, 8, nt, 5);
    CrackShape s;
    s.form = "ELLIPSE", s.semiMajor = R, s.semiMinor = R, s.centre = {0, 0, z0};
    s.vectX = {1, 0, 0}, s.vectY = {0, 1, 0};
    auto ls = shapeLevelSets(*m, s, true);
    const auto crack = buildCrackWithFront(m, ls.lsn, ls.lst);
    ASSERT_EQ(crack->fronts.size(), 1u);
    const auto& f = crack->fronts[0];
    EXPECT_TRUE(f.closed);
    ASSERT_EQ(f.points.size(), size_t(nt + 1));
    EXPECT_EQ(crack->tipCells.size(), size_t(nt));
    const double chord = 2 * R * std::sin(std::numbers::pi / nt);
    const double theta0 = std::atan2(f.points[0][1], f.points[0][0]);
    for (size_t i = 0; i < f.points.size(); ++i) {
        const auto& p = f.points[i];
        EXPECT_NEAR(std::hypot(p[0], p[1]), R, 1e-15) << i;
        EXPECT_NEAR(p[2], z0, 1e-15) << i;
        EXPECT_NEAR(f.abscissa[i], double(i) * chord, 1e-13) << i;
        double arc = std::atan2(p[1], p[0]) - theta0;  // the arc length from the first point
        arc = std::abs(std::remainder(arc, 2 * std::numbers::pi));
        if (i > size_t(nt / 2)) arc = 2 * std::numbers::pi - arc;
        const double polygonError = R * arc * (1 - std::sin(std::numbers::pi / nt) / (std::numbers::pi / nt));
        EXPECT_NEAR(f.abscissa[i], R * arc, polygonError * (1 + 1e-9) + 1e-14) << i;
    }
    EXPECT_NEAR(f.abscissa.back(), 2 * std::numbers::pi * R, 2 * std::numbers::pi * R * 1e-3);  // π²/(6 nt²)
}

// 2D: a SEGMENT has two front points, a DEMI_DROITE one, exactly at the tips.
TEST(CrackFronts, TwoDimensionalFrontPoints) {
    const auto m = xfemtest::square(10, CellType::QUAD4);  // [-5, 5]^2, h = 1
    CrackShape s;
    s.form = "SEGMENT", s.point = {-2.3, 0.25, 0}, s.end = {1.7, 0.25, 0};
    auto ls = shapeLevelSets(*m, s, true);
    auto crack = buildCrackWithFront(m, ls.lsn, ls.lst);
    ASSERT_EQ(crack->fronts.size(), 2u);
    std::vector<double> xs{crack->fronts[0].points[0][0], crack->fronts[1].points[0][0]};
    std::sort(xs.begin(), xs.end());
    EXPECT_NEAR(xs[0], -2.3, 1e-15);
    EXPECT_NEAR(xs[1], 1.7, 1e-15);
    for (const auto& f : crack->fronts) EXPECT_NEAR(f.points[0][1], 0.25, 1e-15);
    s = {};
    s.form = "DEMI_DROITE", s.point = {0.3, -0.45, 0}, s.tangent = {0, 1, 0};
    ls = shapeLevelSets(*m, s, true);
    crack = buildCrackWithFront(m, ls.lsn, ls.lst);
    ASSERT_EQ(crack->fronts.size(), 1u);
    EXPECT_NEAR(crack->fronts[0].points[0][0], 0.3, 1e-15);
    EXPECT_NEAR(crack->fronts[0].points[0][1], -0.45, 1e-15);
    EXPECT_EQ(crack->tipCells.size(), 1u);
}

// A crack whose front lies outside the mesh is a through-cut: Heaviside status only, no front.
TEST(CrackFronts, ThroughCrackHasNoFront) {
    const auto m = xfemtest::square(6, CellType::QUAD4);
    CrackShape s;
    s.form = "DEMI_DROITE", s.point = {9, 0.2, 0}, s.tangent = {1, 0, 0};  // tip at x = 9, outside
    auto ls = shapeLevelSets(*m, s, true);
    const auto crack = buildCrackWithFront(m, ls.lsn, ls.lst);
    EXPECT_TRUE(crack->fronts.empty());
    EXPECT_TRUE(crack->tipCells.empty());
    EXPECT_EQ(crack->nodeCountWithStatus(1), 2 * 7);
    EXPECT_EQ(crack->nodeCountWithStatus(2) + crack->nodeCountWithStatus(3), 0);
}
