// post/EquivalentStress: code_aster's 17 SIEQ components of stress tensors whose invariants are
// known in closed form (uniaxial, pure shear, hydrostatic), and of a general tensor checked against
// its own definition (principal pairs, the von Mises form in principal stresses).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "post/EquivalentStress.hpp"

namespace {

// One point of a 3D SIEF field holding SIXX SIYY SIZZ SIXY SIXZ SIYZ.
ma::GaussField onePoint(const std::array<double, 6>& s) {
    ma::GaussField f;
    f.name = "SIGM_ELGA";
    f.quantity = "SIEF_R";
    f.components = {"SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ"};
    f.cells = {0};
    f.pointOffsets = {0, 1};
    f.values.assign(s.begin(), s.end());
    return f;
}

std::map<std::string, double> sieq(const std::array<double, 6>& s) {
    const auto out = ma::post::equivalentStresses(onePoint(s));
    std::map<std::string, double> v;
    for (size_t c = 0; c < out->components.size(); ++c) v[out->components[c]] = out->values[c];
    return v;
}

TEST(EquivalentStress, UniaxialTension) {
    auto v = sieq({100.0, 0, 0, 0, 0, 0});
    EXPECT_NEAR(v["VMIS"], 100.0, 1e-12);
    EXPECT_NEAR(v["TRESCA"], 100.0, 1e-12);
    EXPECT_NEAR(v["PRIN_1"], 0.0, 1e-12);
    EXPECT_NEAR(v["PRIN_3"], 100.0, 1e-12);
    EXPECT_NEAR(v["VMIS_SG"], 100.0, 1e-12);
    EXPECT_NEAR(v["TRSIG"], 100.0, 1e-12);
    EXPECT_NEAR(v["TRIAX"], 1.0 / 3.0, 1e-15);
    EXPECT_NEAR(std::abs(v["VECT_3_X"]), 1.0, 1e-15);  // the largest principal stress is along x
    auto c = sieq({-100.0, 0, 0, 0, 0, 0});
    EXPECT_NEAR(c["VMIS_SG"], -100.0, 1e-12);  // signed by the trace
    EXPECT_NEAR(c["PRIN_1"], -100.0, 1e-12);
}

TEST(EquivalentStress, PureShear) {
    auto v = sieq({0, 0, 0, 50.0, 0, 0});
    EXPECT_NEAR(v["VMIS"], std::sqrt(3.0) * 50.0, 1e-12);
    EXPECT_NEAR(v["TRESCA"], 100.0, 1e-12);
    EXPECT_NEAR(v["PRIN_1"], -50.0, 1e-12);
    EXPECT_NEAR(v["PRIN_2"], 0.0, 1e-12);
    EXPECT_NEAR(v["PRIN_3"], 50.0, 1e-12);
    EXPECT_NEAR(v["TRIAX"], 0.0, 1e-15);
    // The principal directions are the diagonals of the xy plane.
    EXPECT_NEAR(std::abs(v["VECT_3_X"]), std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(std::abs(v["VECT_3_Y"]), std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(std::abs(v["VECT_2_Z"]), 1.0, 1e-12);
}

TEST(EquivalentStress, HydrostaticHasNoVonMisesAndNoTriaxiality) {
    auto v = sieq({-7.0, -7.0, -7.0, 0, 0, 0});
    EXPECT_NEAR(v["VMIS"], 0.0, 1e-12);
    EXPECT_NEAR(v["TRESCA"], 0.0, 1e-12);
    EXPECT_EQ(v["TRIAX"], 0.0);  // VMIS ~ 0: code_aster's fgequi gives 0, not +-infinity
    EXPECT_NEAR(v["TRSIG"], -21.0, 1e-12);
    auto zero = sieq({0, 0, 0, 0, 0, 0});
    for (const auto& [name, value] : zero) EXPECT_EQ(value, 0.0) << name;
}

TEST(EquivalentStress, GeneralTensorSatisfiesItsDefinitions) {
    const std::array<double, 6> s{12.0, -3.0, 5.0, 4.0, -2.5, 1.5};
    auto v = sieq(s);
    Eigen::Matrix3d t;
    t << s[0], s[3], s[4], s[3], s[1], s[5], s[4], s[5], s[2];
    const double p1 = v["PRIN_1"], p2 = v["PRIN_2"], p3 = v["PRIN_3"];
    EXPECT_LE(p1, p2);
    EXPECT_LE(p2, p3);
    EXPECT_NEAR(p1 + p2 + p3, t.trace(), 1e-12);
    EXPECT_NEAR(p1 * p2 * p3, t.determinant(), 1e-9);
    EXPECT_NEAR(v["VMIS"], std::sqrt(0.5 * ((p1 - p2) * (p1 - p2) + (p2 - p3) * (p2 - p3) + (p3 - p1) * (p3 - p1))),
                1e-12);
    EXPECT_NEAR(v["TRESCA"], p3 - p1, 1e-12);
    const char* names[3] = {"VECT_1_", "VECT_2_", "VECT_3_"};
    const double principal[3] = {p1, p2, p3};
    for (int i = 0; i < 3; ++i) {
        const std::string n = names[i];
        const Eigen::Vector3d d(v[n + "X"], v[n + "Y"], v[n + "Z"]);
        EXPECT_NEAR(d.norm(), 1.0, 1e-12);
        EXPECT_NEAR((t * d - principal[i] * d).norm(), 0.0, 1e-11) << n;
    }
}

// In 2D the tensor is SIXX SIYY SIZZ SIXY with no out-of-plane shear.
TEST(EquivalentStress, PlaneFieldsUseTheirOutOfPlaneStress) {
    ma::GaussField f;
    f.components = {"SIXX", "SIYY", "SIZZ", "SIXY"};
    f.cells = {0};
    f.pointOffsets = {0, 1};
    f.values = {-2.0, -1.0, -0.9, 0.0};  // D_PLAN, nu = 0.3
    const auto out = ma::post::equivalentStresses(f);
    ASSERT_EQ(out->components.size(), 17u);
    EXPECT_NEAR(out->values[2], -2.0, 1e-15);  // PRIN_1
    EXPECT_NEAR(out->values[3], -1.0, 1e-15);  // PRIN_2
    EXPECT_NEAR(out->values[4], -0.9, 1e-15);  // PRIN_3
    EXPECT_NEAR(out->values[1], 1.1, 1e-15);   // TRESCA
}

}  // namespace
