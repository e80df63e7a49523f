// The rows of a table: the filter (CALC_TABLE, TEST_TABLE) and the sort (CALC_TABLE, IMPR_TABLE).
#include "parser/catalog/common/Blocks.hpp"

namespace ma::catalog_entries {

namespace {
const std::vector<std::string> kComparisons{"EQ", "NE", "GT", "LT", "GE", "LE"};
}  // namespace

std::vector<Keyword> tableFilter(bool regexp) {
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
        // Tolerance of real equality: EQ/NE in CALC_TABLE, EQ only in TEST_TABLE.
        bloc(when("CRIT_COMP", regexp ? std::vector<std::string>{"EQ", "NE"} : std::vector<std::string>{"EQ"}),
             {critere(), R("PRECISION").def(1.0e-3)}),
    };
    if (regexp) out.push_back(bloc(when("CRIT_COMP", {"REGEXP"}), {TXM("VALE_K").mandatory()}));
    return out;
}

std::vector<Keyword> tableSort() {
    return {TXM("NOM_PARA").many().mandatory(), TXM("ORDRE").into({"CROISSANT", "DECROISSANT"}).def("CROISSANT")};
}

}  // namespace ma::catalog_entries
