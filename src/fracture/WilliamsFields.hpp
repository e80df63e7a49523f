#pragma once
// Williams' asymptotic crack-tip displacement fields of unit stress intensity factor (modes I, II
// in the plane, III antiplane), in the local frame of a front point: x1 along the propagation
// direction, x2 normal to the crack (the side where theta = +pi), x3 along the front. These are the
// auxiliary fields of the interaction integrals (code_aster's chauxi) and the closed forms the
// fracture tests compare with. kappa = 3 - 4 nu (plane strain, 3D), (3 - nu)/(1 + nu) (plane stress).
#include "core/Vec3.hpp"

namespace ma::fracture {

struct LocalField {
    Vec3 u{};             // displacement in the local frame
    double grad[3][3]{};  // grad[i][j] = du_i / dx_j in the local frame
};

enum class Mode { I, II, III };

// The field of mode `mode` with K = 1 at polar coordinates (r, theta) around the front point
// (theta in [-pi, pi], +-pi on the lips), shear modulus mu.
LocalField williamsField(Mode mode, double r, double theta, double mu, double kappa);

}  // namespace ma::fracture
