#pragma once
// POST_K1_K2_K3's stress intensity factors from the displacement jump of the crack lips at points
// behind the front (code_aster's post_k1_k2_k3_ops): with the jump [u] in the local basis (normal,
// propagation, front) at abscissae 0 = s_0 < s_1 < ... from the front and
//   y_i = (coefd [u_n](s_i))^2, (coefd [u_t])^2, (coefd3 [u_3])^2   (= K^2 s_i for Williams' field)
// method 1 extrapolates y/s linearly to s = 0 from consecutive pairs (s_i, s_i+1), i >= 1; method 2
// takes y_i / s_i, i >= 1; method 3 integrates sqrt(y s) with the trapezoidal rule and divides by
// s_max^2 / 2. K = sign of the last jump times sqrt(K^2); the table keeps method 1's largest K and
// G = coefg (K1^2 + K2^2) + coefg3 K3^2, and ERR_Ki = (max over the methods of Ki_MAX - min of
// Ki_MIN) / max_i Ki_MAX.
#include <array>
#include <vector>

#include "fe/Model.hpp"

namespace ma::fracture {

struct JumpCoefficients {
    double coefd = 0.0, coefd3 = 0.0, coefg = 0.0, coefg3 = 0.0;
    // code_aster's values for E, NU and the modelisation (D_PLAN and 3D alike; C_PLAN).
    static JumpCoefficients of(double E, double nu, Modelisation modelisation);
};

struct JumpSifs {
    std::array<double, 3> K{};    // K1, K2, K3 (method 1, K_MAX)
    std::array<double, 3> err{};  // ERR_K1, ERR_K2, ERR_K3
    double G = 0.0;               // method 1, G_MAX
};

// `jump[c][i]`: component c (normal, propagation, front) at abscissa s[i]; at least 3 points.
JumpSifs extrapolateJumps(const std::vector<double>& s, const std::array<std::vector<double>, 3>& jump,
                          const JumpCoefficients& coef);

}  // namespace ma::fracture
