// DEFI_FISS_XFEM: a crack (with a front) or an interface given by level-set functions, nodal
// fields or a predefined shape (FORM_FISS), and its junctions.
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

namespace {

Keyword vector3(const char* name) { return R(name).min(3).max(3).mandatory(); }
Keyword halfLength(const char* name) { return R(name).mandatory().range(0.0, {}); }

// The keywords of each FORM_FISS (code_aster's blocks b_ellipse … b_droite).
std::vector<Keyword> shapeBlocks() {
    return {
        bloc(when("FORM_FISS", {"ELLIPSE"}),
             {halfLength("DEMI_GRAND_AXE"), halfLength("DEMI_PETIT_AXE"), vector3("CENTRE"), vector3("VECT_X"),
              vector3("VECT_Y"), TXM("COTE_FISS").into({"IN", "OUT"}).def("IN")}),
        bloc(when("FORM_FISS", {"RECTANGLE"}),
             {halfLength("DEMI_GRAND_AXE"), halfLength("DEMI_PETIT_AXE"), R("RAYON_CONGE").range(0.0, {}).def(0.0),
              vector3("CENTRE"), vector3("VECT_X"), vector3("VECT_Y"), TXM("COTE_FISS").into({"IN", "OUT"}).def("IN")}),
        bloc(when("FORM_FISS", {"ENTAILLE"}),
             {halfLength("DEMI_LONGUEUR"), halfLength("RAYON_CONGE"), vector3("CENTRE"), vector3("VECT_X"),
              vector3("VECT_Y")}),
        bloc(when("FORM_FISS", {"CYLINDRE"}),
             {halfLength("DEMI_GRAND_AXE"), halfLength("DEMI_PETIT_AXE"), vector3("CENTRE"), vector3("VECT_X"),
              vector3("VECT_Y")}),
        bloc(when("FORM_FISS", {"DEMI_PLAN"}), {vector3("PFON"), vector3("NORMALE"), vector3("DTAN")}),
        bloc(when("FORM_FISS", {"SEGMENT"}), {vector3("PFON_ORIG"), vector3("PFON_EXTR")}),
        bloc(when("FORM_FISS", {"DEMI_DROITE"}), {vector3("PFON"), vector3("DTAN")}),
        bloc(when("FORM_FISS", {"DROITE"}), {vector3("POINT"), vector3("DTAN")}),
    };
}

}  // namespace

void DEFI_FISS_XFEM(Catalog& c) {
    c.add(cmd("DEFI_FISS_XFEM", kCrack)
              .keywords(join({
                  {CO("MAILLAGE", {kMesh}),
                   CO("MODELE", {kModel}),  // legacy (≤ 2013-10): the mesh is taken from the model
                   TXM("TYPE_DISCONTINUITE").into({"FISSURE", "INTERFACE", "COHESIF"}).notSupported({"COHESIF"})
                       .def("FISSURE"),
                   TXM("CHAM_DISCONTINUITE").into({"DEPL"}).def("DEPL"),
                   fact("DEFI_FISS").mandatory().keywords(join({
                       {CO("FONC_LN", kAnyFunction), CO("FONC_LT", kAnyFunction),
                        CO("CHAM_NO_LSN", {kNodalField}), CO("CHAM_NO_LST", {kNodalField}),
                        TXM("FORM_FISS").into({"ELLIPSE", "RECTANGLE", "CYLINDRE", "DEMI_PLAN", "SEGMENT",
                                               "DEMI_DROITE", "DROITE", "ENTAILLE"})},
                       shapeBlocks(),
                       unsupported({"GROUP_MA_FISS", "GROUP_MA_FOND", "GROUP_MA_BORD_FISS"},
                                   "level sets are given by FONC_LN/FONC_LT, CHAM_NO_LSN/CHAM_NO_LST or FORM_FISS"),
                   })).rules({unParmi({"FONC_LN", "CHAM_NO_LSN", "FORM_FISS"})}),
                   fact("JONCTION").keywords({CO("FISSURE", {kCrack}).many().mandatory(),
                                              R("POINT").max(3).mandatory()}),
                   TXM("GROUP_MA_ENRI"), info({1, 2, 3})},
                  {bloc(when("TYPE_DISCONTINUITE", {"FISSURE"}),
                        {TXM("TYPE_ENRI_FOND").into({"TOPOLOGIQUE", "GEOMETRIQUE"}).def("GEOMETRIQUE"),
                         bloc(when("TYPE_ENRI_FOND", {"GEOMETRIQUE"}),
                              {R("RAYON_ENRI").range(0.0, {}),
                               bloc(whenAbsent("RAYON_ENRI"), {I("NB_COUCHES").range(1, {}).def(2)})})})},
                  unsupported({"FOND_FISS", "FISS_INITIALE", "ORIE_FOND", "CHAM_NO_FOND", "MAILLAGE_GRILLE",
                               "FISS_GRILLE"},
                              "miniaster enriches every node the discontinuity cuts, on the model's mesh"),
              }))
              .rules({unParmi({"MAILLAGE", "MODELE"})}));
}

}  // namespace ma::catalog_entries
