#pragma once
// Fortran edit descriptors of real values (FORMAT_R of IMPR_TABLE, CALC_TABLE) as printf formats.
#include <string>

namespace ma {

// Fortran real format (FORMAT_R, e.g. 'E12.5', '1PE12.5', 'F10.3', 'G14.7') -> printf format
// ('%12.5E'; a scale factor nP gives n leading blanks, as code_aster's fmtF2PY). UserError when
// fortranFormatProblem finds one.
std::string fortranToPrintf(const std::string& fortranFormat);
// Why a FORMAT_R value is not one (empty when it is): for the static check of the catalog.
std::string fortranFormatProblem(const std::string& fortranFormat);

}  // namespace ma
