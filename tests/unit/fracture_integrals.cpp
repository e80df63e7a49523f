// The theta method of CALC_G (src/fracture) fed with Williams' exact crack-tip fields: a square
// grid around the tip, the crack along a grid line behind it, the exact displacement gradient at
// 4x4 Gauss points per cell. K1, K2 and G must come out to quadrature accuracy whatever the crown
// (R_INF, R_SUP): the domain integrals are path-independent for the exact field.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/Error.hpp"
#include "fe/ElementKinematics.hpp"
#include "fe/Quadrature.hpp"
#include "fracture/DomainIntegrals.hpp"
#include "fracture/ThetaField.hpp"
#include "fracture/WilliamsFields.hpp"
#include "xfem/Crack.hpp"

namespace {

using namespace ma;
using namespace ma::fracture;

struct Scene {
    double E = 210e9, nu = 0.3;
    Modelisation modelisation = Modelisation::D_PLAN;
    double K1 = 1.3e6, K2 = -0.45e6;
    double angle = 0.0;  // the crack's direction of propagation
    Vec3 tip{0.013, -0.021, 0.0};
    int n = 40;  // cells per side of [-1, 1]^2 (before rotation and translation)
};

// The grid's node (i, j) rotated by `angle` about the origin and moved to the tip.
Vec3 place(const Scene& s, double x, double y) {
    const double c = std::cos(s.angle), sn = std::sin(s.angle);
    return {s.tip[0] + c * x - sn * y, s.tip[1] + sn * x + c * y, 0.0};
}

std::shared_ptr<Mesh> grid(const Scene& s) {
    auto m = std::make_shared<Mesh>();
    m->dim = 2;
    for (int j = 0; j <= s.n; ++j)
        for (int i = 0; i <= s.n; ++i) m->addNode(place(s, -1.0 + 2.0 * i / s.n, -1.0 + 2.0 * j / s.n));
    auto id = [&](int i, int j) { return j * (s.n + 1) + i; };
    for (int j = 0; j < s.n; ++j)
        for (int i = 0; i < s.n; ++i)
            m->addCell(CellType::QUAD4, std::vector<int>{id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    return m;
}

FrontFrame frameOf(const Scene& s) {
    FrontFrame f;
    f.origin = s.tip;
    f.e1 = {std::cos(s.angle), std::sin(s.angle), 0.0};
    f.e2 = {-std::sin(s.angle), std::cos(s.angle), 0.0};
    f.e3 = {0, 0, 1};
    return f;
}

// Williams' field of (K1, K2) at a point on side `side` of the crack, global axes.
void exactGradient(const Scene& s, const FrontFrame& f, const Vec3& x, double side, double G[3][3]) {
    const auto c = ElasticConstants::of(s.E, s.nu, s.modelisation);
    const Vec3 d = difference(x, f.origin);
    const double x1 = dot(d, f.e1), x2 = dot(d, f.e2);
    const double r = std::hypot(x1, x2);
    const double t = std::copysign(std::acos(std::clamp(x1 / r, -1.0, 1.0)), side);
    const auto a = williamsField(Mode::I, r, t, c.mu, c.kappa), b = williamsField(Mode::II, r, t, c.mu, c.kappa);
    const Vec3* e[2] = {&f.e1, &f.e2};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            G[i][j] = 0.0;
            for (int p = 0; p < 2; ++p)
                for (int q = 0; q < 2; ++q)
                    G[i][j] += (*e[p])[i] * (s.K1 * a.grad[p][q] + s.K2 * b.grad[p][q]) * (*e[q])[j];
        }
}

std::vector<DomainPoint> exactPoints(const Scene& s, const Mesh& mesh, const std::vector<Vec3>& theta) {
    const auto f = frameOf(s);
    const QuadratureRule& line = quadratureRule(CellType::SEG2, "FPG4");
    ElementIntegration ei;
    ei.nodeCount = 4;
    ei.slots.assign(4, 1);
    for (int a = 0; a < line.size(); ++a)
        for (int b = 0; b < line.size(); ++b) {
            ei.refPoints.push_back({line.points[size_t(a)][0], line.points[size_t(b)][0], 0.0});
            ei.refWeights.push_back(line.weights[size_t(a)] * line.weights[size_t(b)]);
        }
    std::vector<DomainPoint> out;
    PointGeometry geo;
    for (int cell = 0; cell < mesh.cellCount(); ++cell) {
        ei.cell = cell;
        computePointGeometry(mesh, cell, 2, false, ei, geo);
        const auto nodes = mesh.cellNodes(cell);
        Vec3 centre{};
        for (int n : nodes)
            for (int k = 0; k < 3; ++k) centre[size_t(k)] += mesh.coords[size_t(n)][size_t(k)] / 4;
        const double side = dot(difference(centre, f.origin), f.e2) > 0 ? 1.0 : -1.0;
        for (size_t p = 0; p < ei.refPoints.size(); ++p) {
            DomainPoint q;
            q.weight = geo.weight[p];
            q.xyz = geo.xyz[p];
            q.side = side;
            q.E = s.E;
            q.nu = s.nu;
            exactGradient(s, f, q.xyz, side, q.gradU);
            for (size_t a = 0; a < 4; ++a)
                for (int k = 0; k < 2; ++k) {
                    q.theta[size_t(k)] += geo.N[p * 4 + a] * theta[size_t(nodes[a])][size_t(k)];
                    for (int j = 0; j < 2; ++j)
                        q.gradTheta[k][j] +=
                            geo.gradN[(p * 4 + a) * 3 + size_t(j)] * theta[size_t(nodes[a])][size_t(k)];
                }
            out.push_back(q);
        }
    }
    return out;
}

FrontValues integrals(const Scene& s, double rInf, double rSup) {
    const auto mesh = grid(s);
    const auto f = frameOf(s);
    const std::vector<Vec3> grlt(size_t(mesh->nodeCount()), f.e1);
    const auto theta = thetaField2D(*mesh, s.tip, grlt, rInf, rSup);
    return domainIntegrals(exactPoints(s, *mesh, theta), f, s.modelisation, 2, true);
}

void expectExact(const Scene& s, const FrontValues& v, double tolerance) {
    const double eStar = ElasticConstants::of(s.E, s.nu, s.modelisation).eStar;
    const double g = (s.K1 * s.K1 + s.K2 * s.K2) / eStar;
    EXPECT_NEAR(v.K1, s.K1, tolerance * std::abs(s.K1));
    EXPECT_NEAR(v.K2, s.K2, tolerance * std::abs(s.K1));
    EXPECT_NEAR(v.G, g, tolerance * g);
    EXPECT_NEAR(v.gIrwin, g, 3 * tolerance * g);
}

TEST(FractureIntegrals, ExactWilliamsFieldAnyCrownPlaneStrain) {
    Scene s;
    for (auto [rInf, rSup] : {std::pair{0.1, 0.3}, {0.2, 0.5}, {0.15, 0.9}, {0.35, 0.4}}) {
        SCOPED_TRACE(testing::Message() << "R_INF " << rInf << " R_SUP " << rSup);
        expectExact(s, integrals(s, rInf, rSup), 1e-6);
    }
}

TEST(FractureIntegrals, ExactWilliamsFieldInclinedCrackPlaneStress) {
    Scene s;
    s.modelisation = Modelisation::C_PLAN;
    s.angle = 0.6;
    s.K2 = 0.8e6;
    for (auto [rInf, rSup] : {std::pair{0.1, 0.3}, {0.25, 0.75}}) {
        SCOPED_TRACE(testing::Message() << "R_INF " << rInf << " R_SUP " << rSup);
        expectExact(s, integrals(s, rInf, rSup), 1e-6);
    }
}

TEST(FractureIntegrals, PureModesAreSeparated) {
    Scene s;
    s.K2 = 0.0;
    auto v = integrals(s, 0.1, 0.4);
    EXPECT_NEAR(v.K2, 0.0, 1e-5 * s.K1);
    s.K1 = 0.0;
    s.K2 = 2e6;
    v = integrals(s, 0.1, 0.4);
    EXPECT_NEAR(v.K1, 0.0, 1e-5 * s.K2);
    EXPECT_NEAR(v.K2, s.K2, 2e-5 * s.K2);
}

TEST(FractureIntegrals, QuadratureErrorFallsWithTheMesh) {
    Scene s;
    s.n = 10;
    const double coarse = std::abs(integrals(s, 0.4, 0.8).K1 - s.K1);
    s.n = 40;
    const double fine = std::abs(integrals(s, 0.4, 0.8).K1 - s.K1);
    EXPECT_LT(fine, coarse);
    EXPECT_LT(fine, 1e-6 * s.K1);
}

TEST(FractureIntegrals, ThetaFieldIsCodeAstersCrown) {
    Scene s;
    s.n = 4;
    const auto mesh = grid(s);
    const std::vector<Vec3> grlt(size_t(mesh->nodeCount()), Vec3{0, 3, 0});
    const auto theta = thetaField2D(*mesh, s.tip, grlt, 0.6, 1.2);
    for (int n = 0; n < mesh->nodeCount(); ++n) {
        const double d = distance(mesh->coords[size_t(n)], s.tip);
        const double expected = d <= 0.6 ? 1.0 : (d >= 1.2 ? 0.0 : (1.2 - d) / 0.6);
        EXPECT_NEAR(theta[size_t(n)][1], expected, 1e-14);
        EXPECT_EQ(theta[size_t(n)][0], 0.0);
    }
    std::vector<Vec3> null = grlt;
    null[12] = Vec3{};  // the centre node: inside the crown
    EXPECT_THROW(thetaField2D(*mesh, s.tip, null, 0.6, 1.2), UserError);
}

}  // namespace

namespace {

// 3D: a straight front along z through a box of HEXA8, the crack y = 0, x < 0; Williams' plane-strain
// modes I, II and the antiplane mode III, uniform along z (an exact solution for a straight front).
// theta = q(r) psi(z) e1 with psi a hat vanishing on the z faces: the integrals are
// G int psi dz and K int psi dz, so dividing by int psi dz gives G and K of the front.
TEST(FractureIntegrals, ExactFieldsAlongAStraightFront3D) {
    const double E = 2e11, nu = 0.3, K1 = 2e6, K2 = -0.7e6, K3 = 1.1e6;
    const int n = 16, nz = 4;
    auto m = std::make_shared<Mesh>();
    m->dim = 3;
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) m->addNode({-1.0 + 2.0 * i / n, -1.0 + 2.0 * j / n, 0.5 * k / nz});
    auto id = [&](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                m->addCell(CellType::HEXA8, std::vector<int>{id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k),
                                                             id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1),
                                                             id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
    FrontFrame f;
    f.e1 = {1, 0, 0}, f.e2 = {0, 1, 0}, f.e3 = {0, 0, 1};
    std::vector<Vec3> theta(size_t(m->nodeCount()));
    for (int a = 0; a < m->nodeCount(); ++a) {
        const Vec3& x = m->coords[size_t(a)];
        const double r = std::hypot(x[0], x[1]), q = r <= 0.25 ? 1.0 : (r >= 0.75 ? 0.0 : (0.75 - r) / 0.5);
        theta[size_t(a)] = {q * (1 - std::abs(x[2] - 0.25) / 0.25), 0.0, 0.0};
    }
    const auto c = ElasticConstants::of(E, nu, Modelisation::TRI_D);
    const QuadratureRule& line = quadratureRule(CellType::SEG2, "FPG4");
    ElementIntegration ei;
    ei.nodeCount = 8;
    ei.slots.assign(8, 1);
    for (const auto& a : line.points)
        for (const auto& b : line.points)
            for (const auto& d : line.points) ei.refPoints.push_back({a[0], b[0], d[0]});
    for (double a : line.weights)
        for (double b : line.weights)
            for (double d : line.weights) ei.refWeights.push_back(a * b * d);
    std::vector<DomainPoint> points;
    PointGeometry geo;
    for (int cell = 0; cell < m->cellCount(); ++cell) {
        ei.cell = cell;
        computePointGeometry(*m, cell, 3, false, ei, geo);
        const auto nodes = m->cellNodes(cell);
        const double side = m->coords[size_t(nodes[2])][1] > 0 ? 1.0 : -1.0;  // node (i+1, j+1): above y = 0 or not
        for (size_t p = 0; p < ei.refPoints.size(); ++p) {
            DomainPoint q;
            q.weight = geo.weight[p], q.xyz = geo.xyz[p], q.side = side, q.E = E, q.nu = nu;
            const double r = std::hypot(q.xyz[0], q.xyz[1]);
            const double t = std::copysign(std::acos(std::clamp(q.xyz[0] / r, -1.0, 1.0)), side);
            const auto a = williamsField(Mode::I, r, t, c.mu, c.kappa),
                       b = williamsField(Mode::II, r, t, c.mu, c.kappa),
                       d = williamsField(Mode::III, r, t, c.mu, c.kappa);
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) q.gradU[i][j] = K1 * a.grad[i][j] + K2 * b.grad[i][j] + K3 * d.grad[i][j];
            for (size_t k = 0; k < 8; ++k)
                for (int j = 0; j < 3; ++j) {
                    q.theta[0] += j == 0 ? geo.N[p * 8 + k] * theta[size_t(nodes[k])][0] : 0.0;
                    q.gradTheta[0][j] += geo.gradN[(p * 8 + k) * 3 + size_t(j)] * theta[size_t(nodes[k])][0];
                }
            points.push_back(q);
        }
    }
    const auto v = domainIntegrals(points, f, Modelisation::TRI_D, 3, true);
    const double length = 0.25;  // int psi dz
    const double g = (K1 * K1 + K2 * K2) * (1 - nu * nu) / E + K3 * K3 * (1 + nu) / E;
    EXPECT_NEAR(v.K1 / length, K1, 1e-6 * K1);
    EXPECT_NEAR(v.K2 / length, K2, 1e-6 * K1);
    EXPECT_NEAR(v.K3 / length, K3, 1e-6 * K1);
    EXPECT_NEAR(v.G / length, g, 1e-6 * g);
}

}  // namespace

