#pragma once
// IMPR_TABLE, FORMAT='TABLEAU' (commands_spec.md §4): code_aster's default text layout.
#include <string>
#include <vector>

#include "post/Table.hpp"

namespace ma {

struct TablePrintOptions {
    std::vector<std::string> columns;   // NOM_PARA (all columns when empty)
    std::string realFormat = "%12.5E";  // FORMAT_R 'E12.5' in printf form
    bool agraf = false;                 // FORMAT='AGRAF': an empty cell is written '\-' (code_aster's table_py)
};

// The text IMPR_TABLE appends to its unit: '#', the separator line, the title lines, the column
// names, one line per non-empty row, a blank line. Columns without any value are left out.
std::string formatTable(const Table& table, const TablePrintOptions& options = {});

}  // namespace ma
