#include "post/EquivalentStress.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "core/Error.hpp"

namespace ma::post {

namespace {

const std::vector<std::string> kComponents{"VMIS",     "TRESCA",   "PRIN_1",   "PRIN_2",   "PRIN_3",   "VMIS_SG",
                                           "VECT_1_X", "VECT_1_Y", "VECT_1_Z", "VECT_2_X", "VECT_2_Y", "VECT_2_Z",
                                           "VECT_3_X", "VECT_3_Y", "VECT_3_Z", "TRSIG",    "TRIAX"};

// code_aster's tolerance for TRIAX (fgequi): VMIS below tol * |trace| counts as zero.
constexpr double kTriaxTolerance = 1.0e-10;

// The 17 SIEQ components of one stress tensor.
void equivalentOf(const Eigen::Matrix3d& sigma, double* out) {
    const double trace = sigma.trace();
    const Eigen::Matrix3d s = sigma - trace / 3.0 * Eigen::Matrix3d::Identity();
    const double vmis = std::sqrt(1.5 * (s.array() * s.array()).sum());
    Eigen::Vector3d principal = Eigen::Vector3d::Zero();
    Eigen::Matrix3d directions = Eigen::Matrix3d::Zero();
    if (!sigma.isZero(0.0)) {
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(sigma);  // ascending eigenvalues
        principal = eigen.eigenvalues();
        directions = eigen.eigenvectors();
    }
    out[0] = vmis;
    out[1] = principal(2) - principal(0);
    for (int i = 0; i < 3; ++i) out[2 + i] = principal(i);
    out[5] = trace >= 0.0 ? vmis : -vmis;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out[6 + 3 * i + j] = directions(j, i);
    out[15] = trace;
    out[16] = vmis > kTriaxTolerance * std::abs(trace) ? trace / 3.0 / vmis : 0.0;
}

}  // namespace

std::shared_ptr<GaussField> equivalentStresses(const GaussField& sigma) {
    const auto index = [&](const char* c) { return sigma.componentIndex(c); };
    const int xx = index("SIXX"), yy = index("SIYY"), zz = index("SIZZ"), xy = index("SIXY");
    const int xz = index("SIXZ"), yz = index("SIYZ");
    if (xx < 0 || yy < 0 || zz < 0 || xy < 0)
        throw InternalError("equivalentStresses: the field " + sigma.name + " is not a stress field");
    auto out = std::make_shared<GaussField>(sigma);
    out->quantity = "SIEF_R";  // code_aster's SIEQ components belong to SIEF_R
    out->components = kComponents;
    const size_t nc = sigma.components.size(), points = sigma.values.size() / nc;
    out->values.assign(points * kComponents.size(), 0.0);
    for (size_t p = 0; p < points; ++p) {
        const double* v = &sigma.values[p * nc];
        const double sxz = xz >= 0 ? v[xz] : 0.0, syz = yz >= 0 ? v[yz] : 0.0;
        Eigen::Matrix3d t;
        t << v[xx], v[xy], sxz, v[xy], v[yy], syz, sxz, syz, v[zz];
        equivalentOf(t, &out->values[p * kComponents.size()]);
    }
    return out;
}

}  // namespace ma::post
