// AFFE_CHAR_MECA_F: the loads of AFFE_CHAR_MECA with values given by functions/formulas of
// X, Y, Z, INST (commands_spec §8.5), evaluated in batch at the nodes (DDL_IMPO) or at the
// integration points (PRES_REP, FORCE_INTERNE).
#include "commands/MechanicsKeywords.hpp"
#include "parser/CommandRegistry.hpp"

namespace ma {
namespace {
ConceptPtr affeCharMecaF(const KeywordSet& kw, CommandContext&) { return mechanics::buildMechanicalLoad(kw, true); }
MA_REGISTER_COMMAND("AFFE_CHAR_MECA_F", affeCharMecaF);
}  // namespace
}  // namespace ma
