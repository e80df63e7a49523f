// DEFI_FISS_XFEM: an X-FEM interface given by level-set functions, and its junctions.
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void DEFI_FISS_XFEM(Catalog& c) {
    c.add(cmd("DEFI_FISS_XFEM", kCrack)
              .keywords(join({
                  {CO("MAILLAGE", {kMesh}),
                   CO("MODELE", {kModel}),  // legacy (≤ 2013-10): the mesh is taken from the model
                   TXM("TYPE_DISCONTINUITE").into({"FISSURE", "INTERFACE", "COHESIF"}).notSupported({"COHESIF"})
                       .def("FISSURE"),
                   TXM("CHAM_DISCONTINUITE").into({"DEPL"}).def("DEPL"),
                   fact("DEFI_FISS").mandatory().keywords(join({
                       {CO("FONC_LN", kAnyFunction).mandatory(), CO("FONC_LT", kAnyFunction)},
                       unsupported({"GROUP_MA_FISS", "GROUP_MA_FOND", "FORM_FISS", "CHAM_NO_LSN", "CHAM_NO_LST",
                                    "GROUP_MA_BORD_FISS"},
                                   "level sets are given by FONC_LN (and FONC_LT)"),
                   })),
                   fact("JONCTION").keywords({CO("FISSURE", {kCrack}).many().mandatory(),
                                              R("POINT").max(3).mandatory()}),
                   TXM("GROUP_MA_ENRI"), info({1, 2, 3})},
                  unsupported({"TYPE_ENRI_FOND", "RAYON_ENRI", "NB_COUCHES", "FOND_FISS",
                               "FISS_INITIALE", "ORIE_FOND", "CHAM_NO_FOND"},
                              "miniaster enriches every node cut by the interface"),
              }))
              .rules({unParmi({"MAILLAGE", "MODELE"})}));
}

}  // namespace ma::catalog_entries
