#pragma once
// CALC_TABLE's operations on an in-memory table (commands_spec.md §3), with the semantics of
// code_aster's Python table engine (which differ slightly from TEST_TABLE's Fortran filters).
#include <optional>
#include <string>
#include <vector>

#include "post/Table.hpp"

namespace ma {

class Function;

// OPERATION='EXTR': keep exactly these columns in this order; rows left empty disappear.
void extractColumns(Table& table, const std::vector<std::string>& names);

// OPERATION='FILTRE'.
struct RowFilter {
    std::string column;
    std::string comparison = "EQ";    // EQ NE GT LT GE LE REGEXP VIDE NON_VIDE MAXI MAXI_ABS MINI MINI_ABS
    std::vector<double> reals;        // VALE
    std::vector<long long> integers;  // VALE_I
    std::vector<std::string> texts;   // VALE_K (the pattern for REGEXP)
    bool relative = true;             // CRITERE
    double precision = 1.0e-3;        // PRECISION

    // The trace line code_aster appends to the title.
    std::string describe() const;
};
void filterRows(Table& table, const RowFilter& filter);

// OPERATION='COMB'. Without key columns: the rows of `other` are appended. With key columns:
// rows whose key is unique in both tables are merged into the matching row, others are appended
// (or dropped when `restrict` — RESTREINT='OUI'). `realFormat` (FORMAT_R, printf form) rounds
// real keys before comparing them.
void combineTables(Table& table, const Table& other, const std::vector<std::string>& keys, bool restrict,
                   const std::string& realFormat = {});

// OPERATION='OPER': new real column `newColumn` = formula(arguments) on every row where all the
// arguments have a value (empty cell otherwise). Arguments are the columns `argumentColumns`
// (NOM_COLONNE) or, when empty, the columns named after the formula's parameters. The formula is
// evaluated once for all rows (batch).
void addFormulaColumn(Table& table, const Function& formula, const std::string& newColumn,
                      const std::vector<std::string>& argumentColumns);

// OPERATION='RENOMME'.
void renameColumn(Table& table, const std::string& from, const std::string& to);
// OPERATION='SUPPRIME'.
void removeColumns(Table& table, const std::vector<std::string>& names);
// OPERATION='TRI': stable sort on the columns in order; empty cells sort first.
void sortRows(Table& table, const std::vector<std::string>& columns, bool ascending);
// OPERATION='AJOUT_COLONNE': constant columns (value type gives the column type).
void addConstantColumns(Table& table, const std::vector<std::string>& names, const std::vector<Cell>& values);

// Type of a text column able to hold `text` (K8, K16, K24, K32, K80).
ColumnType textColumnFor(size_t length);

// code_aster's automatic title line (commands_spec.md §3.1):
// "ASTER <version> CONCEPT <name> CALCULE LE <mm/dd/YYYY> A <HH:MM:SS> DE TYPE <TYPE>", words
// re-flowed on lines of at most 80 characters.
std::vector<std::string> automaticTitle(const std::string& conceptName, const std::string& typeName);

}  // namespace ma
