// The FE side of the fracture engine without crack-tip enrichment: (1) domainPoints, the one place
// where CALC_G reads the displacement gradient through fe's element description, on a classical
// D_PLAN model whose mesh has the crack as a seam (nodes doubled behind the tip) and the nodal
// values of Williams' field: K and G converge to the exact values as the mesh is refined;
// (2) POST_K1_K2_K3's extrapolation of exact lip jumps gives K exactly; (3) the jump sampling
// interpolates 2 H1 along the segment behind the tip.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "fe/Discretisation.hpp"
#include "fe/MechanicalProblem.hpp"
#include "fe_test_support.hpp"
#include "fracture/DomainSampling.hpp"
#include "fracture/JumpExtrapolation.hpp"
#include "fracture/LipJumps.hpp"
#include "fracture/ThetaField.hpp"
#include "fracture/WilliamsFields.hpp"

namespace {

using namespace ma;
using namespace ma::fracture;

constexpr double kE = 2e11, kNu = 0.25, kK1 = 3e6, kK2 = 1e6;

// [-1, 1]^2, n x n QUAD4, the crack y = 0, x < 0 as a seam: the nodes of that line are doubled, the
// cells below use the copies. Group ALL. `upper[node]`: the node belongs to the upper side.
std::shared_ptr<Mesh> seamMesh(int n, std::vector<char>& upper) {
    auto m = std::make_shared<Mesh>();
    m->dim = 2;
    std::vector<int> id((n + 1) * (n + 1)), below((n + 1) * (n + 1), -1);
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const double x = -1.0 + 2.0 * i / n, y = -1.0 + 2.0 * j / n;
            id[size_t(j * (n + 1) + i)] = m->addNode({x, y, 0.0});
            upper.push_back(j >= n / 2);
            if (j == n / 2 && i < n / 2) below[size_t(j * (n + 1) + i)] = m->addNode({x, y, 0.0}), upper.push_back(0);
        }
    std::vector<int> all;
    auto node = [&](int i, int j, bool lower) {
        const size_t k = size_t(j * (n + 1) + i);
        return lower && below[k] >= 0 ? below[k] : id[k];
    };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const bool lower = j < n / 2;
            all.push_back(
                m->addCell(CellType::QUAD4, std::vector<int>{node(i, j, lower), node(i + 1, j, lower),
                                                             node(i + 1, j + 1, lower), node(i, j + 1, lower)}));
        }
    m->cellGroups.set("ALL", all);
    std::vector<int> up, low;  // the outer boundary's nodes by side of the crack
    for (int a = 0; a < m->nodeCount(); ++a) {
        const Vec3& x = m->coords[size_t(a)];
        if (std::max(std::abs(x[0]), std::abs(x[1])) > 1 - 1e-12) (upper[size_t(a)] ? up : low).push_back(a);
    }
    m->nodeGroups.set("BUP", up);
    m->nodeGroups.set("BLO", low);
    return m;
}

FrontValues feIntegrals(int n, double rInf, double rSup) {
    std::vector<char> upper;
    auto mesh = seamMesh(n, upper);
    auto model = fetest::affeModele(mesh, "D_PLAN", {"ALL"});
    auto material = fetest::material(model, kE, kNu);
    Discretisation space(model, material, {});
    const auto c = ElasticConstants::of(kE, kNu, Modelisation::D_PLAN);
    std::vector<double> u(size_t(space.numbering().size()), 0.0), lsn(size_t(mesh->nodeCount()));
    for (int a = 0; a < mesh->nodeCount(); ++a) {
        const Vec3& x = mesh->coords[size_t(a)];
        const double r = std::hypot(x[0], x[1]);
        lsn[size_t(a)] = x[1];
        if (r == 0.0) continue;
        const double t = std::copysign(std::acos(x[0] / r), upper[size_t(a)] ? 1.0 : -1.0);
        const auto f1 = williamsField(Mode::I, r, t, c.mu, c.kappa), f2 = williamsField(Mode::II, r, t, c.mu, c.kappa);
        for (int k = 0; k < 2; ++k)
            u[size_t(space.numbering().dof(a, 0, k))] = kK1 * f1.u[size_t(k)] + kK2 * f2.u[size_t(k)];
    }
    FrontFrame frame;
    frame.e1 = {1, 0, 0}, frame.e2 = {0, 1, 0}, frame.e3 = {0, 0, 1};
    const std::vector<Vec3> grlt(size_t(mesh->nodeCount()), frame.e1);
    const auto theta = thetaField2D(*mesh, frame.origin, grlt, rInf, rSup);
    return domainIntegrals(domainPoints(space, u, theta, lsn, 1.0), frame, Modelisation::D_PLAN, 2, true);
}

