#include "post/TableOperations.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <map>
#include <regex>
#include <sstream>

#include "core/Error.hpp"
#include "core/Function.hpp"
#include "post/PythonFormat.hpp"

namespace ma {
namespace {

bool isNumber(const Cell& c) { return std::holds_alternative<double>(c) || std::holds_alternative<long long>(c); }
double toDouble(const Cell& c) {
    if (auto* i = std::get_if<long long>(&c)) return double(*i);
    return std::get<double>(c);
}

std::string strip(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string::npos) return {};
    const auto e = s.find_last_not_of(" \t");
    return s.substr(b, e - b + 1);
}

// Python's str() of a cell (used by the text comparisons of the Python engine).
std::string pythonStr(const Cell& c) {
    if (auto* s = std::get_if<std::string>(&c)) return *s;
    if (auto* i = std::get_if<long long>(&c)) return std::to_string(*i);
    if (auto* d = std::get_if<double>(&c)) return pythonRepr(*d);
    return "None";
}

// EQ of the Python engine for one numeric cell against the given values.
bool numberEquals(double v, const std::vector<double>& values, bool relative, double precision) {
    for (double x : values) {
        if (precision == 0.0) {
            if (v == x) return true;
        } else if (!relative) {
            if (x - precision <= v && v <= x + precision) return true;
        } else {
            const double s = x > 0 ? 1.0 : -1.0;
            if (s * x * (1.0 - precision) <= s * v && s * v <= s * x * (1.0 + precision)) return true;
        }
    }
    return false;
}

void checkTextFilter(const Column& col, const RowFilter& f) {
    if (col.type.kind != ColumnType::Text)
        throw UserError(fmt::format("FILTRE on column '{}' ({}) with VALE_K: the column does not hold texts", col.name,
                                    col.type.name()));
    (void)f;
}

}  // namespace

void extractColumns(Table& table, const std::vector<std::string>& names) {
    for (const auto& n : names)
        if (!table.hasColumn(n))
            throw UserError(fmt::format("EXTR: table {} has no column '{}' (columns: {})", table.name, n,
                                        fmt::join(table.columnNames(), ", ")));
    table.selectColumns(names);
    table.removeEmptyRows();
}

std::string RowFilter::describe() const {
    std::string vale;
    if (!texts.empty()) vale = fmt::format("{}", fmt::join(texts, ", "));
    else if (!integers.empty()) vale = fmt::format("{}", fmt::join(integers, ", "));
    else if (!reals.empty()) {
        std::vector<std::string> r;
        for (double x : reals) r.push_back(pythonRepr(x));
        vale = fmt::format("{}", fmt::join(r, ", "));
    } else {
        vale = "None";
    }
    return fmt::format("FILTRE -> NOM_PARA: {} CRIT_COMP: {} VALE: {}", column, comparison, vale);
}

