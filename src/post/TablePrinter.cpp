#include "post/TablePrinter.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>

#include "core/Error.hpp"
#include "post/PythonFormat.hpp"

namespace ma {
namespace {

std::string rjust(const std::string& s, size_t w) { return s.size() >= w ? s : std::string(w - s.size(), ' ') + s; }

// Width of the printf real format: that of 0 written with it ("%12.5E" -> 12, " %12.5E" -> 13).
size_t formatWidth(const std::string& f) { return printfReal(f.c_str(), 0.0).size(); }

}  // namespace

std::string formatTable(const Table& table, const TablePrintOptions& options) {
    std::vector<size_t> cols;
    if (options.columns.empty()) {
        for (size_t c = 0; c < table.columnCount(); ++c) cols.push_back(c);
    } else {
        for (const auto& n : options.columns) cols.push_back(size_t(&table.column(n) - &table.column(0)));
    }
    // Columns entirely empty are not printed.
    std::erase_if(cols, [&](size_t c) {
        const auto& cells = table.column(c).cells;
        return std::all_of(cells.begin(), cells.end(), [](const Cell& x) { return isEmpty(x); });
    });

    const size_t realWidth = formatWidth(options.realFormat);
    std::vector<size_t> widths;
    for (size_t c : cols) {
        const Column& col = table.column(c);
        const size_t valueWidth = col.type.kind == ColumnType::Text   ? size_t(col.type.width)
                                  : col.type.kind == ColumnType::Real ? realWidth
                                                                      : 12;
        widths.push_back(std::max(col.name.size(), valueWidth));
    }

    // A lone '#' then each title line as '#' + title (80 characters): '##TITLE' for the first.
    std::string out = "#\n#" + std::string(80, '-') + "\n#";
    for (const auto& line : table.title) {
        out += '#';
        out += ljust(line, 80);
        out += '\n';
    }
    std::string header;
    for (size_t k = 0; k < cols.size(); ++k) {
        if (k) header += ' ';
        const Column& col = table.column(cols[k]);
        const size_t blanks = col.type.kind == ColumnType::Real ? options.realFormat.find('%') : 0;
        header += std::string(blanks, ' ') + ljust(col.name, widths[k] - blanks);
    }
    out += header + "\n";

    for (size_t r = 0; r < table.rowCount(); ++r) {
        bool any = false;
        std::string line;
        for (size_t k = 0; k < cols.size(); ++k) {
            const Column& col = table.column(cols[k]);
            const Cell& cell = col.cells[r];
            const size_t w = widths[k];
            const size_t valueWidth = col.type.kind == ColumnType::Text   ? size_t(col.type.width)
                                      : col.type.kind == ColumnType::Real ? realWidth
                                                                          : 12;
            if (k) line += ' ';
            if (isEmpty(cell)) {
                // code_aster pads '-' as its text format of the column: the real format's leading
                // blanks (1PE12.5) come first.
                const size_t blanks = col.type.kind == ColumnType::Real ? options.realFormat.find('%') : 0;
                if (options.agraf) line += '\\';
                line += std::string(w - valueWidth + blanks, ' ') + ljust("-", valueWidth - blanks);
                continue;
            }
            any = true;
            if (auto* d = std::get_if<double>(&cell)) line += rjust(printfReal(options.realFormat.c_str(), *d), w);
            else if (auto* i = std::get_if<long long>(&cell)) line += rjust(fmt::format("{:12d}", *i), w);
            else line += std::string(w - valueWidth, ' ') + ljust(std::get<std::string>(cell), valueWidth);
        }
        if (any) out += line + "\n";
    }
    out += "\n";
    return out;
}

}  // namespace ma
