// IMPR_TABLE: a table printed in the .resu or a unit.
#include "core/FortranFormat.hpp"
#include "parser/catalog/common/Blocks.hpp"

namespace ma::catalog_entries {

void IMPR_TABLE(Catalog& c) {
    c.add(cmd("IMPR_TABLE").keywords(join({
        {CO("TABLE", {kTable}).mandatory(),
         TXM("FORMAT").into({"TABLEAU", "ASTER", "TABLEAU_CROISE", "AGRAF", "XMGRACE", "NUMPY", "LATEX"})
             .notSupported({"ASTER", "TABLEAU_CROISE", "XMGRACE", "NUMPY", "LATEX"}).def("TABLEAU"),
         I("UNITE").def(8), TXM("NOM_PARA").many(), TXM("FORMAT_R").def("E12.5").checkedBy(fortranFormatProblem), TXM("SEPARATEUR").def(" "),
         TXM("COMMENTAIRE").def("#"), TXM("COMM_PARA").def(""), TXM("DEBUT_LIGNE").def(""),
         TXM("FIN_LIGNE").def("\n"), yesNo("IMPR_FONCTION").def("NON"), titre(), info(),
         fact("TRI").keywords(tableSort())},
        unsupported({"FILTRE", "PAGINATION", "DEBUT_TABLE", "FIN_TABLE", "FORMAT_C", "SENSIBILITE"},
                    "filter or sort the table with CALC_TABLE first"),
    })));
}

}  // namespace ma::catalog_entries
