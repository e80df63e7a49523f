// PRE_GIBI: legacy GIBI conversion (ssnv511 2010-2011), a no-op: the MED mesh of unit 20 is read
// instead.
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void PRE_GIBI(Catalog& c) {
    c.add(cmd("PRE_GIBI").keywords({I("UNITE_GIBI").def(19), I("UNITE_MAILLAGE").def(20)}));
}

}  // namespace ma::catalog_entries