TEST(FractureSampling, NodalWilliamsFieldConvergesThroughTheElements) {
    double previous = 1.0;
    for (int n : {16, 32, 64}) {
        const auto v = feIntegrals(n, 0.25, 0.75);
        const double e1 = std::abs(v.K1 / kK1 - 1), e2 = std::abs(v.K2 / kK2 - 1);
        const double g = (kK1 * kK1 + kK2 * kK2) * (1 - kNu * kNu) / kE;
        SCOPED_TRACE(testing::Message() << "n " << n << " K1 error " << e1 << " K2 error " << e2);
        std::printf("n %d: K1 error %.3e, K2 error %.3e, G error %.3e\n", n, e1, e2, std::abs(v.G / g - 1));
        EXPECT_LT(std::max(e1, e2), previous / 2.5);  // at least h^1.3
        EXPECT_NEAR(v.G, g, 4 * std::max(e1, e2) * g);
        previous = std::max(e1, e2);
    }
    EXPECT_LT(previous, 5e-3);
}

// The same seam mesh solved by MECA_STATIQUE's engine with Williams' displacement prescribed on the
// outer boundary (each lip's side its own branch of theta): K from the FE solution converges.
std::shared_ptr<Function> williams(int component, double side) {
    return std::make_shared<fetest::LambdaFunction>([component, side](double x, double y, double) {
        const auto c = ElasticConstants::of(kE, kNu, Modelisation::D_PLAN);
        const double r = std::hypot(x, y), t = side * std::acos(std::clamp(x / r, -1.0, 1.0));
        const auto f1 = williamsField(Mode::I, r, t, c.mu, c.kappa), f2 = williamsField(Mode::II, r, t, c.mu, c.kappa);
        return kK1 * f1.u[size_t(component)] + kK2 * f2.u[size_t(component)];
    });
}

FrontValues solvedIntegrals(int n) {
    using namespace fetest;
    std::vector<char> upper;
    auto mesh = seamMesh(n, upper);
    auto model = affeModele(mesh, "D_PLAN", {"ALL"});
    auto mat = material(model, kE, kNu);
    KeywordSet kw;
    set(kw, "MODELE", model);
    for (auto [group, side] : {std::pair{"BUP", 1.0}, {"BLO", -1.0}}) {
        auto& d = kw.addOccurrence("DDL_IMPO");
        setTexts(d, "GROUP_NO", {group});
        set(d, "DX", ConceptPtr(williams(0, side)));
        set(d, "DY", ConceptPtr(williams(1, side)));
    }
    auto load = std::dynamic_pointer_cast<MechanicalLoad>(run("AFFE_CHAR_MECA_F", kw, "CHAR"));
    MechanicalProblem problem(model, mat, {{load, nullptr}}, SolverOptions{});
    ConvergenceOptions conv;
    conv.maxIterations = 0;
    conv.resiGlobRela = -1.0;
    problem.solveIncrement(0.0, conv);
    Discretisation space(model, mat, {});
    std::vector<double> lsn;
    for (const auto& x : mesh->coords) lsn.push_back(x[1]);
    FrontFrame frame;
    frame.e1 = {1, 0, 0}, frame.e2 = {0, 1, 0}, frame.e3 = {0, 0, 1};
    const auto theta =
        thetaField2D(*mesh, frame.origin, std::vector<Vec3>(size_t(mesh->nodeCount()), frame.e1), 0.25, 0.75);
    return domainIntegrals(domainPoints(space, problem.state(), theta, lsn, 1.0), frame, Modelisation::D_PLAN, 2, true);
}

