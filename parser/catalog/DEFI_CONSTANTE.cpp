// DEFI_CONSTANTE: a function with the same value for any parameters.
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void DEFI_CONSTANTE(Catalog& c) {
    c.add(cmd("DEFI_CONSTANTE", kFunction).keywords({R("VALE").mandatory(), TXM("NOM_RESU").def("TOUTRESU"), titre()}));
}

}  // namespace ma::catalog_entries
