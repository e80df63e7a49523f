#include "fe/Result.hpp"

#include <cmath>

#include "core/Error.hpp"

namespace ma {

const ResultStep& Result::step(int order) const {
    for (const auto& s : steps)
        if (s.order == order) return s;
    throw UserError("result " + name + " has no NUME_ORDRE " + std::to_string(order));
}

ResultStep& Result::step(int order) { return const_cast<ResultStep&>(static_cast<const Result&>(*this).step(order)); }

const ResultStep& Result::stepAtInst(double inst, double precision, bool relative) const {
    for (const auto& s : steps) {
        double tol = relative ? precision * std::abs(inst) : precision;
        if (std::abs(s.inst - inst) <= tol) return s;
    }
    throw UserError("result " + name + " has no step at INST " + std::to_string(inst));
}

}  // namespace ma
