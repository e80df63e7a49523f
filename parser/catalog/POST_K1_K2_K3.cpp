// POST_K1_K2_K3: stress intensity factors by extrapolating the displacement jump of the crack lips
// (code_aster/Cata/Commands/post_k1_k2_k3.py), here for X-FEM cracks (FISSURE).
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void POST_K1_K2_K3(Catalog& c) {
    c.add(cmd("POST_K1_K2_K3", kTable)
              .keywords(join({
                  {CO("FISSURE", {kCrack}).mandatory(), CO("RESULTAT", kAnyResult).mandatory(),
                   CO("MATER", {kMaterial}), I("NB_NOEUD_COUPE").def(5).range(3, std::nullopt),
                   I("NUME_FOND").def(1), I("NB_POINT_FOND"), R("ABSC_CURV_MAXI"), R("PREC_VIS_A_VIS").def(0.1),
                   TXM("TOUT_ORDRE").into({"OUI"}), I("NUME_ORDRE").many(), R("INST").many(), critere(),
                   R("PRECISION").def(1.0e-6), info(), titre()},
                  unsupported({"FOND_FISS", "TYPE_MAILLAGE", "GROUP_NO", "SANS_GROUP_NO", "TOUT"},
                              "miniaster's cracks are fiss_xfem (FISSURE)"),
                  unsupported({"LIST_ORDRE", "LIST_INST", "TOUT_MODE", "NUME_MODE", "LIST_MODE", "FREQ", "LIST_FREQ"},
                              "miniaster's POST_K1_K2_K3 selects the orders by TOUT_ORDRE, NUME_ORDRE or INST"),
              }))
              .rules({exclus({"TOUT_ORDRE", "NUME_ORDRE", "INST"})}));
}

}  // namespace ma::catalog_entries
