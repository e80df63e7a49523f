#pragma once
// Internal to src/solver: the concrete solvers and shared checks.
#include <memory>
#include <span>

#include "solver/LinearSolver.hpp"

namespace ma {

std::unique_ptr<LinearSolver> makeMumpsSolver(const SolverOptions& options);
std::unique_ptr<LinearSolver> makeEigenSolver(const SolverOptions& options);

// NaN/Inf in the solution -> NumericalError; a large residual -> alarm (the caller decides what
// the residual means for convergence).
void checkSolution(std::span<const double> x, double residual, const SolverOptions& options);

}  // namespace ma
