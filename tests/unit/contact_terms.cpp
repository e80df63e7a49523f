// Contact terms (src/contact/ContactTerms): symmetric tangent (theta = 1 Nitsche, mixed penalty),
// consistency (a field without jump and with a uniform stress gives exactly the traction term
// int sigma_n g(v)), the tangent is the derivative of the residual, and the active-set logic
// (compression keeps contact, tension releases it, GLISSIERE keeps it, a sign at round-off level
// decides nothing), and the loop's record of the statuses (changes, repeated active sets, the points
// named when the loop cannot converge).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include <fmt/format.h>

#include "contact/ActiveSetHistory.hpp"
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

// A state where point 0's contact function cancels to `relative` of its terms (two of its unknowns
// set to opposite contributions).
std::vector<double> cancelling(const Scene& s, double relative) {
    const ContactPoint& cp = s.terms->points()[0];
    std::vector<double> u(s.problem->state().size(), 0.0);
    std::vector<size_t> used;
    for (size_t i = 0; i < cp.dofs.size() && used.size() < 2; ++i)
        if (std::abs(cp.stress[i] + cp.gamma * cp.gap[i]) > 1e-3 * cp.gamma) used.push_back(i);
    EXPECT_EQ(used.size(), 2u);
    u[cp.dofs[used[0]]] = 1e-3 / (cp.stress[used[0]] + cp.gamma * cp.gap[used[0]]);
    u[cp.dofs[used[1]]] = -(1.0 - relative) * 1e-3 / (cp.stress[used[1]] + cp.gamma * cp.gap[used[1]]);
    return u;
}

TEST(ContactTerms, ASignAtRoundOffLevelKeepsTheStatus) {
    Scene s = scene(CellType::QUAD4, 5, ContactAlgorithm::Nitsche);
    ASSERT_TRUE(s.terms->active()[0]);
    // Positive by 1e-12 of its terms: round-off, the point stays in contact; inactive, it stays out.
    const auto tiny = cancelling(s, 1e-12);
    const StatusFunction f = s.terms->statusFunction(0, tiny);
    EXPECT_GT(f.value, 0.0);
    EXPECT_LT(f.value, kStatusRoundOff * f.magnitude);
    s.terms->updateStatus(tiny);
    EXPECT_TRUE(s.terms->active()[0]);
    s.terms->updateStatus(cancelling(s, 1e-6));  // positive by 1e-6 of its terms: released
    EXPECT_FALSE(s.terms->active()[0]);
    s.terms->updateStatus(cancelling(s, -1e-12));  // negative at round-off: stays released
    EXPECT_FALSE(s.terms->active()[0]);
    s.terms->updateStatus(cancelling(s, -1e-6));
    EXPECT_TRUE(s.terms->active()[0]);
}

TEST(ContactTerms, TheHistoryFindsARepeatedActiveSetAndNamesTheFlippingPoints) {
    Scene s = scene(CellType::QUAD4, 5, ContactAlgorithm::Nitsche);
    ActiveSetHistory history(s.terms->active());
    const auto compressed = uniformStrain(s, -1e-3), stretched = uniformStrain(s, 1e-3);
    const int n = static_cast<int>(s.terms->points().size());
    s.terms->updateStatus(stretched);
    auto step = history.record(s.terms->active());
    EXPECT_EQ(step.released, n);
    EXPECT_EQ(step.activated, 0);
    EXPECT_EQ(step.repeats, -1);
    s.terms->updateStatus(compressed);
    step = history.record(s.terms->active());
    EXPECT_EQ(step.activated, n);
    EXPECT_EQ(step.repeats, 0);  // back to the initial statuses: a cycle
    EXPECT_EQ(history.changes(0), 2);
    const std::string text = history.flippingPoints(*s.terms, compressed, 3);
    EXPECT_EQ(text.find(" Points whose status changed more than once:\n  FISS"), 0u) << text;
    EXPECT_NE(text.find("point at ("), std::string::npos) << text;
    EXPECT_NE(text.find("facet in cell M"), std::string::npos) << text;
    EXPECT_NE(text.find("2 status change(s), now active"), std::string::npos) << text;
    EXPECT_NE(text.find(fmt::format("... and {} other point(s)", n - 3)), std::string::npos) << text;
    // An update that changes nothing repeats nothing.
    s.terms->updateStatus(compressed);
    EXPECT_EQ(history.record(s.terms->active()).repeats, -1);
}

TEST(ContactTerms, PenaltyCarriesOnePressureUnknownPerPoint) {
    Scene s = scene(CellType::QUAD4, 5, ContactAlgorithm::Penalty);
    const int n = static_cast<int>(s.terms->points().size());
    EXPECT_EQ(s.terms->extraUnknowns(), n);
    EXPECT_EQ(int(s.problem->state().size()), s.problem->numbering().size() + n);
    expectSymmetric(tangent(*s.terms, s.problem->state()));
    // Statuses from the gap; a gap that is zero (to round-off) decides nothing: the points keep the
    // status they have.
    const auto before = s.terms->active();
    auto st = s.terms->updateStatus(s.problem->state());
    EXPECT_EQ(st.changed, 0);
    EXPECT_EQ(s.terms->active(), before);
}

}  // namespace
