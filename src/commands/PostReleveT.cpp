// POST_RELEVE_T, OPERATION='EXTRACTION' of nodal fields on nodes (commands_spec.md §2).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "core/Error.hpp"
#include "core/Function.hpp"
#include "core/Messages.hpp"
#include "parser/CommandRegistry.hpp"
#include "post/NodalExtraction.hpp"
#include "post/TableOperations.hpp"

namespace ma {
namespace {

// The steps of RESULTAT selected by the access keywords, in the requested order (all orders
// ascending when none is given).
std::vector<const ResultStep*> selectSteps(const KeywordSet& a, const Result& result) {
    std::vector<const ResultStep*> out;
    const bool relative = a.text("CRITERE") == "RELATIF";
    const double precision = a.real("PRECISION");
    auto byInst = [&](const std::vector<double>& insts) {
        for (double t : insts) out.push_back(&result.stepAtInst(t, precision, relative));
    };
    for (const char* k : {"LIST_ORDRE", "FREQ", "LIST_FREQ", "NUME_MODE", "NOEUD_CMP", "NOM_CAS", "ANGLE"})
        if (a.has(k))
            throw NotImplemented(a.pathOf(k) +
                                 " is not supported by miniaster (NUME_ORDRE, INST, LIST_INST, TOUT_ORDRE are)");
    if (a.has("NUME_ORDRE")) {
        for (long long o : a.integers("NUME_ORDRE")) out.push_back(&result.step(int(o)));
    } else if (a.has("INST")) {
        byInst(a.reals("INST"));
    } else if (a.has("LIST_INST")) {
        byInst(a.object<RealList>("LIST_INST")->values);
    } else {
        for (const auto& s : result.steps) out.push_back(&s);
        std::stable_sort(out.begin(), out.end(), [](auto* x, auto* y) { return x->order < y->order; });
    }
    if (out.empty()) throw UserError(fmt::format("result {} has no stored step", result.name));
    return out;
}

// POINT of MOMENT: 2 or 3 coordinates (z = 0 with 2).
std::array<double, 3> momentPoint(const KeywordSet& a) {
    const auto p = a.reals("POINT");
    if (p.size() != 2 && p.size() != 3)
        throw UserError(
            fmt::format("{}: {} value(s) given, 2 or 3 coordinates are needed", a.pathOf("POINT"), p.size()));
    return {p[0], p[1], p.size() == 3 ? p[2] : 0.0};
}

ConceptPtr postReleveT(const KeywordSet& kw, CommandContext& ctx) {
    std::vector<NodalExtraction> actions;
    for (const auto& a : kw.factor("ACTION")) {
        const auto operations = a.texts("OPERATION");
        if (operations.size() != 1 || operations[0] != "EXTRACTION")
            throw NotImplemented(
                fmt::format("{}: only OPERATION='EXTRACTION' is supported by miniaster", a.pathOf("OPERATION")));
        for (const char* k : {"INVARIANT", "ELEM_PRINCIPAUX", "GROUP_MA", "MAILLE", "CHEMIN"})
            if (a.has(k)) throw NotImplemented(a.pathOf(k) + " is not supported by miniaster");
        if (a.text("REPERE") != "GLOBAL")
            throw NotImplemented(a.pathOf("REPERE") + ": only REPERE='GLOBAL' is supported by miniaster");
        NodalExtraction x;
        x.title = a.text("INTITULE");
        x.keywordPath = a.path();
        if (a.has("NOEUD")) x.nodes = a.texts("NOEUD");
        if (a.has("GROUP_NO")) x.nodeGroups = a.texts("GROUP_NO");
        if (x.nodes.empty() && x.nodeGroups.empty()) throw UserError(a.path() + ": give the nodes (NOEUD or GROUP_NO)");
        if (a.has("RESULTAT")) {
            auto result = a.object<Result>("RESULTAT");
            x.fieldName = a.text("NOM_CHAM");
            x.steps = selectSteps(a, *result);
            x.result = result;
        } else {
            auto field = std::dynamic_pointer_cast<NodalField>(a.rawObject("CHAM_GD"));
            if (!field) throw NotImplemented(a.pathOf("CHAM_GD") + ": only nodal fields (cham_no) are supported");
            x.field = field;
        }
        x.allComponents = a.has("TOUT_CMP");
        x.resultant = a.has("RESULTANTE");
        if (x.resultant) {
            x.components = a.texts("RESULTANTE");
            if (a.has("MOMENT")) x.point = momentPoint(a);
            x.moment = a.has("MOMENT");
        } else if (!x.allComponents) {
            if (!a.has("NOM_CMP")) throw UserError(a.path() + ": give TOUT_CMP='OUI', NOM_CMP or RESULTANTE");
            x.components = a.texts("NOM_CMP");
        }
        actions.push_back(std::move(x));
    }
    auto table = extractNodalValues(actions);
    table->title = {automaticTitle(ctx.resultName, table->typeName()).front()};
    msg().infof("    table with {} rows: {}", table->rowCount(), fmt::join(table->columnNames(), ", "));
    return table;
}

MA_REGISTER_COMMAND("POST_RELEVE_T", postReleveT);

}  // namespace
}  // namespace ma
