// DEFI_FONCTION: a function of one parameter, piecewise linear.
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void DEFI_FONCTION(Catalog& c) {
    c.add(cmd("DEFI_FONCTION", kFunction).keywords(join({
        {TXM("NOM_PARA").mandatory(), TXM("NOM_RESU").def("TOUTRESU"), R("VALE").many().min(2).mandatory(),
         TXM("INTERPOL").max(2).into({"NON", "LIN", "LOG"}).notSupported({"NON", "LOG"}).def("LIN"),
         TXM("PROL_GAUCHE").into({"CONSTANT", "LINEAIRE", "EXCLU"}).def("EXCLU"),
         TXM("PROL_DROITE").into({"CONSTANT", "LINEAIRE", "EXCLU"}).def("EXCLU"),
         TXM("VERIF").into({"CROISSANT", "NON"}).def("CROISSANT"), info(), titre()},
        unsupported({"VALE_C", "ABSCISSE", "ORDONNEE", "VALE_PARA", "VALE_FONC", "NOEUD_PARA", "NOM_PARA_FONC"},
                    "miniaster functions are given by VALE=(x1, y1, x2, y2, ...)"),
    })));
}

}  // namespace ma::catalog_entries