namespace {

// CRIT_COMP MAXI, MINI, MAXI_ABS, MINI_ABS: the rows holding the extreme value.
std::vector<size_t> extremeRows(const std::vector<Cell>& cells, const std::string& op) {
    std::vector<size_t> kept;
    const bool useAbs = op.size() > 4;
    const bool max = op.rfind("MAXI", 0) == 0;
    bool any = false;
    double best = 0;
    for (const auto& c : cells) {
        if (!isNumber(c)) continue;
        const double v = useAbs ? std::abs(toDouble(c)) : toDouble(c);
        if (!any || (max ? v > best : v < best)) best = v;
        any = true;
    }
    for (size_t r = 0; r < cells.size(); ++r) {
        if (!isNumber(cells[r])) continue;
        const double v = toDouble(cells[r]);
        if (useAbs ? (v == best || v == -best) : v == best) kept.push_back(r);
    }
    return kept;
}

// CRIT_COMP EQ, NE: texts compared stripped, numbers within CRITERE/PRECISION.
std::vector<size_t> equalRows(const std::vector<Cell>& cells, const RowFilter& f, const std::vector<double>& numbers,
                              bool numeric) {
    const std::string& op = f.comparison;
    std::vector<size_t> kept;
    for (size_t r = 0; r < cells.size(); ++r) {
        bool eq = false;
        if (!f.texts.empty()) {
            const std::string v = strip(pythonStr(cells[r]));
            for (const auto& t : f.texts)
                if (!isEmpty(cells[r]) && v == strip(t)) eq = true;
        } else {
            if (numbers.empty()) throw UserError(fmt::format("FILTRE CRIT_COMP='{}' needs VALE, VALE_I or VALE_K", op));
            if (!numeric)
                throw UserError(fmt::format("FILTRE on text column '{}' needs VALE_K, not a number", f.column));
            eq = isNumber(cells[r]) && numberEquals(toDouble(cells[r]), numbers, f.relative, f.precision);
        }
        if (eq == (op == "EQ")) kept.push_back(r);
    }
    return kept;
}

// CRIT_COMP GT, GE, LT, LE: against the smallest given value (GT/GE) or the largest (LT/LE).
std::vector<size_t> orderedRows(const Column& col, const RowFilter& f, const std::vector<double>& numbers,
                                bool numeric) {
    const auto& cells = col.cells;
    const std::string& op = f.comparison;
    std::vector<size_t> kept;
    const bool lower = op[0] == 'G';
    if (!f.texts.empty()) {
        checkTextFilter(col, f);
        const std::string c = lower ? *std::min_element(f.texts.begin(), f.texts.end())
                                    : *std::max_element(f.texts.begin(), f.texts.end());
        for (size_t r = 0; r < cells.size(); ++r) {
            auto* s = std::get_if<std::string>(&cells[r]);
            if (!s) continue;
            const bool ok = op == "GT" ? *s > c : op == "GE" ? *s >= c : op == "LT" ? *s < c : *s <= c;
            if (ok) kept.push_back(r);
        }
        return kept;
    }
    if (numbers.empty()) throw UserError(fmt::format("FILTRE CRIT_COMP='{}' needs VALE, VALE_I or VALE_K", op));
    if (!numeric) throw UserError(fmt::format("FILTRE on text column '{}' needs VALE_K, not a number", f.column));
    const double c =
        lower ? *std::min_element(numbers.begin(), numbers.end()) : *std::max_element(numbers.begin(), numbers.end());
    for (size_t r = 0; r < cells.size(); ++r) {
        if (!isNumber(cells[r])) continue;
        const double v = toDouble(cells[r]);
        const bool ok = op == "GT" ? v > c : op == "GE" ? v >= c : op == "LT" ? v < c : v <= c;
        if (ok) kept.push_back(r);
    }
    return kept;
}

}  // namespace

void filterRows(Table& table, const RowFilter& f) {
    const Column& col = table.column(f.column);
    const auto& cells = col.cells;
    const std::string& op = f.comparison;
    std::vector<size_t> kept;

    const bool numeric = col.type.kind != ColumnType::Text;
    std::vector<double> numbers = f.reals;
    for (long long i : f.integers) numbers.push_back(double(i));

    if (op == "VIDE" || op == "NON_VIDE") {
        for (size_t r = 0; r < cells.size(); ++r)
            if (isEmpty(cells[r]) == (op == "VIDE")) kept.push_back(r);
    } else if (op == "REGEXP") {
        checkTextFilter(col, f);
        if (f.texts.size() != 1) throw UserError("FILTRE CRIT_COMP='REGEXP' needs exactly one VALE_K (the pattern)");
        std::regex pattern;
        try {
            pattern = std::regex(f.texts[0], std::regex::ECMAScript);
        } catch (const std::regex_error& e) {
            throw UserError(fmt::format("FILTRE CRIT_COMP='REGEXP': invalid pattern '{}' ({})", f.texts[0], e.what()));
        }
        for (size_t r = 0; r < cells.size(); ++r)
            if (auto* s = std::get_if<std::string>(&cells[r]))
                if (std::regex_search(*s, pattern)) kept.push_back(r);  // search, not full match
    } else if (op == "MAXI" || op == "MINI" || op == "MAXI_ABS" || op == "MINI_ABS") {
        if (!numeric) throw UserError(fmt::format("FILTRE CRIT_COMP='{}' on text column '{}'", op, f.column));
        kept = extremeRows(cells, op);
    } else if (op == "EQ" || op == "NE") {
        kept = equalRows(cells, f, numbers, numeric);
    } else if (op == "GT" || op == "GE" || op == "LT" || op == "LE") {
        kept = orderedRows(col, f, numbers, numeric);
    } else {
        throw UserError(fmt::format("FILTRE: unknown CRIT_COMP '{}'", op));
    }
    table.selectRows(kept);
    table.removeEmptyRows();
}

