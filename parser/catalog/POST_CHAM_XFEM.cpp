// POST_CHAM_XFEM: result fields on the visualisation mesh of POST_MAIL_XFEM.
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void POST_CHAM_XFEM(Catalog& c) {
    // The result has the type of RESULTAT (evol_elas or evol_noli).
    c.add(cmd("POST_CHAM_XFEM")
              .keywords({CO("MODELE_VISU", {kModel}).mandatory(), CO("RESULTAT", kAnyResult).mandatory(), info()})
              .resultFrom([](const KeywordSet& kw) { return kw.rawObject("RESULTAT")->typeName(); }));
}

}  // namespace ma::catalog_entries
