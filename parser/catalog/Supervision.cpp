// Supervision commands: DEBUT, FIN, FORMULE, DEFI_FONCTION, DEFI_LIST_REEL, PRE_GIBI
// (commands_spec §7). DEBUT, FIN, FORMULE and PRE_GIBI are executed by the supervisor itself.
#include "parser/catalog/Types.hpp"

namespace ma::catalog_entries {
using namespace cata;
using namespace cata::types;

void addSupervisionCommands(Catalog& c) {
    c.add(cmd("DEBUT").keywords(join({
        {fact("CODE").keywords({TXM("NIV_PUB_WEB").into({"INTERNET", "INTRANET"}),
                                TXM("NOM"),  // legacy (≤ 2013): test case name
                                TXM("VISU_EFICAS").into({"OUI", "NON"})})
             .rules({auMoinsUn({"NIV_PUB_WEB", "NOM"})}),
         fact("DEBUG").keywords({yesNo("SDVERI"), yesNo("JEVEUX"), yesNo("JXVERI"), yesNo("HIST_ETAPE")}),
         // miniaster always runs command by command (code_aster's PAR_LOT='NON').
         yesNo("PAR_LOT"), yesNo("IMPR_MACRO")},
        unsupported({"BASE", "MEMOIRE", "RESERVE_CPU", "IGNORE_ALARM", "LANG", "ERREUR", "MESURE_TEMPS"},
                    "no effect in miniaster, remove it"),
    })));

    c.add(cmd("FIN").keywords(join({
        {yesNo("RETASSAGE"), yesNo("INFO_RESU"), yesNo("PROC0")},
        {unsupported("FORMAT_HDF", "miniaster does not save a database")},
    })));

    // Other keywords are the objects of the evaluation context (depx=depx...).
    c.add(cmd("FORMULE", kFormula)
              .keywords({TXM("VALE"), TXM("NOM_PARA").many().mandatory(),
                         unsupported("VALE_C", "complex formulas")})
              .rules({unParmi({"VALE", "VALE_C"})})
              .contextKeywords());

    c.add(cmd("DEFI_FONCTION", kFunction).keywords(join({
        {TXM("NOM_PARA").mandatory(), TXM("NOM_RESU").def("TOUTRESU"), R("VALE").many().min(2).mandatory(),
         TXM("INTERPOL").max(2).into({"NON", "LIN", "LOG"}).notSupported({"NON", "LOG"}).def("LIN"),
         TXM("PROL_GAUCHE").into({"CONSTANT", "LINEAIRE", "EXCLU"}).def("EXCLU"),
         TXM("PROL_DROITE").into({"CONSTANT", "LINEAIRE", "EXCLU"}).def("EXCLU"),
         TXM("VERIF").into({"CROISSANT", "NON"}).def("CROISSANT"), info(), titre()},
        unsupported({"VALE_C", "ABSCISSE", "ORDONNEE", "VALE_PARA", "VALE_FONC", "NOEUD_PARA", "NOM_PARA_FONC"},
                    "miniaster functions are given by VALE=(x1, y1, x2, y2, ...)"),
    })));

    c.add(cmd("DEFI_LIST_REEL", kRealList)
              .keywords({R("VALE").many(), R("DEBUT"),
                         fact("INTERVALLE").many().keywords({R("JUSQU_A").mandatory(), I("NOMBRE").range(1, {}), R("PAS")})
                             .rules({unParmi({"NOMBRE", "PAS"})}),
                         info(), titre()})
              .rules({unParmi({"VALE", "DEBUT"}), ensemble({"DEBUT", "INTERVALLE"})}));

    // Legacy GIBI conversion (ssnv511 2010-2011): a no-op, the MED mesh of unit 20 is read instead.
    c.add(cmd("PRE_GIBI").keywords({I("UNITE_GIBI").def(19), I("UNITE_MAILLAGE").def(20)}));
}

}  // namespace ma::catalog_entries