namespace {

// The tip of a crack built by DEFI_FISS_XFEM's engine: its point, direction and TAILLE_R (xtailm:
// the largest |edge . e1| of the tip cell; here the grid's edges 0.2 along x and y).
TEST(FractureIntegrals, TipPointFrameAndCellSize) {
    Scene s;
    s.n = 10;
    s.tip = {0.0, 0.0, 0.0};
    const auto mesh = grid(s);
    const double beta = 0.3;
    const Vec3 p{0.05, 0.07, 0.0}, d{std::cos(beta), std::sin(beta), 0.0};
    std::vector<double> lsn, lst;
    for (const auto& x : mesh->coords) {
        lsn.push_back(-d[1] * (x[0] - p[0]) + d[0] * (x[1] - p[1]));
        lst.push_back(d[0] * (x[0] - p[0]) + d[1] * (x[1] - p[1]));
    }
    const auto crack = xfem::buildCrackWithFront(mesh, lsn, lst);
    const auto grlt = xfem::nodalLevelSetGradient(*mesh, crack->lst);
    const auto tip = tipPoint2D(*mesh, *crack, grlt, 1);
    for (int k = 0; k < 2; ++k) {
        EXPECT_NEAR(tip.point[size_t(k)], p[size_t(k)], 1e-14);
        EXPECT_NEAR(tip.frame.e1[size_t(k)], d[size_t(k)], 1e-14);
    }
    EXPECT_NEAR(tip.frame.e2[0], -d[1], 1e-14);
    EXPECT_NEAR(tip.cellSize, 0.2 * std::cos(beta), 1e-14);
    EXPECT_THROW(tipPoint2D(*mesh, *crack, grlt, 2), UserError);
}

}  // namespace
