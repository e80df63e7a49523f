// CONVERGENCE: the residual criteria and the iteration limits of the Newton loop.
#include "parser/catalog/common/Blocks.hpp"

namespace ma::catalog_entries {

Keyword convergence() {
    return fact("CONVERGENCE").byDefault().keywords(join({
        // code_aster's rule: RESI_GLOB_RELA = 1e-6 only when no criterion is given.
        {R("RESI_GLOB_MAXI").range(0, {}),
         bloc(whenAbsent("RESI_GLOB_MAXI"), {R("RESI_GLOB_RELA").range(0, {}).def(1.0e-6)}),
         bloc(whenPresent("RESI_GLOB_MAXI"), {R("RESI_GLOB_RELA").range(0, {})}),
         I("ITER_GLOB_MAXI").def(10).range(0, {}), I("ITER_GLOB_ELAS").def(25),
         yesNo("ARRET").def("OUI")},
        unsupported({"RESI_REFE_RELA", "RESI_COMP_RELA", "SIGM_REFE", "EPSI_REFE"},
                    "miniaster checks RESI_GLOB_MAXI / RESI_GLOB_RELA"),
    }));
}

}  // namespace ma::catalog_entries
