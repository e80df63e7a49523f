// Mesh commands: LIRE_MAILLAGE, DEFI_GROUP, MODI_MAILLAGE (commands_spec §7.7, §8.1, §8.2).
#include "parser/catalog/Types.hpp"

namespace ma::catalog_entries {
using namespace cata;
using namespace cata::types;

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

void addMeshCommands(Catalog& c) {
    c.add(cmd("LIRE_MAILLAGE", kMesh).keywords(join({
        {I("UNITE").def(20),
         TXM("FORMAT").into({"ASTER", "GIBI", "GMSH", "IDEAS", "MED"}).notSupported({"GIBI", "GMSH", "IDEAS"}).def("MED"),
         bloc(when("FORMAT", {"MED"}), {TXM("NOM_MED"), I("INFO_MED").intoInt({1, 2, 3}).def(1)}),
         fact("VERI_MAIL").byDefault().keywords({yesNo("VERIF").def("OUI"), R("APLAT").def(1.0e-3)}),
         info()},
        unsupported({"PARTITIONNEUR", "LECTURE_PARALLELE"}, "parallel reading"),
    })));

    c.add(cmd("DEFI_GROUP", kMesh)
              .reuse(Reuse::Mandatory)
              .keywords({CO("MAILLAGE", {kMesh}).mandatory(), creaGroupMa(), creaGroupNo(),
                         fact("DETR_GROUP_MA").many().keywords({TXM("NOM").many().mandatory()}),
                         fact("DETR_GROUP_NO").many().keywords({TXM("NOM").many().mandatory()}),
                         yesNo("ALARME").def("OUI"), info()})
              .rules({auMoinsUn({"CREA_GROUP_MA", "CREA_GROUP_NO", "DETR_GROUP_MA", "DETR_GROUP_NO"})}));

    c.add(cmd("MODI_MAILLAGE", kMesh)
              .reuse(Reuse::Mandatory)
              .keywords(join({
                  {CO("MAILLAGE", {kMesh}).mandatory(),
                   fact("ORIE_PEAU_2D").many().keywords({TXM("GROUP_MA").many().mandatory(), TXM("GROUP_MA_SURF").many()}),
                   fact("ORIE_PEAU_3D").many().keywords({TXM("GROUP_MA").many().mandatory(), TXM("GROUP_MA_VOLU").many()}),
                   info()},
                  unsupported({"ORIE_FISSURE", "ORIE_NORM_COQUE", "ORIE_LIGNE", "DEFORME", "TRANSLATION", "ROTATION",
                               "MODI_MAILLE", "ECHELLE", "PLAQ_TUBE", "TUBE_COUDE", "SYMETRIE", "ORIE_SHB",
                               "ABSC_CURV", "MODI_BASE"},
                              "miniaster only orients skins (ORIE_PEAU_2D / ORIE_PEAU_3D)"),
              }))
              .rules({auMoinsUn({"ORIE_PEAU_2D", "ORIE_PEAU_3D"})}));
}

}  // namespace ma::catalog_entries
