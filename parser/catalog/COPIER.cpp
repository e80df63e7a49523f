// COPIER: a copy of a concept under another name (code_aster's copier.py; the types miniaster copies).
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void COPIER(Catalog& c) {
    c.add(cmd("COPIER")
              .resultFrom([](const KeywordSet& kw) { return kw.rawObject("CONCEPT")->typeName(); })
              .keywords({CO("CONCEPT", {kMesh, kTable, kFunction, kRealList}).mandatory(), info()}));
}

}  // namespace ma::catalog_entries
