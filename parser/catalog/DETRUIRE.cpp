// DETRUIRE: concepts removed from the command file's names (run by the supervisor).
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void DETRUIRE(Catalog& c) {
    c.add(cmd("DETRUIRE").keywords({fact("CONCEPT").many().mandatory().keywords({CO("NOM", kAnyConcept).many().mandatory()}),
                                    info()}));
}

}  // namespace ma::catalog_entries
