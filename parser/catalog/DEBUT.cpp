// DEBUT: start of a command file (run by the supervisor).
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void DEBUT(Catalog& c) {
    c.add(cmd("DEBUT").keywords(join({
        {fact("CODE").keywords({TXM("NIV_PUB_WEB").into({"INTERNET", "INTRANET"}),
                                TXM("NOM"),  // legacy (≤ 2013): test case name
                                TXM("VISU_EFICAS").into({"OUI", "NON"})})
             .rules({auMoinsUn({"NIV_PUB_WEB", "NOM"})}),
         fact("DEBUG").keywords({yesNo("SDVERI"), yesNo("JEVEUX"), yesNo("JXVERI"), yesNo("HIST_ETAPE")}),
         // miniaster always runs command by command (code_aster's PAR_LOT='NON').
         yesNo("PAR_LOT"), yesNo("IMPR_MACRO"),
         // alarms neither printed nor counted; their number is given at the end of the .mess
         TXM("IGNORE_ALARM").many()},
        unsupported({"BASE", "MEMOIRE", "RESERVE_CPU", "LANG", "ERREUR", "MESURE_TEMPS"},
                    "no effect in miniaster, remove it"),
    })));
}

}  // namespace ma::catalog_entries
