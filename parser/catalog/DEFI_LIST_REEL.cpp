// DEFI_LIST_REEL: a list of reals (instants).
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void DEFI_LIST_REEL(Catalog& c) {
    c.add(cmd("DEFI_LIST_REEL", kRealList)
              .keywords({R("VALE").many(), R("DEBUT"),
                         fact("INTERVALLE").many().keywords({R("JUSQU_A").mandatory(), I("NOMBRE").range(1, {}), R("PAS")})
                             .rules({unParmi({"NOMBRE", "PAS"})}),
                         info(), titre()})
              .rules({unParmi({"VALE", "DEBUT"}), ensemble({"DEBUT", "INTERVALLE"})}));
}

}  // namespace ma::catalog_entries
