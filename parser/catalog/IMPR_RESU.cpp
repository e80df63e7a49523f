// IMPR_RESU: results written as MED or GMSH files, a mesh as code_aster's text (RESULTAT, ASTER).
#include "core/FortranFormat.hpp"
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void IMPR_RESU(Catalog& c) {
    c.add(cmd("IMPR_RESU").keywords(join({
        {TXM("FORMAT").into({"MED", "RESULTAT", "ASTER", "IDEAS", "GMSH", "CASTEM"})
             .notSupported({"IDEAS", "CASTEM"}).def("MED"),
         bloc(when("FORMAT", {"MED"}), {I("UNITE").def(80)}),
         bloc(when("FORMAT", {"RESULTAT"}), {I("UNITE").def(8)}),
         bloc(when("FORMAT", {"ASTER"}), {I("UNITE").def(26)}),
         bloc(when("FORMAT", {"GMSH"}), {I("UNITE").def(37), R("VERSION").def(1.2)}),
         yesNo("PROC0").def("OUI"),
         fact("RESU").many().mandatory().keywords(join({
             {CO("MAILLAGE", {kMesh}), CO("RESULTAT", kAnyResult), CO("CHAM_GD", kAnyField),
              bloc(whenPresent("RESULTAT"),
                   {TXM("NOM_CHAM").many(), I("NUME_ORDRE").many(), TXM("TOUT_ORDRE").into({"OUI"}), R("INST").many(),
                    critere(), R("PRECISION").def(1.0e-6)},
                   {exclus({"NUME_ORDRE", "TOUT_ORDRE", "INST"})}),
              TXM("NOM_CMP").many(), TXM("TOUT_CMP").into({"OUI"}), yesNo("INFO_MAILLAGE").def("NON"),
              TXM("TYPE_CHAM").into({"SCALAIRE", "VECT_2D", "VECT_3D", "TENS_2D", "TENS_3D"}).onlyWith("FORMAT", {"GMSH"}),
              TXM("GROUP_MA").many().onlyWith("FORMAT", {"GMSH", "RESULTAT"}),
              TXM("MAILLE").many().onlyWith("FORMAT", {"GMSH"}),
              // The listing (FORMAT='RESULTAT', commands/ImprResuListing.cpp).
              TXM("GROUP_NO").many().onlyWith("FORMAT", {"RESULTAT"}),
              TXM("NOEUD").many().onlyWith("FORMAT", {"RESULTAT"}),
              TXM("VALE_MAX").into({"OUI"}).onlyWith("FORMAT", {"RESULTAT"}),
              TXM("VALE_MIN").into({"OUI"}).onlyWith("FORMAT", {"RESULTAT"}),
              R("BORNE_SUP").onlyWith("FORMAT", {"RESULTAT"}), R("BORNE_INF").onlyWith("FORMAT", {"RESULTAT"}),
              yesNo("IMPR_COOR").def("NON").onlyWith("FORMAT", {"RESULTAT"}),
              TXM("FORMAT_R").def("1PE21.14").checkedBy(fortranFormatProblem).onlyWith("FORMAT", {"RESULTAT"})},
             unsupported({"NOM_CHAM_MED", "CARA_ELEM", "IMPR_NOM_VARI", "PARTIE", "LIST_INST", "LIST_ORDRE", "FREQ",
                          "NUME_MODE", "TOUT_CHAM", "NOM_CMP_MED", "NOM_RESU_MED", "SOUS_TITRE", "TOUT_PARA",
                          "NOM_PARA", "FORM_TABL"},
                         "not supported by miniaster's IMPR_RESU"),
         }))
             .rules({auMoinsUn({"MAILLAGE", "RESULTAT", "CHAM_GD"}), exclus({"RESULTAT", "CHAM_GD"})}),
         info()},
        unsupported({"VERSION_MED", "MODELE", "CONCEPT"}, "not supported by miniaster's MED output"),
    })));
}

}  // namespace ma::catalog_entries
