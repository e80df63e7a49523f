#pragma once
// The FILTRE keyword of the table commands (CALC_TABLE ACTION/OPERATION='FILTRE', TEST_TABLE
// FILTRE): one occurrence -> a row filter. Header-only: included by src/commands files only.
#include "parser/KeywordTree.hpp"
#include "post/TableOperations.hpp"

namespace ma::tables {

// The occurrence's keywords are those of the catalog's tableFilter (parser/catalog/common/TableRows.cpp),
// defaults filled. CRITERE and PRECISION exist only where the comparison has a tolerance (EQ, and
// NE in CALC_TABLE); the filter does not read them elsewhere.
inline RowFilter rowFilter(const KeywordSet& occ) {
    RowFilter f;
    f.column = occ.text("NOM_PARA");
    f.comparison = occ.text("CRIT_COMP");
    if (occ.has("VALE")) f.reals = occ.reals("VALE");
    if (occ.has("VALE_I")) f.integers = occ.integers("VALE_I");
    if (occ.has("VALE_K")) f.texts = occ.texts("VALE_K");
    if (occ.has("CRITERE")) f.relative = occ.text("CRITERE") == "RELATIF";
    if (occ.has("PRECISION")) f.precision = occ.real("PRECISION");
    return f;
}

}  // namespace ma::tables
