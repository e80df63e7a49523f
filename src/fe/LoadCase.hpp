#pragma once
// One load of a mechanical problem with its FONC_MULT (EXCIT of MECA_STATIQUE / STAT_NON_LINE).
#include <memory>

#include "core/Function.hpp"
#include "fe/MechanicalLoad.hpp"

namespace ma {

struct LoadCase {
    std::shared_ptr<const MechanicalLoad> load;
    std::shared_ptr<const Function> multiplier;  // FONC_MULT (function of INST), null = 1

    // FONC_MULT at instant inst (1 without a multiplier).
    double factor(double inst) const {
        if (!multiplier) return 1.0;
        return multiplier->evaluateColumns({{"INST", {inst}}}, 1)[0];
    }
};

}  // namespace ma