namespace {

// Key of a row for COMB with NOM_PARA: the cells as comparable text.
std::string rowKey(const Table& t, const std::vector<size_t>& cols, size_t row, const std::string& realFormat) {
    std::string key;
    for (size_t c : cols) {
        const Cell& cell = t.cell(row, c);
        if (auto* d = std::get_if<double>(&cell))
            key += realFormat.empty() ? "R" + pythonRepr(*d) : "R" + printfReal(realFormat.c_str(), *d);
        else if (auto* i = std::get_if<long long>(&cell)) key += "I" + std::to_string(*i);
        else if (auto* s = std::get_if<std::string>(&cell)) key += "K" + strip(*s);
        else key += "N";
        key += '\x1f';
    }
    return key;
}

}  // namespace

void combineTables(Table& table, const Table& other, const std::vector<std::string>& keys, bool restrict,
                   const std::string& realFormat) {
    // Columns of `other` not yet in `table` go at the end; shared columns must agree on kind.
    std::vector<size_t> target(other.columnCount());
    for (size_t j = 0; j < other.columnCount(); ++j) {
        const Column& oc = other.column(j);
        const int i = table.columnIndex(oc.name);
        if (i < 0) {
            target[j] = table.addColumn(oc.name, oc.type);
        } else {
            const Column& tc = table.column(size_t(i));
            if (tc.type.kind != oc.type.kind)
                throw UserError(fmt::format("COMB: column '{}' is {} in table {} and {} in table {}", oc.name,
                                            tc.type.name(), table.name, oc.type.name(), other.name));
            // code_aster's Python tables have no fixed text width: keep the wider one.
            if (tc.type.kind == ColumnType::Text && oc.type.width > tc.type.width)
                table.widenTextColumn(size_t(i), oc.type.width);
            target[j] = size_t(i);
        }
    }
    auto copyRow = [&](size_t from, size_t to) {
        for (size_t j = 0; j < other.columnCount(); ++j)
            if (!isEmpty(other.cell(from, j))) table.set(to, target[j], other.cell(from, j));
    };

    if (keys.empty()) {
        for (size_t r = 0; r < other.rowCount(); ++r) copyRow(r, table.addRow());
        table.removeEmptyRows();
        return;
    }

    std::vector<size_t> keyCols1, keyCols2;
    for (const auto& k : keys) {
        if (!table.hasColumn(k) || !other.hasColumn(k))
            throw UserError(fmt::format("COMB: key column '{}' (NOM_PARA) must exist in both tables {} and {}", k,
                                        table.name, other.name));
        keyCols1.push_back(size_t(table.columnIndex(k)));
        keyCols2.push_back(size_t(other.columnIndex(k)));
    }
    const size_t rows1 = table.rowCount();
    std::map<std::string, std::vector<size_t>> index1, index2;
    for (size_t r = 0; r < rows1; ++r) index1[rowKey(table, keyCols1, r, realFormat)].push_back(r);
    for (size_t r = 0; r < other.rowCount(); ++r) index2[rowKey(other, keyCols2, r, realFormat)].push_back(r);
    for (size_t r = 0; r < other.rowCount(); ++r) {
        const std::string key = rowKey(other, keyCols2, r, realFormat);
        auto it1 = index1.find(key);
        if (it1 != index1.end() && it1->second.size() == 1 && index2[key].size() == 1) {
            copyRow(r, it1->second.front());
        } else if (!restrict) {
            copyRow(r, table.addRow());
        }
    }
    table.removeEmptyRows();
}

