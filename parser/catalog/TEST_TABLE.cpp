// TEST_TABLE: a value of a table checked against a reference.
#include "parser/catalog/common/Blocks.hpp"

namespace ma::catalog_entries {

void TEST_TABLE(Catalog& c) {
    c.add(cmd("TEST_TABLE")
              .keywords(join({
                  {CO("TABLE", {kTable}).mandatory(), TXM("NOM_PARA").mandatory(),
                   TXM("TYPE_TEST").into({"SOMM_ABS", "SOMM", "MAX", "MIN"}),
                   fact("FILTRE").many().keywords(tableFilter(false)),
                   R("VALE_CALC").many(), I("VALE_CALC_I").many(), TXM("VALE_CALC_K").many(),
                   // Legacy (≤ 2012-08): VALE= / VALE_I= is a single check against this value,
                   // labelled REFERENCE (default 'NON_REGRESSION'), tolerance PRECISION.
                   R("VALE").many(), I("VALE_I").many(),
                   R("ORDRE_GRANDEUR"), TXM("LEGENDE"), yesNo("VALE_ABS").def("NON"),
                   R("TOLE_MACHINE").def(1.0e-6), critere(),
                   TXM("REFERENCE").into({"ANALYTIQUE", "SOURCE_EXTERNE", "AUTRE_ASTER", "NON_DEFINI", "NON_REGRESSION"}),
                   bloc(whenPresent("REFERENCE"),
                        {R("VALE_REFE").many(), I("VALE_REFE_I").many(), TXM("VALE_REFE_K").many(),
                         R("PRECISION").def(1.0e-3)},
                        {exclus({"VALE_REFE", "VALE_REFE_I", "VALE_REFE_K"})}),
                   bloc(whenPresent("VALE"), {R("PRECISION").def(1.0e-3)}),
                   bloc(whenPresent("VALE_I"), {R("PRECISION").def(1.0e-3)}),
                   TXM("VERSION"),  // legacy, ignored
                   info()},
                  unsupported({"VALE_CALC_C", "VALE_REFE_C", "VALE_C"}, "complex values"),
                  {unsupported("SENSIBILITE", "sensitivity analysis")},
              }))
              .rules({unParmi({"VALE_CALC", "VALE_CALC_I", "VALE_CALC_K", "VALE", "VALE_I"}),
                      presentPresent({"VALE_REFE", "REFERENCE"})}));
}

}  // namespace ma::catalog_entries
