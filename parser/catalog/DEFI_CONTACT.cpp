// DEFI_CONTACT: X-FEM contact zones (FORMULATION='XFEM', frictionless).
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void DEFI_CONTACT(Catalog& c) {
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
}

}  // namespace ma::catalog_entries