void addFormulaColumn(Table& table, const Function& formula, const std::string& newColumn,
                      const std::vector<std::string>& argumentColumns) {
    const auto& params = formula.parameters();
    if (table.hasColumn(newColumn))
        throw UserError(fmt::format("OPER: column '{}' already exists in table {}", newColumn, table.name));
    std::vector<std::string> argCols = argumentColumns.empty() ? params : argumentColumns;
    if (argCols.size() != params.size())
        throw UserError(fmt::format("OPER: NOM_COLONNE gives {} columns but formula {} has {} parameters ({})",
                                    argCols.size(), formula.name, params.size(), fmt::join(params, ", ")));
    std::vector<const Column*> cols;
    for (const auto& c : argCols) {
        if (!table.hasColumn(c))
            throw UserError(fmt::format("OPER: formula {} needs column '{}', absent from table {} (columns: {})",
                                        formula.name, c, table.name, fmt::join(table.columnNames(), ", ")));
        const Column& col = table.column(c);
        if (col.type.kind == ColumnType::Text)
            throw UserError(
                fmt::format("OPER: column '{}' holds texts and cannot be an argument of formula {}", c, formula.name));
        cols.push_back(&col);
    }
    // Rows where every argument has a value, evaluated in one batch.
    std::vector<size_t> rows;
    for (size_t r = 0; r < table.rowCount(); ++r) {
        bool full = true;
        for (const Column* col : cols) full = full && isNumber(col->cells[r]);
        if (full) rows.push_back(r);
    }
    std::map<std::string, std::vector<double>> args;
    for (size_t j = 0; j < params.size(); ++j) {
        auto& v = args[params[j]];
        v.reserve(rows.size());
        for (size_t r : rows) v.push_back(toDouble(cols[j]->cells[r]));
    }
    std::vector<double> values;
    if (!rows.empty()) values = formula.evaluateColumns(args, rows.size());
    const size_t c = table.addColumn(newColumn, ColumnType::real());
    for (size_t k = 0; k < rows.size(); ++k) table.set(rows[k], c, values[k]);
}

void renameColumn(Table& table, const std::string& from, const std::string& to) { table.renameColumn(from, to); }

void removeColumns(Table& table, const std::vector<std::string>& names) {
    for (const auto& n : names) table.removeColumn(n);
    table.removeEmptyRows();
}

void sortRows(Table& table, const std::vector<std::string>& columns, bool ascending) {
    std::vector<const Column*> cols;
    for (const auto& c : columns) cols.push_back(&table.column(c));
    auto less = [](const Cell& a, const Cell& b) {
        if (isEmpty(a) || isEmpty(b)) return isEmpty(a) && !isEmpty(b);
        if (isNumber(a) && isNumber(b)) return toDouble(a) < toDouble(b);
        if (isNumber(a) != isNumber(b)) return isNumber(a);
        return std::get<std::string>(a) < std::get<std::string>(b);
    };
    std::vector<size_t> order(table.rowCount());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t x, size_t y) {
        for (const Column* col : cols) {
            const Cell& a = col->cells[x];
            const Cell& b = col->cells[y];
            if (less(a, b)) return ascending;
            if (less(b, a)) return !ascending;
        }
        return false;
    });
    table.selectRows(order);
}

ColumnType textColumnFor(size_t length) {
    for (int w : {8, 16, 24, 32, 80})
        if (length <= size_t(w)) return ColumnType::text(w);
    return ColumnType::text(int(length));
}

void addConstantColumns(Table& table, const std::vector<std::string>& names, const std::vector<Cell>& values) {
    if (names.size() != values.size())
        throw UserError(
            fmt::format("AJOUT_COLONNE: {} column names (NOM_PARA) but {} values (VALE)", names.size(), values.size()));
    for (size_t k = 0; k < names.size(); ++k) {
        const Cell& v = values[k];
        ColumnType type = std::holds_alternative<long long>(v) ? ColumnType::integer()
                          : std::holds_alternative<double>(v)  ? ColumnType::real()
                                                               : textColumnFor(std::get<std::string>(v).size());
        const size_t c = table.addColumn(names[k], type);
        for (size_t r = 0; r < table.rowCount(); ++r) table.set(r, c, v);
    }
}

std::vector<std::string> automaticTitle(const std::string& conceptName, const std::string& typeName) {
    std::time_t now = std::time(nullptr);
    std::tm tm{};
    localtime_r(&now, &tm);
    char date[32], hour[32];
    std::strftime(date, sizeof date, "%m/%d/%Y", &tm);
    std::strftime(hour, sizeof hour, "%H:%M:%S", &tm);
    std::string type = typeName;
    for (char& c : type) c = char(std::toupper(static_cast<unsigned char>(c)));
    // The version word names miniaster: these tables are not code_aster's.
    const std::string text =
        fmt::format("ASTER miniaster-0.1 CONCEPT {} CALCULE LE {} A {} DE TYPE {}", conceptName, date, hour, type);
    std::vector<std::string> lines;
    std::istringstream words(text);
    std::string word, line;
    while (words >> word) {
        if (!line.empty() && line.size() + 1 + word.size() > 80) {
            lines.push_back(line);
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
    }
    if (!line.empty()) lines.push_back(line);
    return lines;
}

}  // namespace ma
