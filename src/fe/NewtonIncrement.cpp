#include "fe/NewtonIncrement.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "core/Mpi.hpp"
#include "fe/ElementLoop.hpp"
#include "fe/FeMessages.hpp"

namespace ma {

namespace {

class NewtonIteration {
public:
    NewtonIteration(const NewtonSystem& s, std::vector<double>& u, std::vector<double>& lambda)
        : s_(s),
          c_(s.constraints),
          u_(u),
          lambda_(lambda),
          total_(static_cast<int>(c_.eq.size())),
          rhs_(c_.equationCount()) {}

    // R = F_int(u) - F_ext + alpha*C^T*lambda (+ the additional terms).
    void residual() {
        s_.internalForces(u_, fint_);
        R_.assign(total_, 0.0);
        for (int d = 0; d < s_.ndof; ++d) R_[d] = fint_[d] - s_.fext[d];
        for (size_t m = 0; m < c_.multi.size(); ++m)
            for (const auto& [d, coef] : c_.multi[m].terms) R_[d] += s_.alpha * coef * lambda_[m];
        if (s_.additional && !s_.distributed) s_.additional->residual(u_, R_);
        if (s_.additional && s_.distributed) {  // docs/mpi.md
            extra_.assign(total_, 0.0);
            mpi::collectively([&] { s_.additional->residual(u_, extra_); });
            mpi::sum(extra_);
            for (int d = 0; d < total_; ++d) R_[d] += extra_[d];
        }
    }

    // Solves for the correction of the current residual and applies it.
    void correct() {
        for (int d = 0; d < total_; ++d)
            if (c_.eq[d] >= 0) rhs_[c_.eq[d]] = -R_[d];
        for (size_t m = 0; m < c_.multi.size(); ++m) rhs_[c_.freeCount + m] = -s_.alpha * relationGap(m);
        s_.solve(rhs_);
        for (int d = 0; d < total_; ++d)
            if (c_.eq[d] >= 0) u_[d] += rhs_[c_.eq[d]];
        for (size_t m = 0; m < c_.multi.size(); ++m) lambda_[m] += rhs_[c_.freeCount + m];
    }

    // max |R| over the equations and the denominator of the relative criterion: the largest of
    // the external forces and reactions.
    void measure(double& maxR, double& denominator) const {
        maxR = 0.0, denominator = 0.0;
        std::vector<double> reaction(s_.ndof, 0.0);
        for (size_t m = 0; m < c_.multi.size(); ++m)
            for (const auto& [d, coef] : c_.multi[m].terms) reaction[d] += s_.alpha * coef * lambda_[m];
        for (int d = 0; d < s_.ndof; ++d) {
            if (c_.fixed[d]) {
                denominator = std::max(denominator, std::abs(fint_[d]));  // reaction - F_ext = -F_int
            } else {
                maxR = std::max(maxR, std::abs(R_[d]));
                denominator = std::max(denominator, std::abs(reaction[d] - s_.fext[d]));
            }
        }
        for (size_t m = 0; m < c_.multi.size(); ++m) maxR = std::max(maxR, std::abs(s_.alpha * relationGap(m)));
    }

    // Loads and reactions that are the linear solver's noise compared with the elastic forces of
    // the current displacement (imposed rigid motions, zero load): the relative criterion then uses
    // that force scale (mean stiffness diagonal x largest displacement) instead of noise.
    double relativeDenominator(double denominator) {
        double umax = 0.0;
        for (int d = 0; d < s_.ndof; ++d) umax = std::max(umax, std::abs(u_[d]));
        const double forceScale = s_.alpha * umax;
        if (denominator > s_.negligibleLoad * forceScale) return denominator;
        if (!zeroLoadNoted_)
            msg().infof(
                "    loads and reactions are negligible (max {:.3e} vs elastic force scale {:.3e}, below {:g} of "
                "it): RESI_GLOB_RELA is taken relative to the force scale",
                denominator, forceScale, s_.negligibleLoad);
        zeroLoadNoted_ = true;
        return forceScale;
    }

private:
    // C*u - v of multi-term relation m.
    double relationGap(size_t m) const {
        double g = -c_.multi[m].value;
        for (const auto& [d, coef] : c_.multi[m].terms) g += coef * u_[d];
        return g;
    }

    const NewtonSystem& s_;
    const DirichletConstraints& c_;
    std::vector<double>& u_;
    std::vector<double>& lambda_;
    const int total_;
    std::vector<double> rhs_, fint_, R_, extra_;
    bool zeroLoadNoted_ = false;
};

void reportNonConvergence(double inst, const ConvergenceOptions& options, const IncrementReport& report) {
    const FormattedMessage alarm =
        formatted(MECANONLINE5_37, inst, options.maxIterations, report.relativeResidual, report.maxResidual);
    // ARRET='OUI' stops on the facts: the alarm's first line.
    if (options.stopOnFailure) throw NonConvergenceError(alarm.text.substr(0, alarm.text.find('\n')));
    msg().alarm(alarm);
}

}  // namespace

IncrementReport newtonIterations(const NewtonSystem& system, double inst, const ConvergenceOptions& options,
                                 std::vector<double>& u, std::vector<double>& lambda) {
    NewtonIteration newton(system, u, lambda);
    IncrementReport report;
    for (int it = 0; it <= options.maxIterations; ++it) {
        newton.residual();
        newton.correct();
        newton.residual();
        double maxR = 0.0, denominator = 0.0;
        newton.measure(maxR, denominator);
        if (!std::isfinite(maxR))
            throw NumericalError(fmt::format("the residual is not finite at INST {} (iteration {})", inst, it));
        report.iterations = it + 1;
        report.maxResidual = maxR;
        denominator = newton.relativeDenominator(denominator);
        report.relativeResidual = denominator > 0.0 ? maxR / denominator : maxR;
        const bool okMaxi = options.resiGlobMaxi < 0.0 || maxR <= options.resiGlobMaxi;
        const bool okRela = options.resiGlobRela < 0.0 || report.relativeResidual <= options.resiGlobRela;
        msg().infof("    INST {:<12g} Newton iteration {:>2}: RESI_GLOB_RELA {:.6e}  RESI_GLOB_MAXI {:.6e}", inst, it,
                    report.relativeResidual, maxR);
        if (okMaxi && okRela) {
            report.converged = true;
            break;
        }
    }
    msg().infof("    INST {:g}: {} after {} iteration(s), {:.3f} s", inst,
                report.converged ? "converged" : "NOT converged", report.iterations, secondsSince(system.start));
    if (!report.converged) reportNonConvergence(inst, options, report);
    return report;
}

}  // namespace ma
