// TEST_TABLE: checks one value of a table against VALE_CALC (non-regression) and VALE_REFE
// (reference), prints code_aster's report block and records the lines for the run summary
// (commands_spec.md §1).
#include <fmt/format.h>

#include <filesystem>

#include "commands/TableKeywords.hpp"
#include "core/Error.hpp"
#include "parser/CommandRegistry.hpp"
#include "post/TestCheck.hpp"

namespace ma {
namespace {

std::vector<Cell> cells(const KeywordSet& kw, const std::string& keyword) {
    std::vector<Cell> out;
    for (const auto& v : kw.values(keyword)) {
        if (auto* i = std::get_if<long long>(&v)) out.emplace_back(*i);
        else if (auto* d = std::get_if<double>(&v)) out.emplace_back(*d);
        else if (auto* s = std::get_if<std::string>(&v)) out.emplace_back(*s);
        else throw UserError("keyword " + kw.pathOf(keyword) + ": a value is expected");
    }
    return out;
}

// Reals given as Python ints (VALE_CALC=0) are reals: the catalog types VALE_CALC/VALE_REFE/VALE as R.
std::vector<Cell> realCells(const KeywordSet& kw, const std::string& keyword) {
    std::vector<Cell> out = cells(kw, keyword);
    for (auto& c : out)
        if (auto* i = std::get_if<long long>(&c)) c = double(*i);
    for (const auto& c : out)
        if (!std::holds_alternative<double>(c)) throw UserError("keyword " + kw.pathOf(keyword) + " holds reals");
    return out;
}

ConceptPtr testTable(const KeywordSet& kw, CommandContext& ctx) {
    auto table = kw.object<Table>("TABLE");
    for (const char* complex : {"VALE_CALC_C", "VALE_REFE_C", "VALE_C"})
        if (kw.has(complex)) throw NotImplemented(kw.pathOf(complex) + ": complex tables are not supported");

    TestTableRequest rq;
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

    if (kw.has("VALE_CALC")) rq.calc = realCells(kw, "VALE_CALC");
    else if (kw.has("VALE_CALC_I")) rq.calc = cells(kw, "VALE_CALC_I");
    else if (kw.has("VALE_CALC_K")) rq.calc = cells(kw, "VALE_CALC_K");
    else if (kw.has("VALE") || kw.has("VALE_I")) {  // legacy syntax (§1.8)
        rq.legacyVale = true;
        rq.calc = kw.has("VALE") ? realCells(kw, "VALE") : cells(kw, "VALE_I");
    } else {
        throw UserError("TEST_TABLE needs one of VALE_CALC, VALE_CALC_I, VALE_CALC_K");
    }
    if (kw.has("VALE_REFE")) rq.refe = realCells(kw, "VALE_REFE");
    else if (kw.has("VALE_REFE_I")) rq.refe = cells(kw, "VALE_REFE_I");
    else if (kw.has("VALE_REFE_K")) rq.refe = cells(kw, "VALE_REFE_K");

    if (kw.has("REFERENCE")) rq.reference = kw.text("REFERENCE");
    if (!rq.legacyVale && rq.reference && rq.refe.empty())
        throw UserError(fmt::format("{}='{}' needs VALE_REFE (or VALE_REFE_I, VALE_REFE_K)", kw.pathOf("REFERENCE"),
                                    *rq.reference));
    if (!rq.legacyVale && !rq.reference && !rq.refe.empty())
        throw UserError("VALE_REFE is given without REFERENCE (ANALYTIQUE, SOURCE_EXTERNE, AUTRE_ASTER, NON_DEFINI)");
    if (kw.has("ORDRE_GRANDEUR")) rq.orderOfMagnitude = kw.real("ORDRE_GRANDEUR");
    if (kw.has("LEGENDE")) rq.legend = kw.text("LEGENDE");
    rq.relative = kw.text("CRITERE") == "RELATIF";
    rq.absoluteValues = kw.text("VALE_ABS") == "OUI";
    rq.machineTolerance = kw.real("TOLE_MACHINE");
    // PRECISION exists (default 1e-3) with REFERENCE or the legacy VALE / VALE_I only: a
    // non-regression check alone uses TOLE_MACHINE.
    if (kw.has("PRECISION")) rq.precision = kw.real("PRECISION");
    rq.where = fmt::format("TEST_TABLE ({}line {})",
                           ctx.commFile.empty() ? "" : std::filesystem::path(ctx.commFile).filename().string() + " ",
                           ctx.line);
    runTestTable(*table, rq);
    return nullptr;
}

MA_REGISTER_COMMAND("TEST_TABLE", testTable);

}  // namespace
}  // namespace ma
