#include "solver/LinearSolver.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "solver/LinearSolverImpl.hpp"

namespace ma {

std::unique_ptr<LinearSolver> makeLinearSolver(const SolverOptions& options) {
    if (options.method == "MUMPS") return makeMumpsSolver(options);
    if (options.method == "MULT_FRONT" || options.method == "LDLT") return makeEigenSolver(options);
    if (options.method == "GCPC" || options.method == "PETSC")
        throw NotImplemented("SOLVEUR/METHODE='" + options.method +
                             "': miniaster has only direct solvers (MUMPS, MULT_FRONT, LDLT)");
    throw UserError("SOLVEUR/METHODE='" + options.method + "' is not a solver method");
}

double relativeResidual(const CsrMatrix& A, std::span<const double> x, std::span<const double> b) {
    std::vector<double> r(A.rows);
    A.multiply(x, r);
    double num = 0.0, den = 0.0;
    for (int i = 0; i < A.rows; ++i) {
        num += (r[i] - b[i]) * (r[i] - b[i]);
        den += b[i] * b[i];
    }
    return den > 0.0 ? std::sqrt(num / den) : std::sqrt(num);
}

void checkSolution(std::span<const double> x, double residual, const SolverOptions& options) {
    for (double v : x)
        if (!std::isfinite(v))
            throw NumericalError("singular system: the solution contains NaN or Inf. Likely cause: " +
                                 options.singularHint + ".");
    if (!std::isfinite(residual) || residual > 1e-6)
        msg().alarm("FACTOR_57", fmt::format("The relative residual of the linear solve is {:.3e}: the solution "
                                             "is inaccurate (ill-conditioned or nearly singular system).",
                                             residual));
}

}  // namespace ma
