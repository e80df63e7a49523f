// CALC_TABLE: actions applied in sequence to a copy of TABLE (commands_spec.md §3).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "commands/TableKeywords.hpp"
#include "core/Error.hpp"
#include "core/FortranFormat.hpp"
#include "core/Function.hpp"
#include "core/Messages.hpp"
#include "parser/CommandRegistry.hpp"
#include "post/TableOperations.hpp"

namespace ma {
namespace {

Cell toCell(const KeywordValue& v) {
    if (auto* i = std::get_if<long long>(&v)) return *i;
    if (auto* d = std::get_if<double>(&v)) return *d;
    if (auto* s = std::get_if<std::string>(&v)) return *s;
    throw UserError("AJOUT_COLONNE: VALE must hold numbers or texts");
}

ConceptPtr calcTable(const KeywordSet& kw, CommandContext& ctx) {
    auto input = kw.object<Table>("TABLE");
    auto table = std::make_shared<Table>(*input);
    // Title: kept with reuse, otherwise code_aster's automatic one naming the input table. Actions
    // append trace lines; only the first line survives (§3.1).
    std::vector<std::string> title = ctx.reused ? input->title : automaticTitle(input->name, input->typeName());

    for (const auto& action : kw.factor("ACTION")) {
        const std::string op = action.text("OPERATION");
        if (op == "EXTR") {
            extractColumns(*table, action.texts("NOM_PARA"));
        } else if (op == "FILTRE") {
            const RowFilter f = tables::rowFilter(action);
            try {
                filterRows(*table, f);
            } catch (const UserError& e) { throw UserError(action.path() + ": " + e.what()); }
            title.push_back(f.describe());
        } else if (op == "COMB") {
            auto other = action.object<Table>("TABLE");
            const std::vector<std::string> keys =
                action.has("NOM_PARA") ? action.texts("NOM_PARA") : std::vector<std::string>{};
            const std::string format =
                action.has("FORMAT_R") ? fortranToPrintf(action.text("FORMAT_R")) : std::string();
            combineTables(*table, *other, keys, action.text("RESTREINT") == "OUI", format);
            title.insert(title.end(), other->title.begin(), other->title.end());
            title.push_back(fmt::format("MERGE avec labels=[{}]", fmt::join(keys, ", ")));
        } else if (op == "OPER") {
            auto formula = action.object<Function>("FORMULE");
            const std::vector<std::string> args =
                action.has("NOM_COLONNE") ? action.texts("NOM_COLONNE") : std::vector<std::string>{};
            addFormulaColumn(*table, *formula, action.text("NOM_PARA"), args);
        } else if (op == "RENOMME") {
            const auto names = action.texts("NOM_PARA");
            if (names.size() != 2)
                throw UserError(action.pathOf("NOM_PARA") + " needs two names: the column and its new name");
            renameColumn(*table, names[0], names[1]);
        } else if (op == "SUPPRIME") {
            removeColumns(*table, action.texts("NOM_PARA"));
        } else if (op == "TRI") {
            sortRows(*table, action.texts("NOM_PARA"), action.text("ORDRE") == "CROISSANT");
        } else if (op == "AJOUT_COLONNE") {
            std::vector<Cell> values;
            for (const auto& v : action.values("VALE")) values.push_back(toCell(v));
            addConstantColumns(*table, action.texts("NOM_PARA"), values);
        } else {
            throw NotImplemented(
                fmt::format("{}: OPERATION='{}' is not supported by miniaster (EXTR, FILTRE, COMB, "
                            "OPER, RENOMME, SUPPRIME, TRI, AJOUT_COLONNE are)",
                            action.pathOf("OPERATION"), op));
        }
    }
    table->removeEmptyRows();  // code_aster rebuilds the table: rows without any value vanish
    if (kw.has("TITRE")) title = kw.texts("TITRE");
    table->title.clear();
    if (!title.empty()) table->title.push_back(title.front());
    msg().infof("    table with {} rows and {} columns: {}", table->rowCount(), table->columnCount(),
                fmt::join(table->columnNames(), ", "));
    return table;
}

MA_REGISTER_COMMAND("CALC_TABLE", calcTable);

}  // namespace
}  // namespace ma
