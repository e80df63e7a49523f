#pragma once
// The keywords every TEST_* occurrence shares (code_aster's C_TEST_REFERENCE): VALE_CALC*,
// VALE_REFE*, REFERENCE, PRECISION, CRITERE, TOLE_MACHINE, ORDRE_GRANDEUR, LEGENDE, VALE_ABS.
#include "parser/CommandRegistry.hpp"
#include "post/TestCheck.hpp"

namespace ma::test_keywords {

// The checks of occurrence `kw` of command `command` (TEST_TABLE, TEST_RESU), located at the
// command's .comm line. CRITERE and TOLE_MACHINE may hold two values (TEST_RESU/RESU: the second
// one selects INST); the first one is the check's.
TestChecks checks(const KeywordSet& kw, const std::string& command, const CommandContext& ctx);

}  // namespace ma::test_keywords
