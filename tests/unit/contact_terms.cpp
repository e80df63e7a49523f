// Contact terms (src/contact/ContactTerms): symmetric tangent (theta = 1 Nitsche, mixed penalty),
// consistency (a field without jump and with a uniform stress gives exactly the traction term
// int sigma_n g(v)), the tangent is the derivative of the residual, and the active-set logic
// (compression keeps contact, tension releases it, GLISSIERE keeps it).
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "contact_test_scene.hpp"

namespace {

using namespace ma;
using namespace ma::contact;
using contacttest::scene;
using contacttest::Scene;
using contacttest::uniformStrain;

std::map<std::pair<int, int>, double> tangent(const ContactTerms& t, const std::vector<double>& u) {
    std::map<std::pair<int, int>, double> K;
    t.tangent(u, [&](int i, int j, double v) { K[{i, j}] += v; });
    return K;
}

void expectSymmetric(const std::map<std::pair<int, int>, double>& K) {
    double scale = 0;
    for (const auto& [ij, v] : K) scale = std::max(scale, std::abs(v));
    ASSERT_GT(scale, 0.0);
    for (const auto& [ij, v] : K) {
        auto it = K.find({ij.second, ij.first});
        const double w = it == K.end() ? 0.0 : it->second;
        EXPECT_NEAR(v, w, 1e-13 * scale);
    }
}

TEST(ContactTerms, NitscheTangentIsSymmetricAndTheDerivativeOfTheResidual) {
    for (CellType type : {CellType::QUAD4, CellType::TRIA3, CellType::HEXA8}) {
        Scene s = scene(type, 5, ContactAlgorithm::Nitsche);
        const auto u0 = uniformStrain(s, -1e-3);
        const auto K = tangent(*s.terms, u0);
        expectSymmetric(K);
        // Linear terms with frozen statuses: R(u0 + du) - R(u0) = K du exactly.
        std::vector<double> du(u0.size());
        for (size_t i = 0; i < du.size(); ++i) du[i] = 1e-4 * std::sin(1.0 + 3.7 * double(i));
        std::vector<double> u1 = u0;
        for (size_t i = 0; i < du.size(); ++i) u1[i] += du[i];
        std::vector<double> R0(u0.size(), 0.0), R1(u0.size(), 0.0), Kdu(u0.size(), 0.0);
        s.terms->residual(u0, R0);
        s.terms->residual(u1, R1);
        for (const auto& [ij, v] : K) Kdu[ij.first] += v * du[ij.second];
        double scale = 0;
        for (double v : Kdu) scale = std::max(scale, std::abs(v));
        for (size_t i = 0; i < du.size(); ++i) EXPECT_NEAR(R1[i] - R0[i], Kdu[i], 1e-9 * scale);
    }
}

TEST(ContactTerms, ConsistentWithAUniformStressWithoutJump) {
    for (CellType type : {CellType::QUAD4, CellType::TRIA3, CellType::HEXA8, CellType::TETRA4}) {
        Scene s = scene(type, 5, ContactAlgorithm::Nitsche);
        const double eps = -1e-3;
        const auto u = uniformStrain(s, eps);
        // sigma = lambda' tr(eps) I + 2 mu eps: sigma_n on every interface (normal e_x or e_y).
        const double E = 1e8, nu = 0.3, dim = type == CellType::QUAD4 || type == CellType::TRIA3 ? 2 : 3;
        const double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
        const double sn = lam * dim * eps + 2 * mu * eps;
        std::vector<double> R(u.size(), 0.0), expected(u.size(), 0.0);
        s.terms->residual(u, R);
        for (size_t p = 0; p < s.terms->points().size(); ++p) {
            const auto& cp = s.terms->points()[p];
            EXPECT_NEAR(s.terms->gap(int(p), u), 0.0, 1e-15);
            EXPECT_NEAR(s.terms->normalStress(int(p), u), sn, 1e-9 * std::abs(sn));
            EXPECT_NEAR(s.terms->pressure(int(p), u), sn, 1e-9 * std::abs(sn));
            for (size_t i = 0; i < cp.dofs.size(); ++i) expected[cp.dofs[i]] += cp.weight * sn * cp.gap[i];
        }
        double scale = 0;
        for (double v : expected) scale = std::max(scale, std::abs(v));
        ASSERT_GT(scale, 0.0);
        for (size_t i = 0; i < R.size(); ++i) EXPECT_NEAR(R[i], expected[i], 1e-9 * scale);
    }
}

TEST(ContactTerms, ActiveSetKeepsCompressionReleasesTension) {
    Scene s = scene(CellType::QUAD4, 5, ContactAlgorithm::Nitsche);
    const int n = static_cast<int>(s.terms->points().size());
    auto st = s.terms->updateStatus(uniformStrain(s, -1e-3));
    EXPECT_EQ(st.changed, 0);
    EXPECT_EQ(st.active, n);
    st = s.terms->updateStatus(uniformStrain(s, 1e-3));
    EXPECT_EQ(st.changed, n);
    EXPECT_EQ(st.active, 0);
    EXPECT_GT(st.contactResidual, 0.0);
    // Inactive and compressed again: back in contact.
    st = s.terms->updateStatus(uniformStrain(s, -1e-3));
    EXPECT_EQ(st.active, n);
    // GLISSIERE='OUI': once in contact, always active.
    Scene b = scene(CellType::QUAD4, 5, ContactAlgorithm::Nitsche, true);
    st = b.terms->updateStatus(uniformStrain(b, 1e-3));
    EXPECT_EQ(st.changed, 0);
    EXPECT_EQ(st.active, n);
}

TEST(ContactTerms, PenaltyCarriesOnePressureUnknownPerPoint) {
    Scene s = scene(CellType::QUAD4, 5, ContactAlgorithm::Penalty);
    const int n = static_cast<int>(s.terms->points().size());
    EXPECT_EQ(s.terms->extraUnknowns(), n);
    EXPECT_EQ(int(s.problem->state().size()), s.problem->numbering().size() + n);
    expectSymmetric(tangent(*s.terms, s.problem->state()));
    // A closing gap activates, an opening one releases (statuses from the gap).
    auto st = s.terms->updateStatus(s.problem->state());  // zero gap: not interpenetrating
    EXPECT_EQ(st.active, 0);
}

}  // namespace
