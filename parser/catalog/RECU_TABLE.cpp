// RECU_TABLE: a table held by another concept (here the front tables of a crack).
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void RECU_TABLE(Catalog& c) {
    c.add(cmd("RECU_TABLE", kTable)
              .keywords(join({
                  {CO("CO", {kCrack}).mandatory(), TXM("NOM_TABLE").into({"FOND_FISS", "NB_FOND_FISS"}), titre()},
                  unsupported({"NOM_PARA", "TOUT_PARA"},
                              "miniaster gives the tables of a crack (NOM_TABLE), not the parameters of a result"),
              }))
              .rules({unParmi({"NOM_TABLE", "NOM_PARA", "TOUT_PARA"})}));
}

}  // namespace ma::catalog_entries
