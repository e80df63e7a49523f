// Post-processing: CREA_CHAMP (EXTR), POST_ERREUR, POST_RELEVE_T, IMPR_RESU
// (commands_spec §2, §5, §6).
#include "parser/catalog/Types.hpp"

namespace ma::catalog_entries {
using namespace cata;
using namespace cata::types;

namespace {
std::vector<Keyword> formulaList(std::vector<std::string> names) {
    std::vector<Keyword> out;
    for (auto& n : names) out.push_back(CO(std::move(n), kAnyFunction).many());
    return out;
}
}  // namespace

void addPostCommands(Catalog& c) {
    c.add(cmd("CREA_CHAMP")
              .keywords(join({
                  {TXM("TYPE_CHAM").mandatory()
                       .into({"NOEU_DEPL_R", "ELGA_SIEF_R", "ELGA_EPSI_R", "ELNO_SIEF_R", "NOEU_SIEF_R",
                              "ELGA_VARI_R", "NOEU_GEOM_R", "CART_DEPL_R"})
                       .notSupported({"ELGA_EPSI_R", "ELNO_SIEF_R", "NOEU_SIEF_R", "ELGA_VARI_R", "NOEU_GEOM_R",
                                      "CART_DEPL_R"}),
                   TXM("OPERATION").mandatory()
                       .into({"EXTR", "AFFE", "ASSE", "EVAL", "DISC", "COMB", "R2C", "C2R", "NORMALE", "ASSE_DEPL"})
                       .notSupported({"AFFE", "ASSE", "EVAL", "DISC", "COMB", "R2C", "C2R", "NORMALE", "ASSE_DEPL"}),
                   bloc(when("OPERATION", {"EXTR"}),
                        join({{CO("RESULTAT", kAnyResult).mandatory(), TXM("NOM_CHAM").mandatory(), I("NUME_ORDRE"),
                               R("INST"), critere(), R("PRECISION").def(1.0e-6)},
                              unsupported({"TYPE_MAXI", "TYPE_RESU", "FREQ", "NUME_MODE", "NOEUD_CMP", "NOM_CAS",
                                           "ANGLE", "TABLE", "FISSURE", "MAILLAGE", "LIST_INST", "LIST_FREQ"},
                                          "miniaster extracts a field of a result by NUME_ORDRE or INST")}),
                        {unParmi({"NUME_ORDRE", "INST"})}),
                   info(), titre()},
                  unsupported({"MODELE", "PROL_ZERO", "OPTION", "CHAM_F", "CHAM_GD", "CARA_ELEM", "PROPRIETE"},
                              "only OPERATION='EXTR' is supported"),
              }))
              .resultFrom([](const KeywordSet& kw) {
                  return kw.text("TYPE_CHAM").rfind("NOEU_", 0) == 0 ? kNodalField : kGaussField;
              }));

    c.add(cmd("POST_ERREUR", kTable)
              .keywords({
                  TXM("OPTION").mandatory().into({"DEPL_RELA", "ENER_RELA", "LAGR_RELA"}).notSupported({"LAGR_RELA"}),
                  CO("MODELE", {kModel}).mandatory(), TXM("GROUP_MA").many().mandatory(),
                  bloc(when("OPTION", {"DEPL_RELA"}),
                       join({{CO("CHAM_GD", {kNodalField}).mandatory(), CO("CHAM_MATER", {kMaterialField})},
                             formulaList({"DX", "DY", "DZ"})})),
                  bloc(when("OPTION", {"ENER_RELA"}),
                       join({{CO("CHAM_GD", {kGaussField}).mandatory(), CO("CHAM_MATER", {kMaterialField}).mandatory(),
                              TXM("DEFORMATION").mandatory().into({"PETIT"})},
                             formulaList({"SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ"})})),
                  bloc(when("OPTION", {"LAGR_RELA"}),
                       join({{CO("CHAM_GD", {kNodalField}).mandatory()}, formulaList({"LAGS_C"})})),
              }));

    c.add(cmd("POST_RELEVE_T", kTable).keywords({
        fact("ACTION").many().mandatory().keywords(join({
            {TXM("INTITULE").mandatory(),
             TXM("OPERATION").mandatory().max(2).into({"EXTRACTION", "MOYENNE", "MOYENNE_ARITH", "EXTREMA"}),
             CO("RESULTAT", kAnyResult), CO("CHAM_GD", kAnyField),
             bloc(whenPresent("RESULTAT"),
                  {TXM("NOM_CHAM").mandatory(), I("NUME_ORDRE").many(), TXM("TOUT_ORDRE").into({"OUI"}),
                   R("INST").many(), CO("LIST_INST", {kRealList}), critere(), R("PRECISION").def(1.0e-6)},
                  {exclus({"NUME_ORDRE", "TOUT_ORDRE", "INST", "LIST_INST"})}),
             TXM("GROUP_NO").many(), TXM("NOEUD").many(), TXM("TOUT_CMP").into({"OUI"}), TXM("NOM_CMP").many(),
             TXM("REPERE").into({"GLOBAL", "LOCAL", "POLAIRE", "UTILISATEUR", "CYLINDRIQUE"})
                 .notSupported({"LOCAL", "POLAIRE", "UTILISATEUR", "CYLINDRIQUE"}).def("GLOBAL"),
             yesNo("MOYE_NOEUD").def("OUI"), TXM("FORMAT_C").into({"MODULE", "REEL", "IMAG"}).def("MODULE")},
            unsupported({"CHEMIN", "GROUP_MA", "MAILLE", "INVARIANT", "ELEM_PRINCIPAUX", "RESULTANTE", "MOMENT",
                         "POINT", "LIST_ORDRE", "NUME_MODE", "FREQ", "LIST_FREQ", "NOM_CAS", "TRAC_NOR", "TRAC_DIR",
                         "NOEUD_CMP", "VECT_Y", "ORIGINE", "AXE_Z", "ANGL_NAUT", "LIST_MODE"},
                        "miniaster extracts nodal values on GROUP_NO / NOEUD"),
        }))
            .rules({unParmi({"RESULTAT", "CHAM_GD"}), auMoinsUn({"GROUP_NO", "NOEUD"}),
                    unParmi({"TOUT_CMP", "NOM_CMP"})}),
        titre(), info()}));

    c.add(cmd("IMPR_RESU").keywords(join({
        {TXM("FORMAT").into({"MED", "RESULTAT", "ASTER", "IDEAS", "GMSH", "CASTEM"})
             .notSupported({"RESULTAT", "ASTER", "IDEAS", "CASTEM"}).def("MED"),
         bloc(when("FORMAT", {"MED"}), {I("UNITE").def(80)}),
         bloc(when("FORMAT", {"GMSH"}), {I("UNITE").def(37), R("VERSION").def(1.2)}),
         yesNo("PROC0").def("OUI"),
         fact("RESU").many().mandatory().keywords(join({
             {CO("MAILLAGE", {kMesh}), CO("RESULTAT", kAnyResult), CO("CHAM_GD", kAnyField),
              bloc(whenPresent("RESULTAT"),
                   {TXM("NOM_CHAM").many(), I("NUME_ORDRE").many(), TXM("TOUT_ORDRE").into({"OUI"}), R("INST").many(),
                    critere(), R("PRECISION").def(1.0e-6)},
                   {exclus({"NUME_ORDRE", "TOUT_ORDRE", "INST"})}),
              TXM("NOM_CMP").many(), yesNo("INFO_MAILLAGE").def("NON"),
              // FORMAT='GMSH' only (IMPR_RESU refuses them with MED).
              TXM("TYPE_CHAM").into({"SCALAIRE", "VECT_2D", "VECT_3D", "TENS_2D", "TENS_3D"}),
              TXM("GROUP_MA").many(), TXM("MAILLE").many()},
             unsupported({"GROUP_NO", "NOEUD", "NOM_CHAM_MED", "CARA_ELEM", "IMPR_NOM_VARI",
                          "PARTIE", "LIST_INST", "LIST_ORDRE", "FREQ", "NUME_MODE", "TOUT_CHAM", "NOM_CMP_MED",
                          "NOM_RESU_MED", "VALE_MAX", "VALE_MIN", "SOUS_TITRE", "FORMAT_R"},
                         "not supported by miniaster's MED output"),
         }))
             .rules({auMoinsUn({"MAILLAGE", "RESULTAT", "CHAM_GD"}), exclus({"RESULTAT", "CHAM_GD"})}),
         info()},
        unsupported({"VERSION_MED", "MODELE", "CONCEPT"}, "not supported by miniaster's MED output"),
    })));
}

}  // namespace ma::catalog_entries
