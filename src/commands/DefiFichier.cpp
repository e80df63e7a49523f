// DEFI_FICHIER ACTION='ASSOCIER' (TYPE='ASCII', ACCES='NEW') or 'LIBERER' on UNITE: code_aster opens
// (a new file) or closes the unit. miniaster's text units are opened at their first write (the
// file of the .export's line for the unit, or fort.<unit> of the output folder) and kept open, so
// both actions mean the same here: the unit's next write starts its file afresh. No file is created
// for a unit nothing is written to. The .resu (unit 8) cannot be reassociated.
#include <fmt/format.h>

#include "commands/TextUnit.hpp"
#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "core/Units.hpp"
#include "parser/CommandRegistry.hpp"

namespace ma {
namespace {

ConceptPtr defiFichier(const KeywordSet& kw, CommandContext& ctx) {
    const long long unit = kw.integer("UNITE");
    if (unit == 6 || unit == 8 || unit == 9)
        throw UserError(fmt::format("{}={}: the message, result and error units of the run cannot be redefined",
                                    kw.pathOf("UNITE"), unit));
    if (unit <= 0 || unit > 99)
        throw UserError(fmt::format("{}={}: a logical unit is 1 to 99", kw.pathOf("UNITE"), unit));
    if (!ctx.units) throw UserError("DEFI_FICHIER: no logical units are defined for this run");
    const std::string action = kw.text("ACTION");
    if (ctx.units->hasInput(int(unit)))
        throw UserError(fmt::format("{}={}: the unit is a data file of the run (the .export's D line), not an output",
                                    kw.pathOf("UNITE"), unit));
    const std::string path = ctx.units->output(int(unit));
    restartUnit(path);
    msg().infof("    unit {} {}: {} (written at its first write)", unit, action == "LIBERER" ? "freed" : "associated",
                path);
    return nullptr;
}

MA_REGISTER_COMMAND("DEFI_FICHIER", defiFichier);

}  // namespace
}  // namespace ma
