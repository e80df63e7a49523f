// COPIER: a copy of a concept under another name (code_aster's copier.py: every type of its list that
// miniaster has).
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void COPIER(Catalog& c) {
    c.add(cmd("COPIER")
              .resultFrom([](const KeywordSet& kw) { return kw.rawObject("CONCEPT")->typeName(); })
              .keywords({CO("CONCEPT", {kMesh, kTable, kFunction, kRealList, kModel, kStaticResult, kNonlinearResult}).mandatory(), info()}));
}

}  // namespace ma::catalog_entries
