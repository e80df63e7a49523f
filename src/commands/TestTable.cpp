// TEST_TABLE: checks one value of a table against VALE_CALC (non-regression) and VALE_REFE
// (reference), prints code_aster's report block and records the lines for the run summary
// (commands_spec.md §1).
#include <fmt/format.h>

#include "commands/TableKeywords.hpp"
#include "commands/TestKeywords.hpp"
#include "core/Error.hpp"
#include "parser/CommandRegistry.hpp"
#include "post/TestCheck.hpp"

namespace ma {
namespace {

ConceptPtr testTable(const KeywordSet& kw, CommandContext& ctx) {
    auto table = kw.object<Table>("TABLE");
    for (const char* complex : {"VALE_CALC_C", "VALE_REFE_C", "VALE_C"})
        if (kw.has(complex)) throw NotImplemented(kw.pathOf(complex) + ": complex tables are not supported");

    TestTableRequest rq;
    static_cast<TestChecks&>(rq) = test_keywords::checks(kw, "TEST_TABLE", ctx);
    rq.tableName = table->name;
    rq.column = kw.text("NOM_PARA");
    if (kw.has("TYPE_TEST")) rq.typeTest = kw.text("TYPE_TEST");
    for (const auto& f : kw.factor("FILTRE")) {
        // TEST_TABLE's FILTRE takes one value (catalog), compared with Fortran semantics.
        const RowFilter r = tables::rowFilter(f);
        TestFilter filter{r.column, r.comparison, {}, r.relative, r.precision};
        if (!r.reals.empty()) filter.value = r.reals.front();
        else if (!r.integers.empty()) filter.value = r.integers.front();
        else if (!r.texts.empty()) filter.value = r.texts.front();
        rq.filters.push_back(std::move(filter));
    }

    runTestTable(*table, rq);
    return nullptr;
}

MA_REGISTER_COMMAND("TEST_TABLE", testTable);

}  // namespace
}  // namespace ma
