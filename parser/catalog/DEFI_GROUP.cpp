// DEFI_GROUP: cell and node groups created or destroyed in a mesh.
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

namespace {
const std::vector<std::string> kCellTypes{"TOUT", "0D", "1D", "2D", "3D", "POI1", "SEG2", "SEG3", "TRIA3",
                                          "TRIA6", "QUAD4", "QUAD8", "QUAD9", "TETRA4", "TETRA10", "PYRAM5",
                                          "PENTA6", "HEXA8", "HEXA20", "HEXA27"};

// POINT, NOEUD_CENTRE or GROUP_NO_CENTRE (code_aster's utcono).
std::vector<Keyword> centre() {
    return {R("POINT").max(3), TXM("NOEUD_CENTRE"), TXM("GROUP_NO_CENTRE")};
}
Rule oneCentre() { return unParmi({"POINT", "NOEUD_CENTRE", "GROUP_NO_CENTRE"}); }
Rule oneDirection() { return unParmi({"ANGL_NAUT", "VECT_NORMALE"}); }
Keyword cellCriterion() { return TXM("CRIT_NOEUD").into({"TOUS", "AU_MOINS_UN", "MAJORITE"}).def("AU_MOINS_UN"); }
Keyword fissure() { return CO("FISSURE", {kCrack}).many().mandatory(); }

Keyword creaGroupMa() {
    return fact("CREA_GROUP_MA").many().keywords({
        TXM("NOM").mandatory(), TXM("TYPE_MAILLE").into(kCellTypes).def("TOUT"), TXM("TOUT").into({"OUI"}),
        TXM("GROUP_MA").many(), TXM("MAILLE").many(), TXM("INTERSEC").many(), TXM("UNION").many(),
        TXM("DIFFE").many(),
        TXM("OPTION")
            .into({"FACE_NORMALE", "BANDE", "SPHERE", "CYLINDRE", "APPUI", "APPUI_LACHE", "FISS_XFEM", "INCLUSION"})
            .notSupported({"APPUI", "APPUI_LACHE", "INCLUSION"}),
        bloc(when("OPTION", {"FACE_NORMALE"}),
             {R("ANGL_NAUT").max(2), R("VECT_NORMALE").max(3), R("ANGL_PREC").def(0.5), yesNo("VERI_SIGNE").def("OUI")},
             {oneDirection()}),
        bloc(when("OPTION", {"BANDE"}),
             join({centre(), {R("ANGL_NAUT").max(2), R("VECT_NORMALE").max(3), R("DIST").mandatory().range(0, {}),
                              cellCriterion()}}),
             {oneCentre(), oneDirection()}),
        bloc(when("OPTION", {"SPHERE"}), join({centre(), {R("RAYON").mandatory(), cellCriterion()}}), {oneCentre()}),
        bloc(when("OPTION", {"CYLINDRE"}),
             join({centre(), {R("RAYON").mandatory(), R("ANGL_NAUT").max(2), R("VECT_NORMALE").max(3), cellCriterion()}}),
             {oneCentre(), oneDirection()}),
        bloc(when("OPTION", {"FISS_XFEM"}),
             {TXM("TYPE_GROUP").into({"HEAVISIDE", "CRACKTIP", "MIXTE", "FISSUREE", "XFEM"}).def("XFEM"), fissure()}),
    })
        .rules({unParmi({"TOUT", "GROUP_MA", "MAILLE", "INTERSEC", "UNION", "DIFFE", "OPTION"})});
}

// CREA_GROUP_NO without OPTION: groups from other groups, nodes or cells.
Keyword withoutOption() {
    return bloc(whenAbsent("OPTION"),
                {TXM("NOM").many(), TXM("TOUT_GROUP_MA").into({"OUI"}), TXM("GROUP_MA").many(), TXM("GROUP_NO").many(),
                 TXM("NOEUD").many(), TXM("INTERSEC").many(), TXM("UNION").many(), TXM("DIFFE").many(),
                 bloc(whenPresent("GROUP_MA"),
                      {TXM("CRIT_NOEUD").into({"TOUS", "SOMMET", "MILIEU", "CENTRE"}).def("TOUS")})},
                {unParmi({"TOUT_GROUP_MA", "GROUP_MA", "GROUP_NO", "NOEUD", "INTERSEC", "UNION", "DIFFE"}),
                 presentPresent({"INTERSEC", "NOM"}), presentPresent({"UNION", "NOM"}),
                 presentPresent({"DIFFE", "NOM"})});
}

// The geometric options of CREA_GROUP_NO (code_aster's cgnoes, cgnoec, cgnopl, cgnoso, cgnoor).
std::vector<Keyword> geometricOptions() {
    const Keyword precision = R("PRECISION").mandatory();
    return {
        bloc(when("OPTION", {"ENV_SPHERE"}), join({centre(), {R("RAYON").mandatory(), precision}}), {oneCentre()}),
        bloc(when("OPTION", {"ENV_CYLINDRE"}),
             join({centre(), {R("RAYON").mandatory(), R("ANGL_NAUT").max(3), R("VECT_NORMALE").max(3), precision}}),
             {oneCentre(), oneDirection()}),
        bloc(when("OPTION", {"PLAN"}), join({centre(), {R("ANGL_NAUT").max(3), R("VECT_NORMALE").max(3), precision}}),
             {oneCentre(), oneDirection()}),
        bloc(when("OPTION", {"SEGM_DROI_ORDO"}),
             {TXM("NOEUD").many(), TXM("GROUP_NO").many(), TXM("NOEUD_ORIG"), TXM("GROUP_NO_ORIG"), TXM("NOEUD_EXTR"),
              TXM("GROUP_NO_EXTR"), precision, TXM("CRITERE").into({"ABSOLU", "RELATIF"}).mandatory()},
             {auMoinsUn({"NOEUD", "GROUP_NO"}), unParmi({"NOEUD_ORIG", "GROUP_NO_ORIG"}),
              unParmi({"NOEUD_EXTR", "GROUP_NO_EXTR"})}),
        bloc(when("OPTION", {"NOEUD_ORDO"}),
             {TXM("GROUP_MA").many().mandatory(), TXM("NOEUD_ORIG"), TXM("GROUP_NO_ORIG"), TXM("NOEUD_EXTR"),
              TXM("GROUP_NO_EXTR"), R("VECT_ORIE").max(3), TXM("ORIGINE").into({"SANS"})},
             {exclus({"NOEUD_ORIG", "GROUP_NO_ORIG"}), exclus({"NOEUD_EXTR", "GROUP_NO_EXTR"})}),
        bloc(when("OPTION", {"FISS_XFEM"}),
             {TXM("TYPE_GROUP")
                  .into({"HEAVISIDE", "CRACKTIP", "MIXTE", "XFEM", "ZONE_MAJ", "TORE"})
                  .notSupported({"ZONE_MAJ", "TORE"})
                  .mandatory(),
              fissure()}),
    };
}

Keyword creaGroupNo() {
    return fact("CREA_GROUP_NO").many().keywords(join({
        {TXM("OPTION")
             .into({"PLAN", "ENV_SPHERE", "ENV_CYLINDRE", "SEGM_DROI_ORDO", "NOEUD_ORDO", "TUNNEL", "INCLUSION",
                    "FISS_XFEM", "INTERVALLE_VALE", "RELA_CINE_BP"})
             .notSupported({"TUNNEL", "INCLUSION", "INTERVALLE_VALE", "RELA_CINE_BP"}),
         withoutOption(), bloc(whenPresent("OPTION"), {TXM("NOM").mandatory()})},
        geometricOptions(),
    }));
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
