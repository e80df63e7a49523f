// DEFI_GROUP: cell and node groups created or destroyed in a mesh.
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

namespace {
const std::vector<std::string> kCellTypes{"TOUT", "0D", "1D", "2D", "3D", "POI1", "SEG2", "SEG3", "TRIA3",
                                          "TRIA6", "QUAD4", "QUAD8", "QUAD9", "TETRA4", "TETRA10", "PYRAM5",
                                          "PENTA6", "HEXA8", "HEXA20", "HEXA27"};

Keyword creaGroupMa() {
    return fact("CREA_GROUP_MA").many().keywords(join({
        {TXM("NOM").mandatory(), TXM("TYPE_MAILLE").into(kCellTypes).def("TOUT"), TXM("TOUT").into({"OUI"}),
         TXM("GROUP_MA").many(), TXM("MAILLE").many(), TXM("INTERSEC").many(), TXM("UNION").many(),
         TXM("DIFFE").many(),
         TXM("OPTION")
             .into({"FACE_NORMALE", "BANDE", "SPHERE", "CYLINDRE", "APPUI", "APPUI_LACHE", "FISS_XFEM", "INCLUSION"})
             .notSupported({"SPHERE", "CYLINDRE", "APPUI", "APPUI_LACHE", "FISS_XFEM", "INCLUSION"}),
         bloc(when("OPTION", {"FACE_NORMALE"}),
              {R("VECT_NORMALE").max(3).mandatory(), R("ANGL_PREC").def(0.5), yesNo("VERI_SIGNE").def("OUI")}),
         bloc(when("OPTION", {"BANDE"}),
              {R("POINT").max(3).mandatory(), R("VECT_NORMALE").max(3).mandatory(), R("DIST").mandatory().range(0, {}),
               TXM("CRIT_NOEUD").into({"TOUS", "AU_MOINS_UN", "MAJORITE"}).def("AU_MOINS_UN")})},
        unsupported({"ANGL_NAUT", "NOEUD_CENTRE", "GROUP_NO_CENTRE"}, "give POINT and VECT_NORMALE"),
    }))
        .rules({unParmi({"TOUT", "GROUP_MA", "MAILLE", "INTERSEC", "UNION", "DIFFE", "OPTION"})});
}

Keyword creaGroupNo() {
    return fact("CREA_GROUP_NO").many().keywords(join({
        {TXM("NOM").many(), TXM("TOUT_GROUP_MA").into({"OUI"}), TXM("GROUP_MA").many(), TXM("GROUP_NO").many(),
         TXM("NOEUD").many(), TXM("INTERSEC").many(), TXM("UNION").many(), TXM("DIFFE").many(),
         TXM("OPTION")
             .into({"PLAN", "ENV_SPHERE", "ENV_CYLINDRE", "SEGM_DROI_ORDO", "NOEUD_ORDO", "TUNNEL", "INCLUSION",
                    "FISS_XFEM", "INTERVALLE_VALE"})
             .notSupported({"ENV_SPHERE", "ENV_CYLINDRE", "SEGM_DROI_ORDO", "NOEUD_ORDO", "TUNNEL", "INCLUSION",
                            "FISS_XFEM", "INTERVALLE_VALE"}),
         bloc(whenPresent("GROUP_MA"),
              {TXM("CRIT_NOEUD").into({"TOUS", "SOMMET", "MILIEU", "CENTRE"}).def("TOUS")}),
         bloc(when("OPTION", {"PLAN"}),
              {R("POINT").max(3).mandatory(), R("VECT_NORMALE").max(3).mandatory(),
               R("PRECISION").mandatory().range(0, {})})},
        unsupported({"ANGL_NAUT", "NOEUD_CENTRE", "GROUP_NO_CENTRE"}, "give POINT and VECT_NORMALE"),
    }))
        .rules({unParmi({"TOUT_GROUP_MA", "GROUP_MA", "GROUP_NO", "NOEUD", "INTERSEC", "UNION", "DIFFE", "OPTION"}),
                presentPresent({"OPTION", "NOM"}), presentPresent({"INTERSEC", "NOM"}),
                presentPresent({"UNION", "NOM"}), presentPresent({"DIFFE", "NOM"})});
}
}  // namespace

void DEFI_GROUP(Catalog& c) {
    c.add(cmd("DEFI_GROUP", kMesh)
              .reuse(Reuse::Mandatory)
              .keywords({CO("MAILLAGE", {kMesh}).mandatory(), creaGroupMa(), creaGroupNo(),
                         fact("DETR_GROUP_MA").many().keywords({TXM("NOM").many().mandatory()}),
                         fact("DETR_GROUP_NO").many().keywords({TXM("NOM").many().mandatory()}),
                         yesNo("ALARME").def("OUI"), info()})
              .rules({auMoinsUn({"CREA_GROUP_MA", "CREA_GROUP_NO", "DETR_GROUP_MA", "DETR_GROUP_NO"})}));
}

}  // namespace ma::catalog_entries
