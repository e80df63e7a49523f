// AFFE_MODELE: model: a modelling (D_PLAN, C_PLAN, 3D) assigned to cells.
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void AFFE_MODELE(Catalog& c) {
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
}

}  // namespace ma::catalog_entries
