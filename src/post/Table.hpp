#pragma once
// The table concept (table_sdaster): named, typed columns, rows whose cells may be empty, and a
// title. POST_RELEVE_T and POST_ERREUR create tables; CALC_TABLE transforms them; IMPR_TABLE
// prints them; TEST_TABLE checks their values (commands_spec.md §1–§5).
#include <cstddef>
#include <string>
#include <variant>
#include <vector>

#include "core/Concept.hpp"

namespace ma {

// Column types of code_aster tables: 'I' (integer), 'R' (real), 'K' with a width (K8, K16,
// K24, K32, K80: texts of at most that many characters).
struct ColumnType {
    enum Kind { Integer, Real, Text } kind = Real;
    int width = 0;  // Text only

    static ColumnType integer() { return {Integer, 0}; }
    static ColumnType real() { return {Real, 0}; }
    static ColumnType text(int width) { return {Text, width}; }
    std::string name() const;  // "I", "R", "K8"...
    bool operator==(const ColumnType&) const = default;
};

// An empty cell is std::monostate.
using Cell = std::variant<std::monostate, long long, double, std::string>;
inline bool isEmpty(const Cell& c) { return std::holds_alternative<std::monostate>(c); }
std::string describeCell(const Cell& c);  // for messages

struct Column {
    std::string name;
    ColumnType type;
    std::vector<Cell> cells;  // one per row
};

class Table : public Concept {
public:
    std::string typeName() const override { return "table_sdaster"; }

    std::vector<std::string> title;  // title lines

    size_t rowCount() const { return rows_; }
    size_t columnCount() const { return columns_.size(); }
    const std::vector<Column>& columns() const { return columns_; }
    const Column& column(size_t i) const { return columns_[i]; }
    // -1 when absent.
    int columnIndex(const std::string& columnName) const;
    bool hasColumn(const std::string& columnName) const { return columnIndex(columnName) >= 0; }
    // The column of that name; UserError naming the table and the existing columns otherwise.
    const Column& column(const std::string& columnName) const;
    std::vector<std::string> columnNames() const;

    // Appends a column (empty cells); UserError if it exists. Returns its index.
    size_t addColumn(const std::string& columnName, ColumnType type);
    // Index of the column, created at the end when absent (type must then match).
    size_t ensureColumn(const std::string& columnName, ColumnType type);
    // Lets a text column hold longer texts (never narrows).
    void widenTextColumn(size_t col, int width);
    void renameColumn(const std::string& from, const std::string& to);
    void removeColumn(const std::string& columnName);
    // Keeps only `names`, in that order.
    void selectColumns(const std::vector<std::string>& names);

    // Appends an empty row; returns its index.
    size_t addRow();
    // Sets a cell, checking the value against the column type (a long long is accepted in a real
    // column; texts longer than the column width are an error).
    void set(size_t row, size_t col, Cell value);
    void set(size_t row, const std::string& col, Cell value) { set(row, size_t(columnIndex(col)), std::move(value)); }
    const Cell& cell(size_t row, size_t col) const { return columns_[col].cells[row]; }

    // Keeps the given rows, in the given order (indices may repeat).
    void selectRows(const std::vector<size_t>& rows);
    // Drops rows whose cells are all empty (code_aster does so whenever it builds a table).
    void removeEmptyRows();

private:
    std::vector<Column> columns_;
    size_t rows_ = 0;
};

}  // namespace ma
