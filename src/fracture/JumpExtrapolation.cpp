#include "fracture/JumpExtrapolation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ma::fracture {

JumpCoefficients JumpCoefficients::of(double E, double nu, Modelisation modelisation) {
    JumpCoefficients c;
    const double base = E * std::sqrt(2 * std::numbers::pi);
    c.coefg3 = (1 + nu) / E;
    if (modelisation == Modelisation::C_PLAN) {
        c.coefd = base / 8;
        c.coefg = 1 / E;
    } else {
        c.coefd = base / (8 * (1 - nu * nu));
        c.coefg = (1 - nu * nu) / E;
        if (modelisation == Modelisation::TRI_D) c.coefd3 = base / (8 * (1 + nu));
    }
    return c;
}

namespace {

// One method's K^2 values per component and G values, over its pairs or points.
struct MethodValues {
    std::array<std::vector<double>, 3> k2;
    std::vector<double> g;
};

struct Extremes {
    std::array<double, 3> kMax{}, kMin{};
    double gMax = 0.0;
};

Extremes extremes(const MethodValues& m, const std::array<double, 3>& sign, bool alreadySigned) {
    Extremes e;
    for (int c = 0; c < 3; ++c) {
        const auto [lo, hi] = std::minmax_element(m.k2[size_t(c)].begin(), m.k2[size_t(c)].end());
        // code_aster: sqrt of the largest and smallest K^2, times the sign of the last jump
        e.kMax[size_t(c)] = alreadySigned ? *hi : std::sqrt(*hi) * sign[size_t(c)];
        e.kMin[size_t(c)] = alreadySigned ? *lo : std::sqrt(*lo) * sign[size_t(c)];
    }
    e.gMax = *std::max_element(m.g.begin(), m.g.end());
    return e;
}

double gOf(const JumpCoefficients& c, double k1, double k2, double k3) { return c.coefg * (k1 + k2) + c.coefg3 * k3; }

}  // namespace

JumpSifs extrapolateJumps(const std::vector<double>& s, const std::array<std::vector<double>, 3>& jump,
                          const JumpCoefficients& coef) {
    const size_t n = s.size();
    std::array<std::vector<double>, 3> y;
    std::array<double, 3> sign{};
    const double scale[3] = {coef.coefd, coef.coefd, coef.coefd3};
    for (int c = 0; c < 3; ++c) {
        for (size_t i = 0; i < n; ++i) y[size_t(c)].push_back(std::pow(scale[c] * jump[size_t(c)][i], 2));
        // numpy's sign(sign(x) + 0.001): a zero jump counts as positive
        sign[size_t(c)] = jump[size_t(c)].back() < 0 ? -1.0 : 1.0;
    }
    MethodValues m1, m2, m3;
    for (size_t i = 1; i + 1 < n; ++i) {  // method 1: (s_i, s_i+1), i >= 1
        double k[3];
        for (int c = 0; c < 3; ++c) {
            const double y1 = y[size_t(c)][i] / s[i], y2 = y[size_t(c)][i + 1] / s[i + 1];
            k[c] = std::abs(y1 - s[i] * (y2 - y1) / (s[i + 1] - s[i]));
            m1.k2[size_t(c)].push_back(k[c]);
        }
        m1.g.push_back(gOf(coef, k[0], k[1], k[2]));
    }
    for (size_t i = 1; i < n; ++i) {  // method 2
        double k[3];
        for (int c = 0; c < 3; ++c) m2.k2[size_t(c)].push_back(k[c] = std::abs(y[size_t(c)][i] / s[i]));
        m2.g.push_back(gOf(coef, k[0], k[1], k[2]));
    }
    double k3[3];  // method 3: already K (signed)
    for (int c = 0; c < 3; ++c) {
        double sum = 0.0;
        for (size_t i = 0; i + 1 < n; ++i)
            sum += (std::sqrt(y[size_t(c)][i + 1] * s[i + 1]) + std::sqrt(y[size_t(c)][i] * s[i])) * (s[i + 1] - s[i]);
        k3[c] = sum / (s.back() * s.back()) * sign[size_t(c)];
        m3.k2[size_t(c)] = {k3[c]};
    }
    m3.g = {gOf(coef, k3[0] * k3[0], k3[1] * k3[1], k3[2] * k3[2])};
    const Extremes e1 = extremes(m1, sign, false), e2 = extremes(m2, sign, false), e3 = extremes(m3, sign, true);
    JumpSifs out;
    out.G = e1.gMax;
    double kMaxMax = -1e300;
    std::array<double, 3> kMax{}, kMin{};
    for (size_t c = 0; c < 3; ++c) {
        out.K[c] = e1.kMax[c];
        kMax[c] = std::max({e1.kMax[c], e2.kMax[c], e3.kMax[c]});
        kMin[c] = std::min({e1.kMin[c], e2.kMin[c], e3.kMin[c]});
    }
    const size_t components = coef.coefd3 > 0 ? 3 : 2;
    for (size_t c = 0; c < components; ++c) kMaxMax = std::max(kMaxMax, kMax[c]);
    if (std::abs(kMaxMax) > 1e-15)
        for (size_t c = 0; c < components; ++c) out.err[c] = (kMax[c] - kMin[c]) / kMaxMax;
    return out;
}

}  // namespace ma::fracture
