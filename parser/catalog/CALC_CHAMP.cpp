// CALC_CHAMP: stresses, equivalent stresses and strains derived from a static result, and its nodal forces,
// stored in the result.
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void CALC_CHAMP(Catalog& c) {
    const std::string later =
        "miniaster's CALC_CHAMP computes CONTRAINTE (SIGM_ELGA/ELNO/NOEU, SIEF_ELNO/NOEU), CRITERES "
        "(SIEQ_ELGA/ELNO/NOEU), DEFORMATION (EPSI_ELGA/ELNO/NOEU) and FORCE (FORC_NODA, REAC_NODA)";
    c.add(cmd("CALC_CHAMP")
              .reuse(Reuse::Optional)
              .keywords(join({
                  {CO("RESULTAT", kAnyResult).mandatory(), CO("MODELE", {kModel}),
                   CO("CHAM_MATER", {kMaterialField}), TXM("TOUT_ORDRE").into({"OUI"}), I("NUME_ORDRE").many(),
                   R("INST").many(), critere(), R("PRECISION").def(1.0e-6), TXM("TOUT").into({"OUI"}),
                   TXM("GROUP_MA").many(),
                   TXM("CONTRAINTE")
                       .many()
                       .into({"EFGE_ELGA", "EFGE_ELNO", "EFGE_NOEU", "SIEF_ELGA", "SIEF_ELNO", "SIEF_NOEU",
                              "SIGM_ELGA", "SIGM_ELNO", "SIGM_NOEU", "SIPM_ELNO", "SIPO_ELNO", "SIPO_NOEU",
                              "SIRO_ELEM", "STRX_ELGA"})
                       .notSupported({"EFGE_ELGA", "EFGE_ELNO", "EFGE_NOEU", "SIEF_ELGA", "SIPM_ELNO", "SIPO_ELNO",
                                      "SIPO_NOEU", "SIRO_ELEM", "STRX_ELGA"}),
                   TXM("DEFORMATION")
                       .many()
                       .into({"DEGE_ELGA", "DEGE_ELNO", "DEGE_NOEU", "EPME_ELGA", "EPME_ELNO", "EPME_NOEU",
                              "EPSG_ELGA", "EPSG_ELNO", "EPSG_NOEU", "EPSI_ELGA", "EPSI_ELNO", "EPSI_NOEU",
                              "EPVC_ELGA", "EPVC_ELNO", "EPVC_NOEU", "EPSL_ELGA", "EPSL_ELNO", "EPSL_NOEU"})
                       .notSupported({"DEGE_ELGA", "DEGE_ELNO", "DEGE_NOEU", "EPME_ELGA", "EPME_ELNO", "EPME_NOEU",
                                      "EPSG_ELGA", "EPSG_ELNO", "EPSG_NOEU", "EPVC_ELGA", "EPVC_ELNO", "EPVC_NOEU",
                                      "EPSL_ELGA", "EPSL_ELNO", "EPSL_NOEU"}),
                   TXM("CRITERES")
                       .many()
                       .into({"EPEQ_ELGA", "EPEQ_ELNO", "EPEQ_NOEU", "EPGQ_ELGA", "EPGQ_ELNO", "EPGQ_NOEU",
                              "EPMQ_ELGA", "EPMQ_ELNO", "EPMQ_NOEU", "SIEQ_ELGA", "SIEQ_ELNO", "SIEQ_NOEU"})
                       .notSupported({"EPEQ_ELGA", "EPEQ_ELNO", "EPEQ_NOEU", "EPGQ_ELGA", "EPGQ_ELNO", "EPGQ_NOEU",
                                      "EPMQ_ELGA", "EPMQ_ELNO", "EPMQ_NOEU"}),
                   TXM("FORCE").many().into({"FORC_NODA", "REAC_NODA"}),
                   fact("EXCIT")
                       .many()
                       .keywords({CO("CHARGE", {kMechanicalLoad}).mandatory(), CO("FONC_MULT", kAnyFunction),
                                  R("COEF_MULT"), TXM("TYPE_CHARGE").into({"FIXE_CSTE"}).def("FIXE_CSTE")})
                       .rules({exclus({"FONC_MULT", "COEF_MULT"})}),
                   info(), titre()},
                  unsupported({"ENERGIE", "VARI_INTERNE", "PROPRIETES", "CHAM_UTIL"}, later),
                  unsupported({"CARA_ELEM", "NUME_MODE", "NOEUD_CMP", "NOM_CAS", "FREQ", "LIST_INST", "LIST_FREQ",
                               "LIST_ORDRE", "MAILLE"},
                              "miniaster's CALC_CHAMP selects the orders by TOUT_ORDRE, NUME_ORDRE or INST and the "
                              "cells by TOUT or GROUP_MA"),
              }))
              .rules({exclus({"TOUT_ORDRE", "NUME_ORDRE", "INST"}), exclus({"TOUT", "GROUP_MA"}),
                      auMoinsUn({"CONTRAINTE", "DEFORMATION", "CRITERES", "FORCE"})})
              .resultFrom([](const KeywordSet& kw) { return kw.rawObject("RESULTAT")->typeName(); }));
}

}  // namespace ma::catalog_entries
