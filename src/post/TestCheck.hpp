#pragma once
// TEST_TABLE's checks (commands_spec.md §1): Fortran-side value selection and filters, code_aster's
// pass/fail rules, the exact text of the report, and the run's test registry.
#include <optional>
#include <string>
#include <vector>

#include "core/TestReport.hpp"
#include "post/Table.hpp"

namespace ma {

// One FILTRE occurrence of TEST_TABLE (Fortran semantics, §1.3: relative EQ is relative to the
// cell value; strings compare with trailing blanks ignored; empty cells never match but VIDE).
struct TestFilter {
    std::string column;
    std::string comparison = "EQ";  // EQ NE LT GT LE GE VIDE NON_VIDE MAXI MAXI_ABS MINI MINI_ABS
    Cell value;                     // VALE (double) / VALE_I (long long) / VALE_K (string)
    bool relative = true;
    double precision = 1.0e-3;
};

// Rows surviving the filters applied in sequence; UserError (CALCULEL6_7) when one leaves none.
std::vector<size_t> filterRowsForTest(const Table& table, const std::vector<TestFilter>& filters);

enum class Reduction { None, Min, Max, Sum, SumAbs };

// The tested value: the single row with a value (None), or the reduction of the column over the
// rows with a value. `expected` is the kind of VALE_CALC*: it must match the column type.
Cell testedValue(const Table& table, const std::vector<size_t>& rows, const std::string& column, Reduction reduction,
                 ColumnType::Kind expected);

// One printed check line (§1.5.3).
struct CheckInput {
    std::string reference = "NON_REGRESSION";  // printed type: NON_REGRESSION, ANALYTIQUE...
    std::string legend = "XXXX";
    bool printLabel = false;  // column-label line before it (line A)
    bool skip = false;
    bool relative = true;
    double tolerance = 1.0e-6;
    double order = 1.0;       // ORDRE_GRANDEUR (line A only)
    Cell expected, computed;  // both double, or both long long, or both string
};
struct CheckOutput {
    TestLine::Status status = TestLine::Status::Ok;
    std::string text;        // the line(s), each ending with '\n'
    std::string shownError;  // error and tolerance as printed (for the registry)
    std::string shownTolerance;
};
CheckOutput formatCheck(const CheckInput& in);

// LEGENDE as printed: 16 characters at most, anything outside [A-Za-z0-9] becomes '_'.
std::string sanitizeLegend(const std::string& legend);

// Among several expected values, the one tresu_print keeps (§1.3, including its quirk).
size_t chooseExpected(const std::vector<Cell>& expected, const Cell& computed);

// The checks of one TEST_* occurrence (TEST_TABLE, TEST_RESU): the expected values and how they are
// compared, whatever the tested value is.
struct TestChecks {
    std::vector<Cell> calc;                  // VALE_CALC / _I / _K (or legacy VALE)
    std::vector<Cell> refe;                  // VALE_REFE / _I / _K
    bool legacyVale = false;                 // VALE= syntax (§1.8): one check against it, tolerance PRECISION
    std::optional<std::string> reference;    // REFERENCE
    std::optional<double> orderOfMagnitude;  // ORDRE_GRANDEUR
    std::optional<std::string> legend;       // LEGENDE
    bool relative = true;                    // CRITERE
    bool absoluteValues = false;             // VALE_ABS='OUI'
    double machineTolerance = 1.0e-6;        // TOLE_MACHINE
    double precision = 1.0e-3;               // PRECISION
    std::string where;                       // "TEST_TABLE (.comm line 123)" for the registry descriptions
};

// A null VALE_CALC: the NON_REGRESSION check is scaled by ORDRE_GRANDEUR, or skipped.
struct CheckScale {
    double order = 1.0;
    bool skip = false;
};
// Validates the expected values (as many VALE_REFE as VALE_CALC) and emits TEST0_11 for a skipped
// non-regression check without reference, before the header is printed (as code_aster does).
CheckScale checkScale(const TestChecks& checks);

// Prints the NON_REGRESSION line and the reference line of one tested value to the result file and
// records them in testReport(), described as `what`. `closest`: among several expected values, the
// one tresu_print keeps (chooseExpected); otherwise the first.
std::vector<TestLine> runChecks(const TestChecks& checks, const CheckScale& scale, const Cell& computed, bool closest,
                                const std::string& what);

// A whole TEST_TABLE call.
struct TestTableRequest : TestChecks {
    std::string tableName;  // printed in the header (legacy naming: DEPZON_1)
    std::string column;     // NOM_PARA
    std::string typeTest;   // MIN MAX SOMM SOMM_ABS, or empty
    std::vector<TestFilter> filters;
};

// The TYPE_TEST keyword's reduction (None for an empty text).
Reduction reductionOf(const std::string& typeTest);

// Runs the checks, writes the report block to the result file (msg().result), emits the TEST0_11 /
// TEST0_12 alarms and records every line in testReport(). Returns the recorded lines.
std::vector<TestLine> runTestTable(const Table& table, const TestTableRequest& request);

}  // namespace ma