TEST(FractureSampling, SolvedWilliamsProblemConverges) {
    msg().setEcho(false);
    double previous = 1.0;
    for (int n : {16, 32, 64}) {
        const auto v = solvedIntegrals(n);
        const double e = std::max(std::abs(v.K1 / kK1 - 1), std::abs(v.K2 / kK1 - kK2 / kK1));
        std::printf("solved n %d: K1 %.6e K2 %.6e, error %.3e\n", n, v.K1, v.K2, e);
        EXPECT_LT(e, previous / 1.8);
        previous = e;
    }
    EXPECT_LT(previous, 1e-2);
}

TEST(FractureSampling, ExactLipJumpsGiveKExactly) {
    for (auto modelisation : {Modelisation::D_PLAN, Modelisation::C_PLAN}) {
        const auto coef = JumpCoefficients::of(kE, kNu, modelisation);
        const double eStar = modelisation == Modelisation::C_PLAN ? kE : kE / (1 - kNu * kNu);
        std::vector<double> s;
        std::array<std::vector<double>, 3> jump;
        for (int i = 0; i < 6; ++i) {
            s.push_back(0.02 * i);
            const double open = 8 / eStar * std::sqrt(s.back() / (2 * std::numbers::pi));
            jump[0].push_back(kK1 * open), jump[1].push_back(-kK2 * open), jump[2].push_back(0.0);
        }
        const auto k = extrapolateJumps(s, jump, coef);
        EXPECT_NEAR(k.K[0], kK1, 1e-9 * kK1);
        EXPECT_NEAR(k.K[1], -kK2, 1e-9 * kK1);
        EXPECT_NEAR(k.G, (kK1 * kK1 + kK2 * kK2) / eStar, 1e-9 * kK1 * kK1 / eStar);
        EXPECT_NEAR(k.err[0], 0.0, 1e-9);
        EXPECT_NEAR(k.err[1], 0.0, 1e-9);
    }
}

TEST(FractureSampling, JumpExtrapolationSpreadIsCodeAstersError) {
    // A jump that is not sqrt(s): the methods disagree and ERR_K1 says by how much.
    const auto coef = JumpCoefficients::of(kE, kNu, Modelisation::D_PLAN);
    const std::vector<double> s{0.0, 0.1, 0.2, 0.3};
    std::array<std::vector<double>, 3> jump{std::vector<double>{0.0, 1e-6, 1.5e-6, 1.8e-6}, std::vector<double>(4, 0.0),
                                            std::vector<double>(4, 0.0)};
    const auto k = extrapolateJumps(s, jump, coef);
    // method 1 on (0.1, 0.2) and (0.2, 0.3): K^2 extrapolated linearly in s from y/s
    auto y = [&](size_t i) { return std::pow(coef.coefd * jump[0][i], 2) / s[i]; };
    const double k1a = std::abs(y(1) - s[1] * (y(2) - y(1)) / (s[2] - s[1]));
    const double k1b = std::abs(y(2) - s[2] * (y(3) - y(2)) / (s[3] - s[2]));
    EXPECT_NEAR(k.K[0], std::sqrt(std::max(k1a, k1b)), 1e-9 * k.K[0]);
    EXPECT_GT(k.err[0], 0.01);
}

