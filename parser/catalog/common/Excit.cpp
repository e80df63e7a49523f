// EXCIT: the loads of an analysis and their multiplier functions.
#include "parser/catalog/common/Blocks.hpp"

namespace ma::catalog_entries {

Keyword excit(bool nonlinear) {
    std::vector<Keyword> k{CO("CHARGE", {kMechanicalLoad}).mandatory(), CO("FONC_MULT", kAnyFunction)};
    if (nonlinear)
        k.push_back(TXM("TYPE_CHARGE").into({"FIXE_CSTE", "FIXE_PILO", "SUIV", "DIDI"})
                        .notSupported({"FIXE_PILO", "SUIV", "DIDI"}).def("FIXE_CSTE"));
    return fact("EXCIT").many().keywords(std::move(k));
}

}  // namespace ma::catalog_entries
