// POST_MAIL_XFEM: visualisation mesh of an X-FEM model (sub-cells, both lips).
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void POST_MAIL_XFEM(Catalog& c) {
    c.add(cmd("POST_MAIL_XFEM", kMesh).keywords({
        CO("MODELE", {kModel}).mandatory(), TXM("PREF_NOEUD_X").def("NX"), TXM("PREF_NOEUD_M").def("NM"),
        TXM("PREF_NOEUD_P").def("NP"), TXM("PREF_MAILLE_X").def("MX"), TXM("PREF_GROUP_CO").def("NFISSU"), titre(),
        info()}));
}

}  // namespace ma::catalog_entries
