// CONVERGENCE: the residual criteria and the iteration limits of the Newton loop.
#include "parser/catalog/common/Blocks.hpp"

namespace ma::catalog_entries {

Keyword convergence() {
    return fact("CONVERGENCE").byDefault().keywords(join({
        {R("RESI_GLOB_MAXI").range(0, {}), R("RESI_GLOB_RELA").range(0, {}),
         I("ITER_GLOB_MAXI").def(10).range(0, {}), I("ITER_GLOB_ELAS").def(25),
         yesNo("ARRET").def("OUI")},
        unsupported({"RESI_REFE_RELA", "RESI_COMP_RELA", "SIGM_REFE", "EPSI_REFE"},
                    "miniaster checks RESI_GLOB_MAXI / RESI_GLOB_RELA"),
    }));
}

}  // namespace ma::catalog_entries
