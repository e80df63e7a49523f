// FIN: end of a command file (run by the supervisor).
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void FIN(Catalog& c) {
    c.add(cmd("FIN").keywords(join({
        {yesNo("RETASSAGE"), yesNo("INFO_RESU"), yesNo("PROC0")},
        {unsupported("FORMAT_HDF", "miniaster does not save a database")},
    })));
}

}  // namespace ma::catalog_entries
