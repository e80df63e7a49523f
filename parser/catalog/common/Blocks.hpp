#pragma once
// Keyword blocks shared by several commands, one file each in parser/catalog/common/ (as
// code_aster's Cata/Commons): SOLVEUR, EXCIT, COMPORTEMENT, NEWTON, CONVERGENCE, the load
// keywords of AFFE_CHAR_MECA(_F) and the row filter and sort of the table commands.
#include <string>
#include <vector>

#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

// SOLVEUR of MECA_STATIQUE and STAT_NON_LINE (the linear solver and its options).
// `nonLinear`: STAT_NON_LINE's variant (RESI_RELA=-1 by default, FILTRAGE_MATRICE, MIXER_PRECISION).
cata::Keyword solveur(bool nonLinear);
// EXCIT: the loads and their multiplier functions; `nonlinear` adds TYPE_CHARGE (STAT_NON_LINE).
cata::Keyword excit(bool nonlinear);
// COMPORTEMENT, or its legacy name COMP_ELAS (≤ 2013), which is stored as COMPORTEMENT.
cata::Keyword comportement(const std::string& name);
// NEWTON and CONVERGENCE of STAT_NON_LINE.
cata::Keyword newton();
cata::Keyword convergence();
// The keywords of AFFE_CHAR_MECA (real values) or AFFE_CHAR_MECA_F (`functions`: functions or
// formulas of X, Y, Z, INST).
std::vector<cata::Keyword> loadKeywords(bool functions);
// Filter of table rows (CALC_TABLE ACTION/FILTRE, TEST_TABLE FILTRE): CRIT_COMP and its values.
// `regexp`: CALC_TABLE also accepts CRIT_COMP='REGEXP' (VALE_K = pattern searched in the cell).
std::vector<cata::Keyword> tableFilter(bool regexp);
// Row sort (CALC_TABLE ACTION/TRI, IMPR_TABLE TRI).
std::vector<cata::Keyword> tableSort();

}  // namespace ma::catalog_entries
