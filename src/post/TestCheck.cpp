#include "post/TestCheck.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cfloat>
#include <climits>
#include <cmath>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "post/PostMessages.hpp"
#include "post/PythonFormat.hpp"
#include "post/TestHeader.hpp"

namespace ma {
namespace {

const char* kindName(ColumnType::Kind k) {
    switch (k) {
        case ColumnType::Integer: return "integer (VALE_CALC_I)";
        case ColumnType::Real: return "real (VALE_CALC)";
        case ColumnType::Text: return "text (VALE_CALC_K)";
    }
    return "?";
}

ColumnType::Kind kindOf(const Cell& c) {
    if (std::holds_alternative<long long>(c)) return ColumnType::Integer;
    if (std::holds_alternative<std::string>(c)) return ColumnType::Text;
    return ColumnType::Real;
}

std::string numberText(const Cell& c) {
    if (auto* i = std::get_if<long long>(&c)) return std::to_string(*i);
    return testValueText(std::get<double>(c));
}

// Fortran comparison of one filter against a non-empty cell.
bool fortranMatch(const Cell& cell, const TestFilter& f) {
    const std::string& op = f.comparison;
    if (auto* s = std::get_if<std::string>(&cell)) {
        const std::string a = rstrip(*s), b = rstrip(std::get<std::string>(f.value));
        if (op == "EQ") return a == b;
        if (op == "NE") return a != b;
        throw UserError(
            fmt::format("FILTRE on text column '{}': CRIT_COMP '{}' is not available (EQ or NE)", f.column, op));
    }
    if (auto* i = std::get_if<long long>(&cell)) {
        const long long v = std::get<long long>(f.value);
        if (op == "EQ") return *i == v;
        if (op == "NE") return *i != v;
        if (op == "LT") return *i < v;
        if (op == "GT") return *i > v;
        if (op == "LE") return *i <= v;
        if (op == "GE") return *i >= v;
    } else {
        const double c = std::get<double>(cell), v = std::get<double>(f.value);
        if (op == "EQ") return std::abs(v - c) <= (f.relative ? f.precision * std::abs(c) : f.precision);
        if (op == "NE") return c != v;
        if (op == "LT") return c < v;
        if (op == "GT") return c > v;
        if (op == "LE") return c <= v;
        if (op == "GE") return c >= v;
    }
    throw UserError(fmt::format("FILTRE: unknown CRIT_COMP '{}'", op));
}

double asDouble(const Cell& c) {
    if (auto* i = std::get_if<long long>(&c)) return double(*i);
    return std::get<double>(c);
}

}  // namespace

std::vector<size_t> filterRowsForTest(const Table& table, const std::vector<TestFilter>& filters) {
    std::vector<size_t> rows(table.rowCount());
    for (size_t r = 0; r < rows.size(); ++r) rows[r] = r;
    for (size_t k = 0; k < filters.size(); ++k) {
        const TestFilter& f = filters[k];
        const Column& col = table.column(f.column);
        const std::string& op = f.comparison;
        std::vector<size_t> kept;
        if (op == "VIDE" || op == "NON_VIDE") {
            for (size_t r : rows)
                if (isEmpty(col.cells[r]) == (op == "VIDE")) kept.push_back(r);
        } else if (op == "MAXI" || op == "MINI" || op == "MAXI_ABS" || op == "MINI_ABS") {
            if (col.type.kind == ColumnType::Text)
                throw UserError(fmt::format("FILTRE[{}]: CRIT_COMP '{}' on text column '{}'", k + 1, op, f.column));
            const bool max = op.rfind("MAXI", 0) == 0, useAbs = op.size() > 4;
            std::optional<size_t> best;
            double bestValue = 0;
            for (size_t r : rows) {  // the first row reaching the extremum
                if (isEmpty(col.cells[r])) continue;
                const double v = useAbs ? std::abs(asDouble(col.cells[r])) : asDouble(col.cells[r]);
                if (!best || (max ? v > bestValue : v < bestValue)) {
                    best = r;
                    bestValue = v;
                }
            }
            if (best) kept.push_back(*best);
        } else {
            if (isEmpty(f.value) || kindOf(f.value) != col.type.kind)
                throw UserError(fmt::format("FILTRE[{}]: column '{}' of table {} is {} and needs {}", k + 1, f.column,
                                            table.name, col.type.name(),
                                            col.type.kind == ColumnType::Real      ? "VALE"
                                            : col.type.kind == ColumnType::Integer ? "VALE_I"
                                                                                   : "VALE_K"));
            for (size_t r : rows)
                if (!isEmpty(col.cells[r]) && fortranMatch(col.cells[r], f)) kept.push_back(r);
        }
        if (kept.empty())
            throw UserError(
                fmt::format("FILTRE[{}] (NOM_PARA='{}', CRIT_COMP='{}'{}) leaves no row of table {} "
                            "(code_aster CALCULEL6_7)",
                            k + 1, f.column, op, isEmpty(f.value) ? "" : ", value " + describeCell(f.value),
                            table.name));
        rows = std::move(kept);
    }
    return rows;
}

Cell testedValue(const Table& table, const std::vector<size_t>& rows, const std::string& column, Reduction reduction,
                 ColumnType::Kind expected) {
    if (!table.hasColumn(column))
        throw UserError(fmt::format("NOM_PARA: table {} has no column '{}' (columns: {}) (code_aster CALCULEL6_85)",
                                    table.name, column, fmt::join(table.columnNames(), ", ")));
    const Column& col = table.column(column);
    if (col.type.kind != expected)
        throw UserError(
            fmt::format("NOM_PARA: column '{}' of table {} has type {}, but the expected value is {} "
                        "(code_aster {})",
                        column, table.name, col.type.name(), kindName(expected),
                        reduction == Reduction::None ? "CALCULEL6_8" : "TEST0_7"));
    if (reduction == Reduction::None) {
        std::vector<size_t> withValue;
        for (size_t r : rows)
            if (!isEmpty(col.cells[r])) withValue.push_back(r);
        if (withValue.empty())
            throw UserError(
                fmt::format("no row of table {} has a value in column '{}' (code_aster CALCULEL6_4); add "
                            "a FILTRE or a TYPE_TEST",
                            table.name, column));
        if (withValue.size() > 1)
            throw UserError(
                fmt::format("{} rows of table {} have a value in column '{}', one is needed (code_aster "
                            "CALCULEL6_5); add a FILTRE or a TYPE_TEST",
                            withValue.size(), table.name, column));
        return col.cells[withValue.front()];
    }
    if (col.type.kind == ColumnType::Text)
        throw UserError(fmt::format("TYPE_TEST on text column '{}' of table {}", column, table.name));
    if (col.type.kind == ColumnType::Integer) {
        long long acc = reduction == Reduction::Min ? LLONG_MAX : reduction == Reduction::Max ? LLONG_MIN : 0;
        for (size_t r : rows) {
            if (isEmpty(col.cells[r])) continue;
            const long long v = std::get<long long>(col.cells[r]);
            switch (reduction) {
                case Reduction::Min: acc = std::min(acc, v); break;
                case Reduction::Max: acc = std::max(acc, v); break;
                case Reduction::Sum: acc += v; break;
                case Reduction::SumAbs: acc += v < 0 ? -v : v; break;
                case Reduction::None: break;
            }
        }
        return acc;
    }
    // Start values +-r8maem (DBL_MAX): an all-empty column gives them back, as in code_aster.
    double acc = reduction == Reduction::Min ? DBL_MAX : reduction == Reduction::Max ? -DBL_MAX : 0.0;
    for (size_t r : rows) {
        if (isEmpty(col.cells[r])) continue;
        const double v = std::get<double>(col.cells[r]);
        switch (reduction) {
            case Reduction::Min: acc = std::min(acc, v); break;
            case Reduction::Max: acc = std::max(acc, v); break;
            case Reduction::Sum: acc += v; break;
            case Reduction::SumAbs: acc += std::abs(v); break;
            case Reduction::None: break;
        }
    }
    return acc;
}

std::string sanitizeLegend(const std::string& legend) {
    std::string out = legend.substr(0, 16);
    for (char& c : out)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return out;
}

size_t chooseExpected(const std::vector<Cell>& expected, const Cell& computed) {
    // tresu_print means to keep the closest value but compares every candidate with the distance
    // of the first one (the running minimum is never updated): the last candidate closer than the
    // first wins.
    if (expected.size() <= 1 || kindOf(computed) == ColumnType::Text) return 0;
    auto distance = [&](const Cell& c) { return std::abs(asDouble(c) - asDouble(computed)); };
    const double first = distance(expected[0]);
    size_t chosen = 0;
    for (size_t i = 1; i < expected.size(); ++i)
        if (distance(expected[i]) < first) chosen = i;
    return chosen;
}

CheckOutput formatCheck(const CheckInput& in) {
    CheckOutput out;
    const std::string type16 = ljust(in.reference.substr(0, 16), 16);
    const std::string legend16 = in.legend.substr(0, 16);

    if (kindOf(in.expected) == ColumnType::Text) {  // tresu_str: pure Fortran formats
        auto a24 = [](const std::string& s) { return ljust(s.substr(0, 24), 24); };
        const std::string& ref = std::get<std::string>(in.expected);
        const std::string& val = std::get<std::string>(in.computed);
        const bool ok = rstrip(ref) == rstrip(val);
        out.status = ok ? TestLine::Status::Ok : TestLine::Status::Nook;
        if (in.printLabel)
            out.text += "      " + ljust("REFERENCE", 16) + " " + ljust("LEGENDE", 16) + " " + a24("VALE_REFE") + " " +
                        a24("VALE_CALC") + "\n";
        out.text += std::string(ok ? " OK " : "NOOK") + "  " + type16 + " " + ljust(legend16, 16) + " " + a24(ref) +
                    " " + a24(val) + "\n";
        return out;
    }

    const bool integers = kindOf(in.expected) == ColumnType::Integer;
    double err = 0, ref = 0, val = 0;
    if (integers) {
        const long long r = std::get<long long>(in.expected), v = std::get<long long>(in.computed);
        err = double(r > v ? r - v : v - r);
        ref = double(r);
        val = double(v);
    } else {
        ref = std::get<double>(in.expected);
        val = std::get<double>(in.computed);
        err = std::abs(ref - val);
    }
    const bool ok = in.relative ? err <= std::abs(in.tolerance * ref) : err <= std::abs(in.tolerance * in.order);
    out.status = in.skip ? TestLine::Status::Skip : ok ? TestLine::Status::Ok : TestLine::Status::Nook;

    double shownError = err, shownTolerance = std::abs(in.tolerance * in.order);
    if (in.relative) {
        shownError = ref != 0.0 ? err / std::abs(ref) * 100.0 : (ok ? 0.0 : 999.999999);
        shownTolerance = in.tolerance * 100.0;
    }
    std::string sref = numberText(in.expected), sval = numberText(in.computed);
    const size_t width = std::max({size_t(16), sref.size(), sval.size()}) + 2;
    std::string serr = testValueText(shownError);
    if (serr.size() > 15) {
        serr = printfReal("%13.6e", shownError);
        for (char& c : serr)
            if (c == 'e') c = 'E';
    }
    std::string stol = testValueText(shownTolerance);
    if (in.relative) {
        serr += '%';
        stol += '%';
    }
    out.shownError = serr;
    out.shownTolerance = stol;
    std::string legend = legend16;
    if (in.skip) legend = sref = sval = serr = stol = "-";

    auto line = [&](const std::string& c0, const std::string& c1, const std::string& c2, const std::string& c3,
                    const std::string& c4, const std::string& c5, const std::string& c6) {
        return ljust(c0, 4) + "  " + ljust(c1, 16) + " " + ljust(c2, 16) + " " + ljust(c3, width) + " " +
               ljust(c4, width) + " " + ljust(c5, 16) + " " + ljust(c6, 16) + "\n";
    };
    if (in.order != 1.0) out.text += "      ORDRE DE GRANDEUR : " + ljust(testValueText(in.order), 16) + "\n";
    if (in.printLabel) out.text += line(" ", "REFERENCE", "LEGENDE", "VALE_REFE", "VALE_CALC", "ERREUR", "TOLE");
    const char* diag = in.skip ? "SKIP" : ok ? " OK " : "NOOK";
    out.text += line(diag, in.reference.substr(0, 16), legend, sref, sval, serr, stol);
    return out;
}

Reduction reductionOf(const std::string& typeTest) {
    if (typeTest.empty()) return Reduction::None;
    if (typeTest == "MIN") return Reduction::Min;
    if (typeTest == "MAX") return Reduction::Max;
    if (typeTest == "SOMM") return Reduction::Sum;
    if (typeTest == "SOMM_ABS") return Reduction::SumAbs;
    throw UserError("TYPE_TEST: unknown value '" + typeTest + "' (MIN, MAX, SOMM, SOMM_ABS)");
}

namespace {

Cell absolute(const Cell& c) {
    if (auto* d = std::get_if<double>(&c)) return std::abs(*d);
    if (auto* i = std::get_if<long long>(&c)) return *i < 0 ? -*i : *i;
    return c;
}

std::string describe(const std::string& what, const CheckInput& in, const CheckOutput& out) {
    if (out.status == TestLine::Status::Skip) return what + ": skipped (VALE_CALC is zero, no ORDRE_GRANDEUR)";
    auto trimmed = [](const std::string& t) { return t.substr(std::min(t.find_first_not_of(' '), t.size())); };
    return fmt::format("{}: computed {}, expected {}, error {} {} tolerance {}", what, describeCell(in.computed),
                       describeCell(in.expected), trimmed(out.shownError),
                       out.status == TestLine::Status::Ok ? "<=" : ">", out.shownTolerance);
}

std::string describeTable(const TestTableRequest& rq) {
    std::string what =
        fmt::format("{} {} {}{}{}", rq.where, rq.tableName, rq.column, rq.typeTest.empty() ? "" : " ", rq.typeTest);
    for (const auto& f : rq.filters)
        what += fmt::format(" [{} {}{}{}]", f.column, f.comparison, isEmpty(f.value) ? "" : " ",
                            isEmpty(f.value) ? std::string() : describeCell(f.value));
    return what;
}

}  // namespace

CheckScale checkScale(const TestChecks& rq) {
    if (rq.calc.empty()) throw UserError("VALE_CALC (or VALE_CALC_I, VALE_CALC_K) is needed");
    const bool hasReference = !rq.legacyVale && rq.reference.has_value();
    if (hasReference && rq.refe.size() != rq.calc.size())
        throw UserError(fmt::format("REFERENCE given: VALE_REFE needs as many values as VALE_CALC ({} and {})",
                                    rq.refe.size(), rq.calc.size()));
    CheckScale scale;
    if (!rq.legacyVale && kindOf(rq.calc.front()) == ColumnType::Real &&
        std::abs(std::get<double>(rq.calc.front())) <= DBL_EPSILON) {
        if (rq.orderOfMagnitude) scale.order = *rq.orderOfMagnitude;
        else scale.skip = true;
    }
    if (scale.skip && !hasReference) msg().alarm(TEST0_11);
    return scale;
}

std::vector<TestLine> runChecks(const TestChecks& rq, const CheckScale& scale, const Cell& computed, bool closest,
                                const std::string& what) {
    const std::string legend = sanitizeLegend(rq.legend.value_or("XXXX"));
    std::vector<TestLine> recorded;
    auto check = [&](const std::string& type, const std::vector<Cell>& expectedList, double tolerance, bool label,
                     bool skipLine, double og) {
        const size_t pick = closest ? chooseExpected(expectedList, computed) : 0;
        CheckInput in;
        in.reference = type;
        in.legend = legend;
        in.printLabel = label;
        in.skip = skipLine;
        in.relative = rq.relative;
        in.tolerance = tolerance;
        in.order = og;
        in.expected = expectedList[pick];
        in.computed = computed;
        if (kindOf(in.expected) == ColumnType::Integer && kindOf(in.computed) == ColumnType::Real)
            in.expected = asDouble(in.expected);  // an integer literal given for a real value (§1.8)
        if (kindOf(in.expected) != kindOf(in.computed))
            throw UserError(fmt::format("the expected value {} and the tested value {} have different types",
                                        describeCell(in.expected), describeCell(in.computed)));
        if (rq.absoluteValues) {
            in.expected = absolute(in.expected);
            in.computed = absolute(in.computed);
        }
        CheckOutput out = formatCheck(in);
        if (skipLine) msg().alarm(TEST0_12);
        msg().result(out.text);
        TestLine line{type, out.status, describe(what, in, out)};
        testReport().add(line);
        recorded.push_back(line);
    };

    if (rq.legacyVale) {
        // VALE= (before 2012, §1.8): one check against VALE, tolerance PRECISION.
        check(rq.reference.value_or("NON_REGRESSION"), rq.calc, rq.precision, true, false, 1.0);
    } else {
        check("NON_REGRESSION", rq.calc, rq.machineTolerance, true, scale.skip, scale.order);
        if (rq.reference) check(*rq.reference, rq.refe, rq.precision, false, false, 1.0);
    }
    return recorded;
}

std::vector<TestLine> runTestTable(const Table& table, const TestTableRequest& rq) {
    if (rq.calc.empty()) throw UserError("TEST_TABLE needs VALE_CALC (or VALE_CALC_I, VALE_CALC_K)");
    msg().result("\n" + std::string(80, '-') + "\n");
    const CheckScale scale = checkScale(rq);

    TestHeader header("TABLE", rq.tableName);
    header.add("NOM_PARA", rq.column);
    if (!rq.typeTest.empty()) header.add("TYPE_TEST", rq.typeTest);
    msg().result(header.text());

    const Reduction reduction = reductionOf(rq.typeTest);
    const std::vector<size_t> rows = filterRowsForTest(table, rq.filters);
    const Cell computed = testedValue(table, rows, rq.column, reduction, kindOf(rq.calc.front()));
    auto recorded = runChecks(rq, scale, computed, reduction == Reduction::None, describeTable(rq));
    msg().result("  \n");
    return recorded;
}

}  // namespace ma
