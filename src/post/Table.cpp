#include "post/Table.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/Error.hpp"
#include "post/PythonFormat.hpp"

namespace ma {

std::string ColumnType::name() const {
    switch (kind) {
        case Integer: return "I";
        case Real: return "R";
        case Text: return fmt::format("K{}", width);
    }
    return "?";
}

std::string describeCell(const Cell& c) {
    if (std::holds_alternative<long long>(c)) return std::to_string(std::get<long long>(c));
    if (std::holds_alternative<double>(c)) return pythonRepr(std::get<double>(c));
    if (std::holds_alternative<std::string>(c)) return "'" + std::get<std::string>(c) + "'";
    return "(empty)";
}

int Table::columnIndex(const std::string& columnName) const {
    for (size_t i = 0; i < columns_.size(); ++i)
        if (columns_[i].name == columnName) return static_cast<int>(i);
    return -1;
}

std::vector<std::string> Table::columnNames() const {
    std::vector<std::string> out;
    for (const auto& c : columns_) out.push_back(c.name);
    return out;
}

const Column& Table::column(const std::string& colName) const {
    const int i = columnIndex(colName);
    if (i < 0)
        throw UserError(
            fmt::format("table {} has no column '{}' (columns: {})", name, colName, fmt::join(columnNames(), ", ")));
    return columns_[size_t(i)];
}

size_t Table::addColumn(const std::string& columnName, ColumnType type) {
    if (hasColumn(columnName))
        throw UserError(fmt::format("table {}: column '{}' already exists", this->name, columnName));
    columns_.push_back(Column{columnName, type, std::vector<Cell>(rows_)});
    return columns_.size() - 1;
}

size_t Table::ensureColumn(const std::string& columnName, ColumnType type) {
    const int i = columnIndex(columnName);
    if (i < 0) return addColumn(columnName, type);
    if (columns_[size_t(i)].type.kind != type.kind)
        throw UserError(fmt::format("table {}: column '{}' has type {}, not {}", this->name, columnName,
                                    columns_[size_t(i)].type.name(), type.name()));
    return size_t(i);
}

void Table::widenTextColumn(size_t col, int width) {
    ColumnType& t = columns_.at(col).type;
    if (t.kind == ColumnType::Text && width > t.width) t.width = width;
}

void Table::renameColumn(const std::string& from, const std::string& to) {
    const int i = columnIndex(from);
    if (i < 0) (void)column(from);  // throws with the list of columns
    if (from != to && hasColumn(to))
        throw UserError(fmt::format("table {}: cannot rename '{}' to '{}', which already exists", name, from, to));
    columns_[size_t(i)].name = to;
}

void Table::removeColumn(const std::string& colName) {
    const int i = columnIndex(colName);
    if (i < 0) (void)column(colName);
    columns_.erase(columns_.begin() + i);
}

void Table::selectColumns(const std::vector<std::string>& names) {
    std::vector<Column> kept;
    for (const auto& n : names) {
        for (const auto& k : kept)
            if (k.name == n) throw UserError(fmt::format("column '{}' is listed twice", n));
        kept.push_back(column(n));
    }
    columns_ = std::move(kept);
}

size_t Table::addRow() {
    for (auto& c : columns_) c.cells.emplace_back();
    return rows_++;
}

void Table::set(size_t row, size_t col, Cell value) {
    Column& c = columns_.at(col);
    switch (c.type.kind) {
        case ColumnType::Real:
            if (auto* i = std::get_if<long long>(&value)) value = double(*i);
            if (!isEmpty(value) && !std::holds_alternative<double>(value))
                throw UserError(
                    fmt::format("table {}: column '{}' holds reals, not {}", name, c.name, describeCell(value)));
            break;
        case ColumnType::Integer:
            if (!isEmpty(value) && !std::holds_alternative<long long>(value))
                throw UserError(
                    fmt::format("table {}: column '{}' holds integers, not {}", name, c.name, describeCell(value)));
            break;
        case ColumnType::Text:
            if (!isEmpty(value)) {
                auto* s = std::get_if<std::string>(&value);
                if (!s)
                    throw UserError(
                        fmt::format("table {}: column '{}' holds texts, not {}", name, c.name, describeCell(value)));
                if (int(s->size()) > c.type.width)
                    throw UserError(fmt::format("table {}: '{}' is longer than the {} characters of column '{}'", name,
                                                *s, c.type.width, c.name));
            }
            break;
    }
    c.cells.at(row) = std::move(value);
}

void Table::selectRows(const std::vector<size_t>& rows) {
    for (auto& c : columns_) {
        std::vector<Cell> kept;
        kept.reserve(rows.size());
        for (size_t r : rows) kept.push_back(c.cells.at(r));
        c.cells = std::move(kept);
    }
    rows_ = rows.size();
}

void Table::removeEmptyRows() {
    std::vector<size_t> kept;
    for (size_t r = 0; r < rows_; ++r) {
        for (const auto& c : columns_)
            if (!isEmpty(c.cells[r])) {
                kept.push_back(r);
                break;
            }
    }
    if (kept.size() != rows_) selectRows(kept);
}

}  // namespace ma
