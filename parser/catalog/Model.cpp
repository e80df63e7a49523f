// Model and material commands: AFFE_MODELE, DEFI_MATERIAU, AFFE_MATERIAU (commands_spec §8.3, §8.4).
#include "parser/catalog/Types.hpp"

namespace ma::catalog_entries {
using namespace cata;
using namespace cata::types;

void addModelCommands(Catalog& c) {
    c.add(cmd("AFFE_MODELE", kModel).keywords(join({
        {CO("MAILLAGE", {kMesh}).mandatory(),
         fact("AFFE").many().mandatory().keywords({
             TXM("TOUT").into({"OUI"}), TXM("GROUP_MA").many(), TXM("MAILLE").many(),
             TXM("PHENOMENE").mandatory().into({"MECANIQUE", "THERMIQUE", "ACOUSTIQUE"})
                 .notSupported({"THERMIQUE", "ACOUSTIQUE"}),
             TXM("MODELISATION").mandatory().max(10)
                 .into({"D_PLAN", "C_PLAN", "3D", "AXIS", "DKT", "DST", "COQUE_3D", "POU_D_E", "POU_D_T", "BARRE",
                        "DIS_T", "DIS_TR", "3D_SI", "D_PLAN_SI", "C_PLAN_SI", "AXIS_SI", "PLAN_ELDI", "3D_INCO_UP"})
                 .notSupported({"AXIS", "DKT", "DST", "COQUE_3D", "POU_D_E", "POU_D_T", "BARRE", "DIS_T", "DIS_TR",
                                "3D_SI", "D_PLAN_SI", "C_PLAN_SI", "AXIS_SI", "PLAN_ELDI", "3D_INCO_UP"}),
         }).rules({unParmi({"TOUT", "GROUP_MA", "MAILLE"})}),
         yesNo("VERI_JACOBIEN").def("OUI"),
         // Accepted without effect: miniaster is sequential, every distribution gives the same model.
         fact("DISTRIBUTION").keywords({TXM("METHODE").into({"CENTRALISE", "SOUS_DOMAINE", "MAIL_CONTIGU",
                                                             "MAIL_DISPERSE", "GROUP_ELEM", "SOUS_DOM.OLD"}),
                                        I("NB_SOUS_DOMAINE"), TXM("PARTITIONNEUR"), I("CHARGE_PROC0_MA"),
                                        I("CHARGE_PROC0_SD")}),
         info()},
        unsupported({"PARTITION", "GRANDEUR_CARA", "AFFE_SOUS_STRUC", "VERI_NORM_IFS"},
                    "sub-structures and characteristic sizes are not modelled"),
    })));

    c.add(cmd("DEFI_MATERIAU", kMaterial)
              .keywords(join({
                  {fact("ELAS").keywords({R("E").mandatory().range(0, {}), R("NU").mandatory().range(-1.0, 0.5),
                                          R("RHO"), R("ALPHA"), R("AMOR_ALPHA"), R("AMOR_BETA"), R("AMOR_HYST")}),
                   info()},
                  unsupported({"ELAS_FO", "ELAS_ORTH", "ELAS_ISTR", "ECRO_LINE", "ECRO_PUIS", "TRACTION", "THER",
                               "THER_NL", "BETON_DOUBLE_DP", "ENDO_ORTH_BETON", "MAZARS", "RUPT_FRAG", "VISCOCHAB",
                               "CIN1_CHAB", "ROUSSELIER", "DIS_CONTACT", "ELAS_HYPER"},
                              "miniaster models linear isotropic elasticity (ELAS) only"),
              }))
              .rules({auMoinsUn({"ELAS"})}));

    c.add(cmd("AFFE_MATERIAU", kMaterialField)
              .keywords(join({
                  {CO("MAILLAGE", {kMesh}), CO("MODELE", {kModel}),
                   fact("AFFE").many().mandatory().keywords({
                       TXM("TOUT").into({"OUI"}), TXM("GROUP_MA").many(), TXM("MAILLE").many(),
                       CO("MATER", {kMaterial}).mandatory().max(30)})
                       .rules({unParmi({"TOUT", "GROUP_MA", "MAILLE"})}),
                   info()},
                  unsupported({"AFFE_VARC", "AFFE_COMPOR", "AFFE_NOM_VARC"}, "command variables (temperature...)"),
              }))
              .rules({auMoinsUn({"MAILLAGE", "MODELE"})}));
}

}  // namespace ma::catalog_entries
