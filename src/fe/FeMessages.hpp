#pragma once
// The finite-element engine's alarms: materials, Newton (docs/messages.md).
#include <string>

#include "core/Message.hpp"

namespace ma {

// Where (a keyword path, or "material M"), NU, 1 - 2 NU, lambda/mu.
inline constexpr Message<std::string, double, double, double> MATERIAL_1_INCOMPRESSIBLE{
    "MATERIAL_1",
    "{}: NU = {} is nearly incompressible in 3D and plane strain (1 - 2 NU = {:.1e}, lambda/mu = {:.1e}): the "
    "stiffness matrix is singular to working precision (displacement elements lock); use NU <= 0.4999"};
// Where, NU, 1 + NU.
inline constexpr Message<std::string, double, double> MATERIAL_1_SHEAR_INFINITE{
    "MATERIAL_1",
    "{}: NU = {} is close to -1 (1 + NU = {:.1e}): the shear modulus E/(2(1+NU)) is nearly infinite and the "
    "stiffness matrix singular to working precision"};
// INST, ITER_GLOB_MAXI, RESI_GLOB_RELA, RESI_GLOB_MAXI reached. With ARRET='OUI' the first line is the error.
inline constexpr Message<double, int, double, double> MECANONLINE5_37{
    "MECANONLINE5_37",
    "Newton did not converge at INST {} in {} iterations (ITER_GLOB_MAXI): RESI_GLOB_RELA = {:.3e}, "
    "RESI_GLOB_MAXI = {:.3e}\nARRET='NON': the computation goes on with this unconverged state."};

inline constexpr MessageText feMessages[] = {entry(MATERIAL_1_INCOMPRESSIBLE), entry(MATERIAL_1_SHEAR_INFINITE),
                                             entry(MECANONLINE5_37)};

}  // namespace ma
