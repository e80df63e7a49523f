#include "fracture/WilliamsFields.hpp"

#include <cmath>
#include <numbers>

namespace ma::fracture {

namespace {

// u_i = sqrt(r) f_i(theta) / (2 mu sqrt(2 pi)) (modes I, II), the angular parts and their
// derivatives.
struct Angular {
    double f[3]{};
    double df[3]{};
};

Angular angularPart(Mode mode, double t, double kappa) {
    const double c2 = std::cos(t / 2), s2 = std::sin(t / 2), c = std::cos(t), s = std::sin(t);
    Angular a;
    switch (mode) {
        case Mode::I:
            a.f[0] = c2 * (kappa - c);
            a.f[1] = s2 * (kappa - c);
            a.df[0] = -0.5 * s2 * (kappa - c) + c2 * s;
            a.df[1] = 0.5 * c2 * (kappa - c) + s2 * s;
            break;
        case Mode::II:
            a.f[0] = s2 * (kappa + 2 + c);
            a.f[1] = -c2 * (kappa - 2 + c);
            a.df[0] = 0.5 * c2 * (kappa + 2 + c) - s2 * s;
            a.df[1] = 0.5 * s2 * (kappa - 2 + c) + c2 * s;
            break;
        case Mode::III:  // u3 = 4 sqrt(r) sin(theta/2) / (2 mu sqrt(2 pi))
            a.f[2] = 4 * s2;
            a.df[2] = 2 * c2;
            break;
    }
    return a;
}

}  // namespace

LocalField williamsField(Mode mode, double r, double theta, double mu, double kappa) {
    const Angular a = angularPart(mode, theta, kappa);
    const double scale = 1.0 / (2 * mu * std::sqrt(2 * std::numbers::pi));
    const double sr = std::sqrt(r);
    const double c = std::cos(theta), s = std::sin(theta);
    LocalField out;
    for (int i = 0; i < 3; ++i) {
        out.u[i] = scale * sr * a.f[i];
        // du/dr = f / (2 sqrt r), du/dtheta = sqrt r f'; x1 = r cos, x2 = r sin.
        const double dr = scale * a.f[i] / (2 * sr), dt = scale * sr * a.df[i];
        out.grad[i][0] = c * dr - s * dt / r;
        out.grad[i][1] = s * dr + c * dt / r;
        out.grad[i][2] = 0.0;
    }
    return out;
}

}  // namespace ma::fracture