TEST(FractureSampling, HeavisideJumpsInterpolateTwiceH1) {
    std::vector<char> upper;
    auto mesh = seamMesh(8, upper);
    NodalField depl;
    depl.resize(mesh, {"DX", "DY", "H1X", "H1Y"});
    for (int a = 0; a < mesh->nodeCount(); ++a) {
        const Vec3& x = mesh->coords[size_t(a)];
        depl.set(a, 2, 1e-3 * (1 - x[0]));
        depl.set(a, 3, 2e-3 + 1e-3 * x[0]);
    }
    const auto samples = heavisideJumps(*mesh, depl, {0.1, 0.0, 0.0}, {1, 0, 0}, 0.8, 5);
    ASSERT_EQ(samples.abscissa.size(), 5u);
    for (size_t i = 0; i < 5; ++i) {
        const double x = 0.1 - 0.2 * double(i);
        EXPECT_NEAR(samples.abscissa[i], 0.2 * double(i), 1e-15);
        EXPECT_NEAR(samples.jump[i][0], 2e-3 * (1 - x), 1e-15);
        EXPECT_NEAR(samples.jump[i][1], 2 * (2e-3 + 1e-3 * x), 1e-15);
    }
    // beyond the mesh: dropped
    EXPECT_EQ(heavisideJumps(*mesh, depl, {0.1, 0.0, 0.0}, {1, 0, 0}, 2.0, 5).abscissa.size(), 3u);
    // 0.06 beyond the edge x = -1: kept within DISTANCE_MAX 0.1, with the values at x = -1
    const auto near = heavisideJumps(*mesh, depl, {0.1, 0.0, 0.0}, {1, 0, 0}, 1.16, 5, 0.1);
    ASSERT_EQ(near.abscissa.size(), 5u);
    EXPECT_NEAR(near.abscissa[4], 1.16, 1e-15);
    EXPECT_NEAR(near.jump[4][0], 2e-3 * 2, 1e-15);
    EXPECT_NEAR(near.jump[4][1], 2 * (2e-3 - 1e-3), 1e-15);
    EXPECT_EQ(heavisideJumps(*mesh, depl, {0.1, 0.0, 0.0}, {1, 0, 0}, 1.16, 5, 0.05).abscissa.size(), 4u);
}

// Near the front the Heaviside nodes end: code_aster's projection of an X-FEM DEPL (pjxfem)
// interpolates H1 over the nodes that carry it, the others adding nothing (no renormalisation),
// and adds the crack-tip terms' jump (given by the caller).
TEST(FractureSampling, HeavisideJumpsSkipNodesWithoutH1AndAddTheTipJump) {
    std::vector<char> upper;
    auto mesh = seamMesh(8, upper);  // cells 0.25 wide, the crack y = 0 for x < 0
    NodalField depl;
    depl.resize(mesh, {"DX", "DY", "H1X", "H1Y"});
    for (int a = 0; a < mesh->nodeCount(); ++a) {
        const Vec3& x = mesh->coords[size_t(a)];
        depl.set(a, 0, 1.0);
        if (x[0] <= -0.5 + 1e-12) depl.set(a, 2, 1e-3 * (1 - x[0]));
    }
    // x = -0.3 in [-0.5, -0.25]: on the seam only the node at x = -0.5 carries H1, with N = 0.2
    const auto inside = heavisideJumps(*mesh, depl, {-0.3, 0.0, 0.0}, {1, 0, 0}, 0.3, 2);
    ASSERT_EQ(inside.abscissa.size(), 2u);
    EXPECT_NEAR(inside.jump[0][0], 2 * 0.2 * 1.5e-3, 1e-15);
    EXPECT_NEAR(inside.jump[1][0], 2e-3 * 1.6, 1e-15);
    EXPECT_EQ(inside.jump[0][1], 0.0);
    // x = -0.1: no node of the cell carries H1; the tip jump alone
    const auto tip = [](const PointInCell&, std::span<const double> N) {
        double sum = 0.0;
        for (double v : N) sum += v;
        return Vec3{0.0, 5e-4 * sum, 0.0};
    };
    const auto near = heavisideJumps(*mesh, depl, {-0.1, 0.0, 0.0}, {1, 0, 0}, 0.5, 2, 0.0, tip);
    EXPECT_EQ(near.jump[0][0], 0.0);
    EXPECT_NEAR(near.jump[0][1], 5e-4, 1e-15);
    EXPECT_NEAR(near.jump[1][0], 2e-3 * 1.6, 1e-15);
}

}  // namespace
