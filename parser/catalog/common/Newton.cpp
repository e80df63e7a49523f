// NEWTON: when the tangent matrix is rebuilt, and which one.
#include "parser/catalog/common/Blocks.hpp"

namespace ma::catalog_entries {

Keyword newton() {
    return fact("NEWTON").byDefault().keywords({
        I("REAC_INCR").def(1).range(0, {}), I("REAC_ITER").def(1).range(0, {}),
        TXM("MATRICE").into({"TANGENTE", "ELASTIQUE"}).def("TANGENTE"),
        TXM("PREDICTION").into({"DEPL_CALCULE", "TANGENTE", "ELASTIQUE", "EXTRAPOLE"}),
        I("REAC_ITER_ELAS").def(0), R("PAS_MINI_ELAS")});
}

}  // namespace ma::catalog_entries
