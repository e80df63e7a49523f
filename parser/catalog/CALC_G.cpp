// CALC_G: energy release rate and stress intensity factors at a crack front by the theta method
// (code_aster 15's catalogue, code_aster/Cata/Commands/calc_g.py).
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void CALC_G(Catalog& c) {
    const std::string orders = "miniaster's CALC_G selects the orders by TOUT_ORDRE, NUME_ORDRE or INST";
    c.add(cmd("CALC_G", kTable)
              .keywords(join({
                  {fact("THETA")
                       .mandatory()
                       .keywords(join({{CO("FISSURE", {kCrack}).mandatory(), I("NUME_FOND").def(1), R("R_INF"),
                                        R("R_SUP"), I("NB_POINT_FOND")},
                                       unsupported({"FOND_FISS"}, "miniaster's cracks are fiss_xfem (FISSURE)"),
                                       unsupported({"R_INF_FO", "R_SUP_FO"},
                                                   "R_INF and R_SUP are real values in miniaster")}))
                       .rules({presentPresent({"R_INF", "R_SUP"})}),
                   CO("RESULTAT", kAnyResult).mandatory(), TXM("TOUT_ORDRE").into({"OUI"}), I("NUME_ORDRE").many(),
                   R("INST").many(), critere(), R("PRECISION").def(1.0e-6),
                   fact("LISSAGE")
                       .byDefault()
                       .keywords({TXM("LISSAGE_THETA")
                                      .into({"LEGENDRE", "LAGRANGE"})
                                      .def("LEGENDRE"),
                                  TXM("LISSAGE_G")
                                      .into({"LEGENDRE", "LAGRANGE", "LAGRANGE_NO_NO"})
                                      .def("LEGENDRE"),
                                  bloc(when("LISSAGE_THETA", {"LEGENDRE"}),
                                       {I("DEGRE").intoInt({0, 1, 2, 3, 4, 5, 6, 7}).def(5)})}),
                   TXM("OPTION").into({"CALC_G", "CALC_K_G"}).def("CALC_G"), titre(), info()},
                  unsupported({"CHAM_THETA"}, "miniaster does not output the theta field"),
                  unsupported({"LIST_ORDRE", "LIST_INST", "TOUT_MODE", "NUME_MODE", "LIST_MODE", "LIST_FREQ", "FREQ"},
                              orders),
                  unsupported({"EXCIT"}, "CALC_G reads the loads of the result (its EXCIT)"),
                  unsupported({"COMPORTEMENT", "ETAT_INIT"},
                              "miniaster's CALC_G is linear elastic without initial state"),
              }))
              .rules({exclus({"TOUT_ORDRE", "NUME_ORDRE", "INST"})}));
}

}  // namespace ma::catalog_entries
