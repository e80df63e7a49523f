// X-FEM commands: DEFI_FISS_XFEM, MODI_MODELE_XFEM, DEFI_CONTACT (FORMULATION='XFEM'),
// POST_MAIL_XFEM, POST_CHAM_XFEM (xfem_spec §1, §3, §5, §6, §7; commands_spec §8.8, §9).
#include "parser/catalog/Types.hpp"

namespace ma::catalog_entries {
using namespace cata;
using namespace cata::types;

void addXfemCommands(Catalog& c) {
    c.add(cmd("DEFI_FISS_XFEM", kCrack)
              .keywords(join({
                  {CO("MAILLAGE", {kMesh}),
                   CO("MODELE", {kModel}),  // legacy (≤ 2013-10): the mesh is taken from the model
                   TXM("TYPE_DISCONTINUITE").into({"FISSURE", "INTERFACE", "COHESIF"}).notSupported({"COHESIF"})
                       .def("FISSURE"),
                   TXM("CHAM_DISCONTINUITE").into({"DEPL"}).def("DEPL"),
                   fact("DEFI_FISS").mandatory().keywords(join({
                       {CO("FONC_LN", kAnyFunction).mandatory(), CO("FONC_LT", kAnyFunction)},
                       unsupported({"GROUP_MA_FISS", "GROUP_MA_FOND", "FORM_FISS", "CHAM_NO_LSN", "CHAM_NO_LST",
                                    "GROUP_MA_BORD_FISS"},
                                   "level sets are given by FONC_LN (and FONC_LT)"),
                   })),
                   fact("JONCTION").keywords({CO("FISSURE", {kCrack}).many().mandatory(),
                                              R("POINT").max(3).mandatory()}),
                   info({1, 2, 3})},
                  unsupported({"GROUP_MA_ENRI", "TYPE_ENRI_FOND", "RAYON_ENRI", "NB_COUCHES", "FOND_FISS",
                               "FISS_INITIALE", "ORIE_FOND", "CHAM_NO_FOND"},
                              "miniaster enriches every node cut by the interface"),
              }))
              .rules({unParmi({"MAILLAGE", "MODELE"})}));

    c.add(cmd("MODI_MODELE_XFEM", kModel).keywords({
        CO("MODELE_IN", {kModel}).mandatory(), CO("FISSURE", {kCrack}).many().mandatory().max(99),
        // 'P1P1' (≤ 2013-10) and 'OUI' (2013-10 … 2014-10) are older names of 'STANDARD'.
        TXM("CONTACT").into({"SANS", "STANDARD", "MORTAR", "P1P1", "OUI"}).notSupported({"MORTAR"})
            .legacy({{"P1P1", "STANDARD"}, {"OUI", "STANDARD"}}).def("SANS"),
        TXM("PRETRAITEMENTS").into({"AUTO", "SANS", "FORCE"}).def("AUTO"),
        TXM("DECOUPE_FACETTE").into({"DEFAUT", "SOUS_ELEMENTS"}).def("DEFAUT"),
        info({1, 2, 3}),
    }));

    c.add(cmd("DEFI_CONTACT", kContact).keywords(join({
        {CO("MODELE", {kModel}).mandatory(),
         TXM("FORMULATION").into({"DISCRETE", "CONTINUE", "XFEM", "LIAISON_UNIL"})
             .notSupported({"DISCRETE", "CONTINUE", "LIAISON_UNIL"}).def("DISCRETE"),
         TXM("FROTTEMENT").into({"SANS", "COULOMB"}).notSupported({"COULOMB"}).def("SANS"),
         I("ITER_CONT_MAXI").def(30).range(1, {}), TXM("ITER_CONT_TYPE").into({"MAXI", "MULT"}).def("MAXI"),
         TXM("ELIM_ARETE").into({"DUAL", "ELIM"}).def("DUAL"),
         TXM("REAC_GEOM").into({"AUTOMATIQUE", "CONTROLE", "SANS"}).def("SANS"),
         I("NB_ITER_GEOM"),  // REAC_GEOM='CONTROLE' (also found alone in files of 2011-2014)
         I("ITER_GEOM_MAXI"), R("RESI_GEOM"),
         yesNo("STOP_INTERP"),
         fact("ZONE").many().mandatory().keywords(join({
             {CO("FISS_MAIT", {kCrack}).mandatory(),
              TXM("INTEGRATION").into({"NOEUD", "GAUSS", "SIMPSON", "NCOTES"}).def("GAUSS"),
              // ORDRE_INT: degree of the Legendre polynomial (GAUSS), number of subdivisions
              // (SIMPSON), degree of the interpolating polynomial (NCOTES).
              bloc(when("INTEGRATION", {"GAUSS"}), {I("ORDRE_INT").def(6).range(1, 6)}),
              bloc(when("INTEGRATION", {"SIMPSON"}), {I("ORDRE_INT").def(1).range(1, 4)}),
              bloc(when("INTEGRATION", {"NCOTES"}), {I("ORDRE_INT").def(3).range(3, 8)}),
              yesNo("CONTACT_INIT").def("NON"), yesNo("GLISSIERE").def("NON"),
              TXM("ALGO_CONT").into({"STANDARD", "PENALISATION", "CZM"}).notSupported({"CZM"}).def("STANDARD"),
              bloc(when("ALGO_CONT", {"STANDARD"}), {R("COEF_CONT").def(100.0)}),
              bloc(when("ALGO_CONT", {"PENALISATION"}), {R("COEF_PENA_CONT").mandatory().range(0, {})}),
              TXM("ALGO_LAGR").into({"AUTO", "NON", "VERSION1", "VERSION2", "VERSION3"}).def("AUTO"),
              R("COEF_ECHELLE"),  // legacy (2011): scaling of the contact equations
              R("TOLE_PROJ_EXT")},
             unsupported({"COEF_FROT", "ALGO_FROT", "COEF_PENA_FROT", "SEUIL_INIT", "COULOMB", "FROTTEMENT"},
                         "friction is not modelled (frictionless contact only)"),
             unsupported({"RELATION", "FISS_ESCL", "TOLE_PROJ_EXT_F", "GROUP_MA_MAIT", "GROUP_MA_ESCL"},
                         "miniaster models X-FEM contact on FISS_MAIT only"),
         })),
         info()},
        unsupported({"ITER_FROT_MAXI", "RESI_FROT", "ALGO_RESO_FROT", "ALGO_FROT", "COEF_FROT"},
                    "friction is not modelled (frictionless contact only)"),
        unsupported({"ALGO_RESO_CONT", "ALGO_RESO_GEOM", "LISSAGE", "VERI_NORM", "STRATEGIE", "RESI_PRIMAL"},
                    "options of the DISCRETE/CONTINUE formulations"),
    })));

    c.add(cmd("POST_MAIL_XFEM", kMesh).keywords({
        CO("MODELE", {kModel}).mandatory(), TXM("PREF_NOEUD_X").def("NX"), TXM("PREF_NOEUD_M").def("NM"),
        TXM("PREF_NOEUD_P").def("NP"), TXM("PREF_MAILLE_X").def("MX"), TXM("PREF_GROUP_CO").def("NFISSU"), titre(),
        info()}));

    // The result has the type of RESULTAT (evol_elas or evol_noli).
    c.add(cmd("POST_CHAM_XFEM")
              .keywords({CO("MODELE_VISU", {kModel}).mandatory(), CO("RESULTAT", kAnyResult).mandatory(), info()})
              .resultFrom([](const KeywordSet& kw) { return kw.rawObject("RESULTAT")->typeName(); }));
}

}  // namespace ma::catalog_entries
