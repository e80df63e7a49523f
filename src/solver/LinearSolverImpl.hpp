#pragma once
// Internal to src/solver: the concrete solvers and what they share (scaling, refinement, checks).
#include <memory>
#include <span>
#include <vector>

#include "solver/LinearSolver.hpp"

namespace ma {

std::unique_ptr<LinearSolver> makeMumpsSolver(const SolverOptions& options);
std::unique_ptr<LinearSolver> makeEigenSolver(const SolverOptions& options);
std::unique_ptr<LinearSolver> makePetscSolver(const SolverOptions& options);
class ScaledDirectSolver;
// MUMPS as the factors of a preconditioner (PRE_COND='LDLT_SP'/'LDLT_DP': options.mixedPrecision).
std::unique_ptr<ScaledDirectSolver> makeMumpsFactors(const SolverOptions& options);

// NaN/Inf in the solution -> NumericalError; a large residual -> alarm (the caller decides what
// the residual means for convergence).
void checkSolution(std::span<const double> x, double residual, const SolverOptions& options);

// Symmetric diagonal (Jacobi) scaling s with S A S of unit diagonal: s_i = |a_ii|^-1/2. Rows with
// a zero diagonal (Lagrange multipliers) get s_i = 1 / max_j |a_ij| s_j over the scaled columns,
// so that their entries are of order one too (1 when the row is empty: the pivot stays null).
std::vector<double> symmetricDiagonalScaling(const CsrMatrix& A);
// Its two steps: a_ii of each row (0 where the pattern lacks it), and s from those values.
std::vector<double> diagonalOf(const CsrMatrix& A);
std::vector<double> scalingFromDiagonal(const CsrMatrix& A, std::span<const double> diagonal);

// Residual r = b - A x accumulated in extended precision (long double) and the backward errors:
// normwise ||r|| / ||b||, componentwise max_i |r_i| / (|A| |x| + |b|)_i, and Arioli, Demmel and
// Duff's omega1 + omega2, which measures a row whose own scale is round-off (the solution is ~0
// around it: a block held at zero) against (|A| |x|)_i + ||A_i|| ||x|| instead; on `threads`
// threads, with the same result for any number of them.
struct ResidualInfo {
    double normwise = 0.0;
    double componentwise = 0.0;
    double omega = 0.0;
};
// The backward errors accumulated row by row from r_i, its scale |b_i| + (|A| |x|)_i and
// ||A_i||_inf ||x||_inf, for a system of n rows.
class ResidualNorms {
public:
    explicit ResidualNorms(long long n = 0) : n_(n) {}
    void add(long double ri, long double scale, double bi, long double rowTimesX);
    void merge(const ResidualNorms& other);  // the rows of `other` after these
    ResidualInfo info() const;

private:
    long long n_;
    long double num_ = 0.0L, den_ = 0.0L;
    double componentwise_ = 0.0, omega1_ = 0.0, omega2_ = 0.0;
};
ResidualInfo residualOf(const CsrMatrix& A, std::span<const double> x, std::span<const double> b,
                        std::vector<double>& r, int threads = 1);

// A distributed matrix (SolverOptions::distributed: the sum of the processes' parts, each with
// the whole pattern; solver/DistributedSystem.cpp). Its diagonal, summed; the scaling above from
// it (a zero-diagonal row scaled by the largest of the processes' partial entries); the residual
// b - A x with the products summed over the processes in extended precision (the componentwise
// scale |A| |x| from the partial entries: an upper bound).
std::vector<double> summedDiagonal(const CsrMatrix& A);
std::vector<double> distributedDiagonalScaling(const CsrMatrix& A, std::span<const double> diagonal);
// S as the direct solvers scale A under `options` (all ones without PRETRAITEMENTS; from the summed
// diagonal when distributed), the diagonal's range logged: the Krylov methods iterate on the S A S
// their factors are of, and hand S to them (ScaledDirectSolver::factorizeWith).
std::vector<double> diagonalScalingOf(const CsrMatrix& A, const SolverOptions& options);
ResidualInfo distributedResidualOf(const CsrMatrix& A, std::span<const double> x, std::span<const double> b,
                                   std::vector<double>& r);

// What MUMPS and Eigen share: the factorisation is done on S A S (S from
// symmetricDiagonalScaling), solutions are mapped back, the residual is measured on the unscaled
// system and, while the componentwise backward error is above a few ulps and keeps decreasing,
// iterative refinement steps (residual in extended precision, correction with the same factors)
// are made. Why: an enrichment whose support is cut in a small fraction f has a stiffness row of
// order f; a backward-stable solve determines it only to eps/f relative, which shows directly in
// the lip displacement. Refinement brings every row's equation to round-off of its own size.
class ScaledDirectSolver : public LinearSolver {
public:
    explicit ScaledDirectSolver(const SolverOptions& options) : options_(options) {}
    void factorize(const CsrMatrix& A, MatrixKind kind, std::span<const RowPoint> rowPoints = {}) final;
    // The same with S given (diagonalScalingOf's, computed by the caller): no second pass over A.
    void factorizeWith(const CsrMatrix& A, std::vector<double> scale, MatrixKind kind,
                       std::span<const RowPoint> rowPoints = {});
    double solve(std::span<double> rhs) final;
    // v <- (S A S)^-1 v with the factors alone: no refinement, no residual, no log (a
    // preconditioner's application to the scaled system).
    void applyFactors(std::span<double> v) { solveScaled(v); }
    // S (all ones when scaling is off), from the last factorize.
    const std::vector<double>& scale() const { return scale_; }

protected:
    // Factorise S A S (entries a_ij s_i s_j), S given by `scale` (all ones when scaling is off).
    virtual void factorizeScaled(const CsrMatrix& A, std::span<const double> scale, MatrixKind kind,
                                 std::span<const RowPoint> rowPoints) = 0;
    // Solve (S A S) y = rhs in place with the factors.
    virtual void solveScaled(std::span<double> rhs) = 0;

    SolverOptions options_;

    // MIXER_PRECISION: at most this many refinement steps, and without RESI_RELA the componentwise
    // backward error they must reach (a double-precision factorisation ends at ~1e-16).
    static constexpr int kMixedMaxSteps = 30;
    static constexpr double kMixedBackwardError = 1e-12;

private:
    // RESI_RELA, and the convergence of a mixed-precision refinement: a NumericalError naming the
    // solver, never a silent inaccurate answer.
    void checkAccuracy(const ResidualInfo& res, int steps) const;
    ResidualInfo residual(std::span<const double> x, std::span<const double> b, std::vector<double>& r) const;

    const CsrMatrix* A_ = nullptr;
    std::vector<double> scale_;
};

}  // namespace ma
