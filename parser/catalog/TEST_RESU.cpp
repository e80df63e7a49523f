// TEST_RESU: a value of a result's field, of a nodal field or of a field at integration points
// checked against a reference.
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {
namespace {

// code_aster's C_TEST_REFERENCE for RESU (`multiPrecision`: CRITERE and TOLE_MACHINE take two values,
// the second one selecting INST), CHAM_NO and CHAM_ELEM.
std::vector<Keyword> testReference(bool multiPrecision) {
    return join({
        {R("VALE_CALC").many().mandatory(), R("ORDRE_GRANDEUR"), TXM("LEGENDE"), yesNo("VALE_ABS").def("NON"),
         TXM("TYPE_TEST").into({"SOMM_ABS", "SOMM", "MAX", "MIN"}),
         multiPrecision ? R("TOLE_MACHINE").max(2) : R("TOLE_MACHINE").def(1.0e-6),
         multiPrecision ? TXM("CRITERE").max(2).into({"RELATIF", "ABSOLU"}) : critere(),
         TXM("REFERENCE").into({"ANALYTIQUE", "SOURCE_EXTERNE", "AUTRE_ASTER", "NON_DEFINI"}),
         bloc(whenPresent("REFERENCE"), {R("VALE_REFE").many().mandatory(), R("PRECISION").def(1.0e-3)})},
        unsupported({"VALE_CALC_I", "VALE_REFE_I"}, "miniaster's fields hold reals (VALE_CALC, VALE_REFE)"),
        unsupported({"VALE_CALC_C", "VALE_REFE_C"}, "complex values"),
    });
}

}  // namespace

void TEST_RESU(Catalog& c) {
    c.add(cmd("TEST_RESU")
              .keywords(join({
                  {fact("RESU").many().keywords(join({
                       {CO("RESULTAT", kAnyResult).mandatory(), I("NUME_ORDRE"), R("INST"),
                        TXM("NOM_CHAM").mandatory(), TXM("NOM_CMP"), TXM("GROUP_MA"), TXM("MAILLE"),
                        TXM("NOEUD").many(), TXM("GROUP_NO").many(), I("POINT"), I("SOUS_POINT")},
                       testReference(true),
                       unsupported({"FREQ", "NUME_MODE", "NOEUD_CMP", "NOM_CAS", "ANGLE"},
                                   "miniaster's results are accessed by NUME_ORDRE or INST"),
                       {unsupported("PARA", "miniaster's results store no parameters to test, only fields"),
                        unsupported("NOM_VARI", "miniaster stores no internal variables (elasticity)")},
                   }))
                       .rules({unParmi({"NUME_ORDRE", "INST"}), exclus({"NOEUD", "GROUP_NO", "POINT"}),
                               exclus({"MAILLE", "GROUP_MA"})}),
                   fact("CHAM_NO")
                       .many()
                       .keywords(join({{CO("CHAM_GD", {kNodalField}).mandatory(), TXM("NOEUD"), TXM("GROUP_NO"),
                                        TXM("NOM_CMP")},
                                       testReference(false)}))
                       .rules({exclus({"NOEUD", "GROUP_NO"}), presentPresent({"NOEUD", "NOM_CMP"}),
                               presentPresent({"GROUP_NO", "NOM_CMP"})}),
                   fact("CHAM_ELEM")
                       .many()
                       .keywords(join({{CO("CHAM_GD", {kGaussField}).mandatory(), TXM("GROUP_MA"), TXM("MAILLE"),
                                        I("POINT"), I("SOUS_POINT"), TXM("NOM_CMP")},
                                       testReference(false),
                                       unsupported({"NOEUD", "GROUP_NO"},
                                                   "miniaster's fields by element are at integration points (ELGA): "
                                                   "select MAILLE and POINT")}))
                       .rules({exclus({"MAILLE", "GROUP_MA"}), presentPresent({"POINT", "NOM_CMP"})})},
                  unsupported({"CARTE", "OBJET"}, "miniaster has no CARTE nor JEVEUX objects to test"),
                  {unsupported("GENE", "generalised (modal) results are not computed by miniaster"),
                   unsupported("MAILLAGE", "mesh counts are not tested by miniaster's TEST_RESU"),
                   unsupported("TEST_NAN", "the NaN check of code_aster's Fortran is not reproduced")},
              }))
              .rules({auMoinsUn({"CHAM_NO", "CHAM_ELEM", "RESU"})}));
}

}  // namespace ma::catalog_entries
