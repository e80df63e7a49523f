#pragma once
// The linear solvers' alarms (docs/messages.md).
#include <string>

#include "core/Message.hpp"

namespace ma {

inline constexpr Message<double> FACTOR_57{
    "FACTOR_57",
    "The relative residual of the linear solve is {:.3e}: the solution is inaccurate (ill-conditioned or nearly "
    "singular system)."};
// The count of negative pivots (MUMPS INFOG(12)).
inline constexpr Message<int> FACTOR_10{
    "FACTOR_10",
    "MUMPS found {} negative pivot(s) in a stiffness matrix that should be positive definite (inverted or "
    "degenerate elements?)"};

// SOLVEUR/ACCELERATION='FR+' or 'FR++' on the public MUMPS.
inline constexpr Message<std::string> FACTOR_48{
    "FACTOR_48",
    "SOLVEUR/ACCELERATION='{}' asks for the aggressive full-rank optimisations of the consortium version of "
    "MUMPS; the public MUMPS 5.5.1 of this system has none: the factorisation is the plain full-rank one "
    "(ACCELERATION='FR')"};

inline constexpr MessageText solverMessages[] = {entry(FACTOR_57), entry(FACTOR_10), entry(FACTOR_48)};

}  // namespace ma
