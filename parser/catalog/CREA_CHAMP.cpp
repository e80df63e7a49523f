// CREA_CHAMP: field extracted from a result or from a crack (OPERATION='EXTR').
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void CREA_CHAMP(Catalog& c) {
    c.add(cmd("CREA_CHAMP")
              .keywords(join({
                  {TXM("TYPE_CHAM").mandatory()
                       .into({"NOEU_DEPL_R", "NOEU_NEUT_R", "ELGA_SIEF_R", "ELGA_EPSI_R", "ELNO_SIEF_R", "NOEU_SIEF_R",
                              "ELGA_VARI_R", "NOEU_GEOM_R", "CART_DEPL_R"})
                       .notSupported({"ELGA_EPSI_R", "ELGA_VARI_R", "NOEU_GEOM_R",
                                      "CART_DEPL_R"}),
                   TXM("OPERATION").mandatory()
                       .into({"EXTR", "AFFE", "ASSE", "EVAL", "DISC", "COMB", "R2C", "C2R", "NORMALE", "ASSE_DEPL"})
                       .notSupported({"AFFE", "ASSE", "EVAL", "DISC", "COMB", "R2C", "C2R", "NORMALE", "ASSE_DEPL"}),
                   bloc(when("OPERATION", {"EXTR"}),
                        join({{CO("RESULTAT", kAnyResult), CO("FISSURE", {kCrack})},
                              {bloc(whenPresent("RESULTAT"),
                                    {TXM("NOM_CHAM").mandatory(), I("NUME_ORDRE"), R("INST"), critere(),
                                     R("PRECISION").def(1.0e-6)},
                                    {unParmi({"NUME_ORDRE", "INST"})}),
                               bloc(whenPresent("FISSURE"),
                                    {TXM("NOM_CHAM").mandatory()
                                         .into({"LTNO", "LNNO", "GRLTNO", "GRLNNO", "STNO", "STNOR", "BASLOC",
                                                "GRI.LNNO", "GRI.LTNO", "GRI.GRLNNO", "GRI.GRLTNO"})
                                         .notSupported({"STNO", "STNOR", "BASLOC", "GRI.LNNO", "GRI.LTNO",
                                                        "GRI.GRLNNO", "GRI.GRLTNO"})})},
                              unsupported({"TYPE_MAXI", "TYPE_RESU", "FREQ", "NUME_MODE", "NOEUD_CMP", "NOM_CAS",
                                           "ANGLE", "TABLE", "MAILLAGE", "LIST_INST", "LIST_FREQ"},
                                          "miniaster extracts a field of a result (NUME_ORDRE or INST) or a level "
                                          "set of a crack")}),
                        {unParmi({"RESULTAT", "FISSURE"})}),
                   info(), titre()},
                  unsupported({"MODELE", "PROL_ZERO", "OPTION", "CHAM_F", "CHAM_GD", "CARA_ELEM", "PROPRIETE"},
                              "only OPERATION='EXTR' is supported"),
              }))
              .resultFrom([](const KeywordSet& kw) {
                  return kw.text("TYPE_CHAM").rfind("NOEU_", 0) == 0 ? kNodalField : kGaussField;
              }));
}

}  // namespace ma::catalog_entries
