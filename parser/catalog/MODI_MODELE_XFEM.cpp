// MODI_MODELE_XFEM: model enriched by X-FEM interfaces.
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void MODI_MODELE_XFEM(Catalog& c) {
    c.add(cmd("MODI_MODELE_XFEM", kModel).keywords({
        CO("MODELE_IN", {kModel}).mandatory(), CO("FISSURE", {kCrack}).many().mandatory().max(99),
        // 'P1P1' (≤ 2013-10) and 'OUI' (2013-10 … 2014-10) are older names of 'STANDARD'.
        TXM("CONTACT").into({"SANS", "STANDARD", "MORTAR", "P1P1", "OUI"}).notSupported({"MORTAR"})
            .legacy({{"P1P1", "STANDARD"}, {"OUI", "STANDARD"}}).def("SANS"),
        TXM("PRETRAITEMENTS").into({"AUTO", "SANS", "FORCE"}).def("AUTO"),
        TXM("DECOUPE_FACETTE").into({"DEFAUT", "SOUS_ELEMENTS"}).def("DEFAUT"),
        info({1, 2, 3}),
    }));
}

}  // namespace ma::catalog_entries
