// IMPR_TABLE, FORMAT='TABLEAU' or 'AGRAF' (commands_spec.md §4). UNITE 8 (the default) is the result file
// (.resu); any other unit is a file of the run: the first IMPR_TABLE of the run on that unit
// replaces it, the following ones append (code_aster keeps the unit open for the whole run).
// Every write is atomic.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "commands/TextUnit.hpp"
#include "core/Error.hpp"
#include "core/FortranFormat.hpp"
#include "core/Messages.hpp"
#include "core/Units.hpp"
#include "parser/CommandRegistry.hpp"
#include "post/PostMessages.hpp"
#include "post/TableOperations.hpp"
#include "post/TablePrinter.hpp"

namespace ma {
namespace {

ConceptPtr imprTable(const KeywordSet& kw, CommandContext& ctx) {
    auto table = kw.object<Table>("TABLE");
    const std::string format = kw.text("FORMAT");
    if (format != "TABLEAU" && format != "AGRAF")
        throw NotImplemented(fmt::format("{}: FORMAT='{}' is not supported by miniaster (TABLEAU and AGRAF are)",
                                         kw.pathOf("FORMAT"), format));

    // FILTRE and TRI are refused by the catalog (filter or sort with CALC_TABLE first).
    Table printed = *table;
    if (kw.has("TITRE")) printed.title = kw.texts("TITRE");

    TablePrintOptions options;
    if (kw.has("NOM_PARA")) {
        std::vector<std::string> missing;
        for (const auto& n : kw.texts("NOM_PARA")) {
            if (printed.hasColumn(n)) options.columns.push_back(n);
            else missing.push_back(n);
        }
        if (!missing.empty()) msg().alarm(TABLE0_7, fmt::format("{}", fmt::join(missing, ", ")), table->name);
    }
    options.realFormat = fortranToPrintf(kw.text("FORMAT_R"));
    options.agraf = format == "AGRAF";
    const std::string text = formatTable(printed, options);

    const long long unit = kw.integer("UNITE");
    if (const std::string path = printOnUnit("IMPR_TABLE", unit, ctx.units, text); !path.empty())
        msg().infof("    table {} printed on unit {} ({})", table->name, unit, path);
    return nullptr;
}

MA_REGISTER_COMMAND("IMPR_TABLE", imprTable);

}  // namespace
}  // namespace ma
