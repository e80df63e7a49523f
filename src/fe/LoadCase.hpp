#pragma once
// One load of a mechanical problem with its FONC_MULT (EXCIT of MECA_STATIQUE / STAT_NON_LINE).
#include <memory>

#include "core/Function.hpp"
#include "fe/MechanicalLoad.hpp"

namespace ma {

struct LoadCase {
    std::shared_ptr<const MechanicalLoad> load;
    std::shared_ptr<const Function> multiplier;  // FONC_MULT (function of INST), null = 1
    double coefficient = 1.0;                    // COEF_MULT (CALC_CHAMP's EXCIT)

    // The load's factor at instant inst: FONC_MULT(inst) x COEF_MULT.
    double factor(double inst) const {
        if (!multiplier) return coefficient;
        return coefficient * multiplier->evaluateColumns({{"INST", {inst}}}, 1)[0];
    }
};

}  // namespace ma
