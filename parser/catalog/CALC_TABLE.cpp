// CALC_TABLE: table operations (filter, extract, rename, sort, combine, formula columns, delete).
#include "core/FortranFormat.hpp"
#include "parser/catalog/common/Blocks.hpp"

namespace ma::catalog_entries {

void CALC_TABLE(Catalog& c) {
    c.add(cmd("CALC_TABLE", kTable)
              .reuse(Reuse::Optional)
              .keywords({
                  CO("TABLE", {kTable}).mandatory(),
                  fact("ACTION").many().mandatory().keywords({
                      TXM("OPERATION").mandatory()
                          .into({"FILTRE", "EXTR", "RENOMME", "TRI", "COMB", "OPER", "SUPPRIME", "AJOUT_LIGNE",
                                 "AJOUT_COLONNE", "UNIQUE", "STATISTIQUES", "CALCUL"})
                          .notSupported({"AJOUT_LIGNE", "AJOUT_COLONNE", "UNIQUE", "STATISTIQUES", "CALCUL"}),
                      bloc(when("OPERATION", {"FILTRE"}), tableFilter(true)),
                      bloc(when("OPERATION", {"EXTR"}), {TXM("NOM_PARA").many().mandatory()}),
                      bloc(when("OPERATION", {"RENOMME"}), {TXM("NOM_PARA").min(2).max(2).mandatory()}),
                      bloc(when("OPERATION", {"TRI"}), tableSort()),
                      bloc(when("OPERATION", {"COMB"}),
                           {CO("TABLE", {kTable}).mandatory(), TXM("NOM_PARA").many(),
                            yesNo("RESTREINT").def("NON"), TXM("FORMAT_R").checkedBy(fortranFormatProblem)}),
                      bloc(when("OPERATION", {"OPER"}),
                           {CO("FORMULE", {kFormula}).mandatory(), TXM("NOM_PARA").mandatory(),
                            TXM("NOM_COLONNE").many()}),
                      bloc(when("OPERATION", {"SUPPRIME"}), {TXM("NOM_PARA").many().mandatory()}),
                  }),
                  titre(), info()}));
}

}  // namespace ma::catalog_entries
