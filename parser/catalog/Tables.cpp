// Tables: CALC_TABLE, IMPR_TABLE, TEST_TABLE (commands_spec §1, §3, §4).
#include "parser/catalog/Types.hpp"

namespace ma::catalog_entries {
using namespace cata;
using namespace cata::types;

namespace {
const std::vector<std::string> kComparisons{"EQ", "NE", "GT", "LT", "GE", "LE"};

// Filter of table rows (CALC_TABLE ACTION/FILTRE, TEST_TABLE FILTRE): CRIT_COMP and its values.
// `regexp`: CALC_TABLE also accepts CRIT_COMP='REGEXP' (VALE_K = pattern searched in the cell).
std::vector<Keyword> filterKeywords(bool regexp) {
    std::vector<std::string> crit = kComparisons;
    if (regexp) crit.push_back("REGEXP");
    for (const auto* c : {"VIDE", "NON_VIDE", "MAXI", "MAXI_ABS", "MINI", "MINI_ABS"}) crit.push_back(c);
    // Lists of values for CALC_TABLE (any of them), one value for TEST_TABLE.
    auto values = [&](Keyword k) { return regexp ? k.many() : k; };
    std::vector<Keyword> out{
        TXM("NOM_PARA").mandatory(), TXM("CRIT_COMP").into(crit).def("EQ"),
        bloc(when("CRIT_COMP", kComparisons),
             {values(R("VALE")), values(I("VALE_I")), values(TXM("VALE_K")),
              unsupported("VALE_C", "complex values")},
             {unParmi({"VALE", "VALE_I", "VALE_K"})}),
        // Tolerance of real equality: EQ/NE in CALC_TABLE, EQ only in TEST_TABLE (commands_spec §1.1, §3.3).
        bloc(when("CRIT_COMP", regexp ? std::vector<std::string>{"EQ", "NE"} : std::vector<std::string>{"EQ"}),
             {critere(), R("PRECISION").def(1.0e-3)}),
    };
    if (regexp) out.push_back(bloc(when("CRIT_COMP", {"REGEXP"}), {TXM("VALE_K").mandatory()}));
    return out;
}

// Row sort (CALC_TABLE ACTION/TRI, IMPR_TABLE TRI).
std::vector<Keyword> sortKeywords() {
    return {TXM("NOM_PARA").many().mandatory(), TXM("ORDRE").into({"CROISSANT", "DECROISSANT"}).def("CROISSANT")};
}
}  // namespace

void addTableCommands(Catalog& c) {
    c.add(cmd("CALC_TABLE", kTable)
              .reuse(Reuse::Optional)
              .keywords({
                  CO("TABLE", {kTable}).mandatory(),
                  fact("ACTION").many().mandatory().keywords({
                      TXM("OPERATION").mandatory()
                          .into({"FILTRE", "EXTR", "RENOMME", "TRI", "COMB", "OPER", "SUPPRIME", "AJOUT_LIGNE",
                                 "AJOUT_COLONNE", "UNIQUE", "STATISTIQUES", "CALCUL"})
                          .notSupported({"AJOUT_LIGNE", "AJOUT_COLONNE", "UNIQUE", "STATISTIQUES", "CALCUL"}),
                      bloc(when("OPERATION", {"FILTRE"}), filterKeywords(true)),
                      bloc(when("OPERATION", {"EXTR"}), {TXM("NOM_PARA").many().mandatory()}),
                      bloc(when("OPERATION", {"RENOMME"}), {TXM("NOM_PARA").min(2).max(2).mandatory()}),
                      bloc(when("OPERATION", {"TRI"}), sortKeywords()),
                      bloc(when("OPERATION", {"COMB"}),
                           {CO("TABLE", {kTable}).mandatory(), TXM("NOM_PARA").many(),
                            yesNo("RESTREINT").def("NON"), TXM("FORMAT_R")}),
                      bloc(when("OPERATION", {"OPER"}),
                           {CO("FORMULE", {kFormula}).mandatory(), TXM("NOM_PARA").mandatory(),
                            TXM("NOM_COLONNE").many()}),
                      bloc(when("OPERATION", {"SUPPRIME"}), {TXM("NOM_PARA").many().mandatory()}),
                  }),
                  titre(), info()}));

    c.add(cmd("IMPR_TABLE").keywords(join({
        {CO("TABLE", {kTable}).mandatory(),
         TXM("FORMAT").into({"TABLEAU", "ASTER", "TABLEAU_CROISE", "AGRAF", "XMGRACE", "NUMPY", "LATEX"})
             .notSupported({"ASTER", "TABLEAU_CROISE", "AGRAF", "XMGRACE", "NUMPY", "LATEX"}).def("TABLEAU"),
         I("UNITE").def(8), TXM("NOM_PARA").many(), TXM("FORMAT_R").def("E12.5"), TXM("SEPARATEUR").def(" "),
         TXM("COMMENTAIRE").def("#"), TXM("COMM_PARA").def(""), TXM("DEBUT_LIGNE").def(""),
         TXM("FIN_LIGNE").def("\n"), yesNo("IMPR_FONCTION").def("NON"), titre(), info(),
         fact("TRI").keywords(sortKeywords())},
        unsupported({"FILTRE", "PAGINATION", "DEBUT_TABLE", "FIN_TABLE", "FORMAT_C", "SENSIBILITE"},
                    "filter or sort the table with CALC_TABLE first"),
    })));

    c.add(cmd("TEST_TABLE")
              .keywords(join({
                  {CO("TABLE", {kTable}).mandatory(), TXM("NOM_PARA").mandatory(),
                   TXM("TYPE_TEST").into({"SOMM_ABS", "SOMM", "MAX", "MIN"}),
                   fact("FILTRE").many().keywords(filterKeywords(false)),
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
