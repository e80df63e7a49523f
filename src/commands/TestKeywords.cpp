#include "commands/TestKeywords.hpp"

#include <fmt/format.h>

#include <filesystem>

#include "core/Error.hpp"

namespace ma::test_keywords {
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

}  // namespace

TestChecks checks(const KeywordSet& kw, const std::string& command, const CommandContext& ctx) {
    TestChecks rq;
    if (kw.has("VALE_CALC")) rq.calc = realCells(kw, "VALE_CALC");
    else if (kw.has("VALE_CALC_I")) rq.calc = cells(kw, "VALE_CALC_I");
    else if (kw.has("VALE_CALC_K")) rq.calc = cells(kw, "VALE_CALC_K");
    else if (kw.has("VALE") || kw.has("VALE_I")) {  // legacy syntax of TEST_TABLE (§1.8)
        rq.legacyVale = true;
        rq.calc = kw.has("VALE") ? realCells(kw, "VALE") : cells(kw, "VALE_I");
    } else {
        throw UserError(kw.path() + ": " + command + " needs VALE_CALC");
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
    if (kw.has("CRITERE")) rq.relative = kw.texts("CRITERE").front() == "RELATIF";
    rq.absoluteValues = kw.has("VALE_ABS") && kw.text("VALE_ABS") == "OUI";
    if (kw.has("TOLE_MACHINE")) rq.machineTolerance = kw.reals("TOLE_MACHINE").front();
    // PRECISION exists (default 1e-3) with REFERENCE or TEST_TABLE's legacy VALE / VALE_I only: a
    // non-regression check alone uses TOLE_MACHINE.
    if (kw.has("PRECISION")) rq.precision = kw.real("PRECISION");
    rq.where = fmt::format("{} ({}line {})", command,
                           ctx.commFile.empty() ? "" : std::filesystem::path(ctx.commFile).filename().string() + " ",
                           ctx.line);
    return rq;
}

}  // namespace ma::test_keywords
