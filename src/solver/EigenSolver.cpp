// Eigen's sparse direct solvers: LDL^T (SimplicialLDLT, AMD ordering) for SPD systems, LU
// (SparseLU, COLAMD) when Lagrange multipliers make the system indefinite.
#include <fmt/format.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <chrono>
#include <cmath>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "core/Timing.hpp"
#include "solver/LinearSolverImpl.hpp"

namespace ma {

namespace {

class EigenSolver : public ScaledDirectSolver {
public:
    explicit EigenSolver(const SolverOptions& options) : ScaledDirectSolver(options) {}
    std::string name() const override { return "Eigen"; }

protected:
    void factorizeScaled(const CsrMatrix& A, std::span<const double> s, MatrixKind kind,
                         std::span<const RowPoint>) override {
        const auto t0 = std::chrono::steady_clock::now();
        std::vector<Eigen::Triplet<double>> triplets;
        triplets.reserve(A.nonZeros());
        for (int i = 0; i < A.rows; ++i)
            for (long long k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k)
                triplets.emplace_back(i, A.cols[k], s[i] * A.values[k] * s[A.cols[k]]);
        Eigen::SparseMatrix<double> M(A.rows, A.rows);
        M.setFromTriplets(triplets.begin(), triplets.end());
        M.makeCompressed();
        spd_ = kind == MatrixKind::SymmetricPositiveDefinite;
        const std::string singular = "singular system: the " + std::string(spd_ ? "LDL^T" : "LU") +
                                     " factorisation (SOLVEUR/METHODE='" + options_.method +
                                     "') met a null pivot. Likely cause: " + options_.singularHint + ".";
        if (spd_) {
            ldlt_.compute(M);
            if (ldlt_.info() != Eigen::Success) throw SingularSystemError(singular);
            const auto& d = ldlt_.vectorD();
            const double dmax = d.cwiseAbs().maxCoeff();
            const double dmin = d.cwiseAbs().minCoeff();
            if (options_.nprec >= 0 && (dmin <= std::pow(10.0, -options_.nprec) * dmax || d.minCoeff() <= 0.0))
                throw SingularSystemError(
                    fmt::format("{} (smallest/largest pivot {:.3e}/{:.3e})", singular, dmin, dmax));
        } else {
            lu_.compute(M);
            if (lu_.info() != Eigen::Success) throw SingularSystemError(singular + " " + lu_.lastErrorMessage());
        }
        msg().infof("    Eigen {} ({}): n = {}, non-zeros = {}, ordering {}, factorisation {:.3f} s",
                    spd_ ? "SimplicialLDLT" : "SparseLU", options_.method, A.rows, A.nonZeros(),
                    spd_ ? "AMD" : "COLAMD", secondsSince(t0));
    }

    void solveScaled(std::span<double> rhs) override {
        Eigen::Map<Eigen::VectorXd> b(rhs.data(), static_cast<Eigen::Index>(rhs.size()));
        Eigen::VectorXd x = spd_ ? Eigen::VectorXd(ldlt_.solve(b)) : Eigen::VectorXd(lu_.solve(b));
        b = x;
    }

private:
    bool spd_ = true;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt_;
    Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu_;
};

}  // namespace

std::unique_ptr<LinearSolver> makeEigenSolver(const SolverOptions& options) {
    return std::make_unique<EigenSolver>(options);
}

}  // namespace ma
