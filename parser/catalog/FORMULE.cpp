// FORMULE: a function given by a Python expression (run by the supervisor).
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void FORMULE(Catalog& c) {
    // Other keywords are the objects of the evaluation context (depx=depx...).
    c.add(cmd("FORMULE", kFormula)
              .keywords({TXM("VALE"), TXM("NOM_PARA").many().mandatory(),
                         unsupported("VALE_C", "complex formulas")})
              .rules({unParmi({"VALE", "VALE_C"})})
              .contextKeywords());
}

}  // namespace ma::catalog_entries
