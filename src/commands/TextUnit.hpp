#pragma once
// Text written by a command on a logical unit other than the result file (IMPR_TABLE, IMPR_CO).
#include <string>

#include "core/Units.hpp"

namespace ma {

// The first write of the run on a unit replaces its file, the following ones append (code_aster
// keeps the unit open for the whole run). Atomic; rank 0 only.
void appendToUnit(const std::string& command, const std::string& path, const std::string& text);

// DEFI_FICHIER ACTION='ASSOCIER' (ACCES='NEW') or 'LIBERER': the unit's next write replaces its file.
void restartUnit(const std::string& path);

// The text on UNITE: 8 is the result file (.resu); another unit is a file of the run (above).
// Returns that file's path ("" for the .resu). UserError when the run has no units.
std::string printOnUnit(const std::string& command, long long unit, const Units* units, const std::string& text);

}  // namespace ma
