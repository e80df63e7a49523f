#pragma once
// The Newton iterations of one load increment and their convergence criterion (code_aster's
// nmresi): max |R| over the equations (RESI_GLOB_MAXI), relative to the largest of the external
// forces and reactions (RESI_GLOB_RELA). The system is
//     [ K      alpha*C^T ] [du]   = -[ F_int(u) - F_ext + alpha*C^T*lambda ]
//     [ alpha*C    0     ] [dlam]    [ alpha*(C*u - v)                     ]
// with the eliminated dofs already at their values in u.
#include <chrono>
#include <functional>
#include <vector>

#include "fe/AdditionalTerms.hpp"
#include "fe/DirichletConstraints.hpp"

namespace ma {

// STAT_NON_LINE's CONVERGENCE (its defaults are the catalogue's); as constructed: one solve and
// no convergence test (MECA_STATIQUE: the problem is linear).
struct ConvergenceOptions {
    int maxIterations = 0;       // ITER_GLOB_MAXI: iterations 0 .. maxIterations
    double resiGlobMaxi = -1.0;  // < 0: not checked
    double resiGlobRela = -1.0;  // < 0: not checked
    bool stopOnFailure = true;   // ARRET='OUI'
};

struct IncrementReport {
    int iterations = 0;
    double maxResidual = 0.0;       // max_i |R_i| (RESI_GLOB_MAXI)
    double relativeResidual = 0.0;  // max_i |R_i| / max_i |B^T lambda - F_ext|_i (RESI_GLOB_RELA)
    bool converged = false;
};

// What the iterations work on: the problem's constraints, its forces and its linear solve.
struct NewtonSystem {
    const DirichletConstraints& constraints;
    double alpha = 1.0;               // multiplier scaling of the matrix
    int ndof = 0;                     // displacement dofs; the additional unknowns follow
    const std::vector<double>& fext;  // F_ext at the increment's instant
    std::function<void(const std::vector<double>& u, std::vector<double>& fint)> internalForces;
    const AdditionalTerms* additional = nullptr;
    std::function<void(std::vector<double>& rhs)> solve;  // right-hand side in, correction out
    std::chrono::steady_clock::time_point start;          // of the increment (its logged time)
    // Each process computes the additional terms' residual on its own cells: summed here.
    bool distributed = false;
    // Loads and reactions below this fraction of the elastic force scale are the linear solver's
    // noise (round-off for a direct solver; a Krylov method's tolerance leaves more).
    double negligibleLoad = 1e-12;
};

// Iterates from the state (u, lambda) at instant inst until the criterion holds or
// ITER_GLOB_MAXI; logs every iteration. Not converged: NumericalError (ARRET='OUI') or an alarm.
IncrementReport newtonIterations(const NewtonSystem& system, double inst, const ConvergenceOptions& options,
                                 std::vector<double>& u, std::vector<double>& lambda);

}  // namespace ma
