#include "solver/LinearSolver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "core/Timing.hpp"
#include "solver/LinearSolverImpl.hpp"
#include "solver/SolverMessages.hpp"

namespace ma {

std::unique_ptr<LinearSolver> makeLinearSolver(const SolverOptions& options) {
    if (options.method == "MUMPS") return makeMumpsSolver(options);
    if (options.method == "MULT_FRONT" || options.method == "LDLT") return makeEigenSolver(options);
    if (options.krylov()) return makePetscSolver(options);
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
            throw SingularSystemError(
                "singular system: the solution contains NaN or Inf. Likely cause: " + options.singularHint + ".");
    // With RESI_RELA the check is an error (ScaledDirectSolver::solve); without it, an alarm.
    if (options.resiRela <= 0.0 && (!std::isfinite(residual) || residual > 1e-6)) msg().alarm(FACTOR_57, residual);
}

std::vector<double> symmetricDiagonalScaling(const CsrMatrix& A) { return scalingFromDiagonal(A, diagonalOf(A)); }

std::vector<double> diagonalOf(const CsrMatrix& A) {
    std::vector<double> d(size_t(A.rows), 0.0);
    for (int i = 0; i < A.rows; ++i)
        if (const long long k = A.find(i, i); k >= 0) d[size_t(i)] = A.values[size_t(k)];
    return d;
}

std::vector<double> scalingFromDiagonal(const CsrMatrix& A, std::span<const double> diagonal) {
    std::vector<double> s(size_t(A.rows), 0.0);
    std::vector<int> zeroDiagonal;
    for (int i = 0; i < A.rows; ++i) {
        const double d = std::abs(diagonal[size_t(i)]);
        if (d > 0.0 && std::isfinite(d)) s[size_t(i)] = 1.0 / std::sqrt(d);
        else zeroDiagonal.push_back(i);
    }
    for (int i : zeroDiagonal) {
        double m = 0.0;
        for (long long k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k)
            if (s[size_t(A.cols[k])] > 0.0) m = std::max(m, std::abs(A.values[k]) * s[size_t(A.cols[k])]);
        s[size_t(i)] = m > 0.0 && std::isfinite(m) ? 1.0 / m : 1.0;
    }
    return s;
}

namespace {

// The norms of residualOf over rows [begin, end); xMax = ||x||_inf.
ResidualNorms residualRows(const CsrMatrix& A, std::span<const double> x, std::span<const double> b,
                           std::vector<double>& r, int begin, int end, double xMax) {
    ResidualNorms norms(A.rows);
    for (int i = begin; i < end; ++i) {
        long double ri = b[i], scale = std::abs(b[i]);
        double rowMax = 0.0;
        for (long long k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) {
            const long double p = static_cast<long double>(A.values[k]) * x[A.cols[k]];
            ri -= p;
            scale += std::abs(p);
            rowMax = std::max(rowMax, std::abs(A.values[k]));
        }
        r[i] = static_cast<double>(ri);
        norms.add(ri, scale, b[i], static_cast<long double>(rowMax) * xMax);
    }
    return norms;
}

}  // namespace

ResidualInfo residualOf(const CsrMatrix& A, std::span<const double> x, std::span<const double> b,
                        std::vector<double>& r, int threads) {
    r.resize(A.rows);
    // Fixed blocks of rows, merged in block order: the same bits for any number of threads.
    constexpr int kBlockRows = 1 << 16;
    const int blocks = (A.rows + kBlockRows - 1) / kBlockRows;
    std::vector<ResidualNorms> partial(static_cast<size_t>(blocks));
    double xMax = 0.0;
    for (double v : x) xMax = std::max(xMax, std::abs(v));
    std::atomic<int> next = 0;
    auto work = [&] {
        for (int k = next++; k < blocks; k = next++)
            partial[k] = residualRows(A, x, b, r, k * kBlockRows, std::min(A.rows, (k + 1) * kBlockRows), xMax);
    };
    std::vector<std::thread> workers;
    for (int t = 1; t < std::min(threads, blocks); ++t) workers.emplace_back(work);
    work();
    for (auto& w : workers) w.join();
    ResidualNorms all(A.rows);
    for (const ResidualNorms& p : partial) all.merge(p);
    return all.info();
}

void ResidualNorms::add(long double ri, long double scale, double bi, long double rowTimesX) {
    num_ += ri * ri;
    den_ += static_cast<long double>(bi) * bi;
    if (ri == 0.0L) return;
    const double e = std::abs(double(ri));
    componentwise_ = std::max(componentwise_, scale > 0.0L ? double(e / scale) : INFINITY);
    // Arioli, Demmel and Duff (1989): a scale below 1000 n eps of the row's size is round-off.
    const long double tau = 1000.0L * static_cast<long double>(n_) * std::numeric_limits<double>::epsilon() *
                            (rowTimesX + std::abs(static_cast<long double>(bi)));
    if (scale > tau) omega1_ = std::max(omega1_, double(e / scale));
    else {
        const long double wide = scale - std::abs(static_cast<long double>(bi)) + rowTimesX;
        omega2_ = std::max(omega2_, wide > 0.0L ? double(e / wide) : INFINITY);
    }
}

void ResidualNorms::merge(const ResidualNorms& other) {
    num_ += other.num_, den_ += other.den_, componentwise_ = std::max(componentwise_, other.componentwise_);
    omega1_ = std::max(omega1_, other.omega1_), omega2_ = std::max(omega2_, other.omega2_);
}

ResidualInfo ResidualNorms::info() const {
    ResidualInfo info;
    info.normwise = double(den_ > 0.0L ? std::sqrt(num_ / den_) : std::sqrt(num_));
    info.componentwise = componentwise_;
    info.omega = omega1_ + omega2_;
    return info;
}

namespace {

// The range of |K_ii| the scaling evens out, in the .mess.
void logDiagonalRange(std::span<const double> diagonal) {
    double dmin = INFINITY, dmax = 0.0;
    int zero = 0;
    for (double v : diagonal) {
        const double d = std::abs(v);
        if (d > 0.0) dmin = std::min(dmin, d), dmax = std::max(dmax, d);
        else ++zero;
    }
    msg().infof("    diagonal scaling D^-1/2 K D^-1/2: |K_ii| from {:.3e} to {:.3e} (ratio {:.1e}){}", dmin, dmax,
                dmax > 0.0 ? dmin / dmax : 0.0,
                zero ? fmt::format(", {} zero-diagonal row(s) (multipliers) scaled by their entries", zero) : "");
}

}  // namespace

std::vector<double> diagonalScalingOf(const CsrMatrix& A, const SolverOptions& options) {
    if (!options.diagonalScaling) return std::vector<double>(size_t(A.rows), 1.0);
    const std::vector<double> diagonal = options.distributed ? summedDiagonal(A) : diagonalOf(A);
    logDiagonalRange(diagonal);
    return options.distributed ? distributedDiagonalScaling(A, diagonal) : scalingFromDiagonal(A, diagonal);
}

void ScaledDirectSolver::factorize(const CsrMatrix& A, MatrixKind kind, std::span<const RowPoint> rowPoints) {
    factorizeWith(A, diagonalScalingOf(A, options_), kind, rowPoints);
}

void ScaledDirectSolver::factorizeWith(const CsrMatrix& A, std::vector<double> scale, MatrixKind kind,
                                       std::span<const RowPoint> rowPoints) {
    if (scale.size() != size_t(A.rows)) throw InternalError("diagonal scaling of the wrong size for the matrix");
    A_ = &A;
    scale_ = std::move(scale);
    factorizeScaled(A, scale_, kind, rowPoints);
}

ResidualInfo ScaledDirectSolver::residual(std::span<const double> x, std::span<const double> b,
                                          std::vector<double>& r) const {
    return options_.distributed ? distributedResidualOf(*A_, x, b, r) : residualOf(*A_, x, b, r, options_.threads);
}

double ScaledDirectSolver::solve(std::span<double> rhs) {
    const auto t0 = std::chrono::steady_clock::now();
    const int n = A_->rows;
    const std::vector<double> b(rhs.begin(), rhs.end());
    std::vector<double> y(n), r;
    auto correction = [&](std::span<const double> v, std::span<double> out) {  // out = S (SAS)^-1 S v
        for (int i = 0; i < n; ++i) y[i] = scale_[i] * v[i];
        solveScaled(y);
        for (int i = 0; i < n; ++i) out[i] = scale_[i] * y[i];
    };
    correction(b, rhs);
    ResidualInfo res = residual(rhs, b, r);
    const ResidualInfo first = res;
    // One refinement step always (cheap next to the factorisation; it gains the last digits the
    // lip displacements need, measured in docs/xfem.md), more while the componentwise backward
    // error is above round-off and at least halves. Single-precision factors (MIXER_PRECISION) gain
    // about -log10(cond * 6e-8) digits a step: they refine up to kMixedMaxSteps steps.
    constexpr double kRoundOff = std::numeric_limits<double>::epsilon();
    const int maxSteps = options_.mixedPrecision ? kMixedMaxSteps : options_.maxRefinementSteps;
    int steps = 0;
    std::vector<double> dx(n), candidate(n), rNew;
    // Single-precision factors refine to convergence: judged by Arioli, Demmel and Duff's omega, so
    // that rows around a block held at zero (their own scale round-off) do not stop them.
    const auto backward = [&](const ResidualInfo& info) {
        return options_.mixedPrecision ? info.omega : info.componentwise;
    };
    while (steps < maxSteps && std::isfinite(backward(res)) && (steps == 0 || backward(res) > kRoundOff)) {
        correction(r, dx);
        for (int i = 0; i < n; ++i) candidate[i] = rhs[i] + dx[i];
        const ResidualInfo next = residual(candidate, b, rNew);
        if (!(backward(next) < backward(res))) break;  // no longer helps: keep the better one
        std::copy(candidate.begin(), candidate.end(), rhs.begin());
        r.swap(rNew);
        const bool slow = backward(next) > 0.5 * backward(res);
        res = next;
        ++steps;
        if (slow) break;
    }
    msg().infof(
        "    {} solve {:.3f} s, relative residual ||Ku-f||/||f|| = {:.3e}, componentwise backward error "
        "{:.2e}{}{}",
        name(), secondsSince(t0), res.normwise, res.componentwise,
        options_.mixedPrecision ? fmt::format(" (Arioli-Demmel-Duff's omega {:.2e})", res.omega) : std::string(),
        steps ? fmt::format(" after {} refinement step(s) (before: {:.3e}, {:.2e}{})", steps, first.normwise,
                            first.componentwise,
                            options_.mixedPrecision ? fmt::format(", omega {:.2e}", first.omega) : std::string())
              : std::string(maxSteps ? "" : " (no refinement)"));
    checkSolution(rhs, res.normwise, options_);
    checkAccuracy(res, steps);
    return res.normwise;
}

void ScaledDirectSolver::checkAccuracy(const ResidualInfo& res, int steps) const {
    const bool mixed = options_.mixedPrecision;
    const char* why = mixed ? "the matrix is too ill-conditioned for single-precision factors: use "
                              "SOLVEUR/MIXER_PRECISION='NON'"
                            : "ill-conditioned or nearly singular system";
    if (options_.resiRela > 0.0 && !(res.normwise <= options_.resiRela))
        throw NumericalError(fmt::format(
            "linear solver {}: the relative residual ||Ku-f||/||f|| = {:.3e} after {} refinement step(s) is above "
            "SOLVEUR/RESI_RELA = {:g}: {}",
            name(), res.normwise, steps, options_.resiRela, why));
    if (mixed && options_.resiRela <= 0.0 && !(res.omega <= kMixedBackwardError))
        throw NumericalError(
            fmt::format("linear solver {}: the iterative refinement of the single-precision factors did not converge: "
                        "backward error (Arioli-Demmel-Duff's omega) {:.2e} after {} step(s), above the {:.0e} a "
                        "double-precision factorisation reaches (relative residual {:.3e}; SOLVEUR/RESI_RELA unset): "
                        "{}",
                        name(), res.omega, steps, kMixedBackwardError, res.normwise, why));
}

}  // namespace ma
