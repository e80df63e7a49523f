// TEST_TABLE: pass/fail rules and the exact report text of commands_spec.md §1.5.6.
#include <gtest/gtest.h>

#include <cfloat>
#include <sstream>

#include "core/Messages.hpp"
#include "core/TestReport.hpp"
#include "parser/Catalog.hpp"
#include "parser/CommandRegistry.hpp"
#include "post/TestCheck.hpp"

using namespace ma;

namespace {

class TestTableFixture : public ::testing::Test {
protected:
    void SetUp() override {
        msg().setEcho(false);
        msg().reset();
        testReport().reset();
    }

    // A table named `name` with one real column `column` holding `values`.
    static std::shared_ptr<Table> realTable(const std::string& name, const std::string& column,
                                            const std::vector<double>& values) {
        auto t = std::make_shared<Table>();
        t->name = name;
        t->addColumn(column, ColumnType::real());
        for (double v : values) t->set(t->addRow(), 0, v);
        return t;
    }

    // Runs the TEST_TABLE command with the given keywords (TABLE added).
    static void run(const std::shared_ptr<Table>& table, KeywordSet kw) {
        kw.setValues("TABLE", {ConceptPtr(table)});
        CommandContext ctx;
        ctx.command = "TEST_TABLE";
        ctx.line = 42;
        const CommandFunction* fn = CommandRegistry::instance().find("TEST_TABLE");
        ASSERT_NE(fn, nullptr);
        (*fn)(validateKeywords("TEST_TABLE", kw), ctx);
    }

    // The result text with each line's trailing blanks removed (the spec's examples (a)-(d) are
    // printed that way) and without the block separator.
    static std::string stripped(const std::string& text) {
        std::istringstream in(text);
        std::string line, out;
        while (std::getline(in, line)) {
            while (!line.empty() && line.back() == ' ') line.pop_back();
            out += line + "\n";
        }
        return out;
    }
};

KeywordSet keywords(std::initializer_list<std::pair<const char*, KeywordValue>> values) {
    KeywordSet kw;
    for (const auto& [k, v] : values) kw.setValues(k, {v});
    return kw;
}

}  // namespace

// §1.5.6, the requested example, byte for byte (trailing blanks included).
TEST_F(TestTableFixture, ReconstructedExampleExact) {
    auto t = realTable("DEPZON_1", "DX", {-0.25, 0.5, -0.1});
    run(t, keywords({{"NOM_PARA", std::string("DX")},
                     {"TYPE_TEST", std::string("MIN")},
                     {"VALE_CALC", -0.25},
                     {"VALE_REFE", -0.25},
                     {"CRITERE", std::string("RELATIF")},
                     {"PRECISION", 1e-13},
                     {"REFERENCE", std::string("ANALYTIQUE")}}));
    const std::string expected =
        "\n"
        "--------------------------------------------------------------------------------\n"
        " ---- TABLE            NOM_PARA         TYPE_TEST\n"
        "      DEPZON_1         DX               MIN\n"
        "      REFERENCE        LEGENDE          VALE_REFE          VALE_CALC          ERREUR           TOLE           "
        " \n"
        " OK   NON_REGRESSION   XXXX             -0.25              -0.25              0.0%             "
        "9.999999999999999E-05%\n"
        " OK   ANALYTIQUE       XXXX             -0.25              -0.25              0.0%             "
        "1.0000000000000001E-11%\n"
        "  \n";
    EXPECT_EQ(msg().resuText(), expected);
    ASSERT_EQ(testReport().lines().size(), 2u);
    EXPECT_EQ(testReport().lines()[0].kind, "NON_REGRESSION");
    EXPECT_EQ(testReport().lines()[0].status, TestLine::Status::Ok);
    EXPECT_EQ(testReport().lines()[1].kind, "ANALYTIQUE");
    EXPECT_EQ(testReport().lines()[1].status, TestLine::Status::Ok);
    EXPECT_EQ(msg().alarmCount(), 0);
}

// §1.5.6 (a): ABSOLU, the reference error longer than 15 characters goes through %13.6E.
TEST_F(TestTableFixture, AbsoluteWithLongError) {
    auto t = realTable("DEPZON_1", "DY", {2.6562953225895E-17, -1.0347625534202E-15, 0.0});
    run(t, keywords({{"NOM_PARA", std::string("DY")},
                     {"TYPE_TEST", std::string("MIN")},
                     {"VALE_CALC", -1.0347625534202E-15},
                     {"VALE_REFE", 0.0},
                     {"CRITERE", std::string("ABSOLU")},
                     {"PRECISION", 1e-13},
                     {"REFERENCE", std::string("ANALYTIQUE")}}));
    const std::string expected =
        "\n"
        "--------------------------------------------------------------------------------\n"
        " ---- TABLE            NOM_PARA         TYPE_TEST\n"
        "      DEPZON_1         DY               MIN\n"
        "      REFERENCE        LEGENDE          VALE_REFE              VALE_CALC              ERREUR           TOLE\n"
        " OK   NON_REGRESSION   XXXX             -1.0347625534202E-15   -1.0347625534202E-15   0.0              1E-06\n"
        " OK   ANALYTIQUE       XXXX             0.0                    -1.0347625534202E-15    1.034763E-15    1E-13\n"
        "\n";
    EXPECT_EQ(stripped(msg().resuText()), expected);
    EXPECT_EQ(testReport().nookCount(), 0);
}

// §1.5.6 (b): |VALE_CALC| <= DBL_EPSILON without ORDRE_GRANDEUR: SKIP + alarm TEST0_12 before the
// label line; the reference line is still evaluated.
TEST_F(TestTableFixture, SkipNearZeroWithAlarm) {
    auto t = realTable("DEPZON_1", "DY", {2.6562953225895E-17, -1.0347625534202E-15});
    run(t, keywords({{"NOM_PARA", std::string("DY")},
                     {"TYPE_TEST", std::string("MAX")},
                     {"VALE_CALC", 2.6562953225895E-17},
                     {"VALE_REFE", 0.0},
                     {"CRITERE", std::string("ABSOLU")},
                     {"PRECISION", 1e-13},
                     {"REFERENCE", std::string("ANALYTIQUE")}}));
    const std::string expected =
        "\n"
        "--------------------------------------------------------------------------------\n"
        " ---- TABLE            NOM_PARA         TYPE_TEST\n"
        "      DEPZON_1         DY               MAX\n"
        "      REFERENCE        LEGENDE          VALE_REFE             VALE_CALC             ERREUR           TOLE\n"
        "SKIP  NON_REGRESSION   -                -                     -                     -                -\n"
        " OK   ANALYTIQUE       XXXX             0.0                   2.6562953225895E-17    2.656295E-17    1E-13\n"
        "\n";
    EXPECT_EQ(stripped(msg().resuText()), expected);
    EXPECT_EQ(msg().alarmCount(), 1);
    const std::string& mess = msg().messText();
    const size_t alarm = mess.find("<A> <TEST0_12>");
    ASSERT_NE(alarm, std::string::npos);
    EXPECT_LT(alarm, mess.find("      REFERENCE        LEGENDE"));
    EXPECT_GT(alarm, mess.find("      DEPZON_1"));
    EXPECT_EQ(mess.find("TEST0_11"), std::string::npos);  // a reference check exists
    ASSERT_EQ(testReport().lines().size(), 2u);
    EXPECT_EQ(testReport().lines()[0].status, TestLine::Status::Skip);
    EXPECT_EQ(testReport().lines()[1].status, TestLine::Status::Ok);
}

// §1.5.6 (c): no TYPE_TEST, FILTRE on a text column, VALE_CALC=0 skipped, RELATIF zero reference
// passes because the value is exactly 0; PRECISION defaults to 1e-3 (0.1%).
TEST_F(TestTableFixture, FilterZeroReferenceExactZeroPasses) {
    auto t = std::make_shared<Table>();
    t->name = "tabNRJ";
    t->addColumn("GROUP_MA", ColumnType::text(8));
    t->addColumn("DIFFERENCE", ColumnType::real());
    t->addColumn("REFERENCE", ColumnType::real());
    for (const char* g : {"SURF", "TOTAL"}) {
        const size_t r = t->addRow();
        t->set(r, 0, std::string(g));
        t->set(r, 1, 1.0);
        t->set(r, 2, 0.0);
    }
    KeywordSet kw = keywords({{"NOM_PARA", std::string("REFERENCE")},
                              {"VALE_CALC", 0.0},
                              {"VALE_REFE", 0.0},
                              {"CRITERE", std::string("RELATIF")},
                              {"REFERENCE", std::string("ANALYTIQUE")}});
    KeywordSet& f = kw.addOccurrence("FILTRE");
    f.setValues("NOM_PARA", {std::string("GROUP_MA")});
    f.setValues("VALE_K", {std::string("TOTAL")});
    run(t, kw);
    const std::string expected =
        "\n"
        "--------------------------------------------------------------------------------\n"
        " ---- TABLE            NOM_PARA\n"
        "      tabNRJ           REFERENCE\n"
        "      REFERENCE        LEGENDE          VALE_REFE          VALE_CALC          ERREUR           TOLE\n"
        "SKIP  NON_REGRESSION   -                -                  -                  -                -\n"
        " OK   ANALYTIQUE       XXXX             0.0                0.0                0.0%             0.1%\n"
        "\n";
    EXPECT_EQ(stripped(msg().resuText()), expected);
}

// §1.5.6 (d): a relative non-regression miss and a relative check against a zero reference.
TEST_F(TestTableFixture, FailingLinesExact) {
    CheckInput a;
    a.expected = 0.991602252648;
    a.computed = 0.9921;
    CheckOutput outA = formatCheck(a);
    EXPECT_EQ(outA.status, TestLine::Status::Nook);
    EXPECT_EQ(outA.text,
              "NOOK  NON_REGRESSION   XXXX             0.991602252648     0.9921              5.019627E-02%   "
              "9.999999999999999E-05%\n");
    CheckInput b;
    b.reference = "ANALYTIQUE";
    b.tolerance = 1e-3;
    b.expected = 0.0;
    b.computed = 1e-300;
    CheckOutput outB = formatCheck(b);
    EXPECT_EQ(outB.status, TestLine::Status::Nook);
    EXPECT_EQ(outB.text,
              "NOOK  ANALYTIQUE       XXXX             0.0                1E-300             999.999999%      0.1%"
              "            \n");
}

TEST_F(TestTableFixture, RelativeRule) {
    CheckInput in;
    in.tolerance = 1e-3;
    in.expected = 100.0;
    in.computed = 100.1;  // error 0.1 <= 1e-3*100
    EXPECT_EQ(formatCheck(in).status, TestLine::Status::Ok);
    in.computed = 100.11;
    EXPECT_EQ(formatCheck(in).status, TestLine::Status::Nook);
    in.expected = -100.0;  // |tol * ref|
    in.computed = -100.05;
    EXPECT_EQ(formatCheck(in).status, TestLine::Status::Ok);
    // zero reference: OK only for an exact zero, and the error is shown as 0.0%
    in.expected = 0.0;
    in.computed = 0.0;
    CheckOutput out = formatCheck(in);
    EXPECT_EQ(out.status, TestLine::Status::Ok);
    EXPECT_EQ(out.shownError, "0.0%");
    in.computed = 1e-200;
    out = formatCheck(in);
    EXPECT_EQ(out.status, TestLine::Status::Nook);
    EXPECT_EQ(out.shownError, "999.999999%");
}

TEST_F(TestTableFixture, AbsoluteRuleAndOrderOfMagnitude) {
    CheckInput in;
    in.relative = false;
    in.tolerance = 1e-6;
    in.expected = 5.0;
    in.computed = 5.0 + 0.9e-6;
    EXPECT_EQ(formatCheck(in).status, TestLine::Status::Ok);
    in.computed = 5.0 + 1.1e-6;
    EXPECT_EQ(formatCheck(in).status, TestLine::Status::Nook);
    // ORDRE_GRANDEUR scales the absolute tolerance and is printed before the label line
    in.order = 10.0;
    in.printLabel = true;
    CheckOutput out = formatCheck(in);
    EXPECT_EQ(out.status, TestLine::Status::Ok);
    EXPECT_EQ(out.shownTolerance, "9.999999999999999E-06");  // Python: 1e-6 * 10
    EXPECT_EQ(out.text.substr(0, out.text.find('\n')), "      ORDRE DE GRANDEUR : 10.0            ");
    // with RELATIF the order of magnitude changes nothing
    in.relative = true;
    in.computed = 5.0 + 1.1e-5;
    EXPECT_EQ(formatCheck(in).status, TestLine::Status::Nook);
}

// Without REFERENCE and with a null VALE_CALC: TEST0_11 then TEST0_12, one SKIP line.
TEST_F(TestTableFixture, SkipWithoutReferenceRaisesBothAlarms) {
    auto t = realTable("T", "V", {1e-17});
    run(t, keywords({{"NOM_PARA", std::string("V")}, {"VALE_CALC", 1e-17}}));
    EXPECT_EQ(msg().alarmCount(), 2);
    EXPECT_LT(msg().messText().find("TEST0_11"), msg().messText().find("TEST0_12"));
    ASSERT_EQ(testReport().lines().size(), 1u);
    EXPECT_EQ(testReport().lines()[0].status, TestLine::Status::Skip);
    EXPECT_NE(msg().resuText().find("SKIP  NON_REGRESSION   -                -"), std::string::npos);
}

// DBL_EPSILON itself is skipped; just above it is tested.
TEST_F(TestTableFixture, SkipThresholdIsDblEpsilon) {
    auto t = realTable("T", "V", {DBL_EPSILON});
    run(t, keywords({{"NOM_PARA", std::string("V")}, {"VALE_CALC", DBL_EPSILON}}));
    EXPECT_EQ(testReport().lines().back().status, TestLine::Status::Skip);
    const double above = 2.3e-16;
    auto t2 = realTable("T", "V", {above});
    run(t2, keywords({{"NOM_PARA", std::string("V")}, {"VALE_CALC", above}}));
    EXPECT_EQ(testReport().lines().back().status, TestLine::Status::Ok);
}

// ORDRE_GRANDEUR with a null VALE_CALC: the check is made (ABSOLU, tolerance TOLE_MACHINE * og).
TEST_F(TestTableFixture, OrderOfMagnitudeMakesNullValueTestable) {
    auto t = realTable("T", "V", {3e-7});
    run(t, keywords({{"NOM_PARA", std::string("V")},
                     {"VALE_CALC", 0.0},
                     {"ORDRE_GRANDEUR", 1.0},
                     {"CRITERE", std::string("ABSOLU")}}));
    EXPECT_EQ(testReport().lines().back().status, TestLine::Status::Ok);
    EXPECT_EQ(msg().alarmCount(), 0);
    run(t, keywords({{"NOM_PARA", std::string("V")},
                     {"VALE_CALC", 0.0},
                     {"ORDRE_GRANDEUR", 0.1},
                     {"CRITERE", std::string("ABSOLU")}}));
    EXPECT_EQ(testReport().lines().back().status, TestLine::Status::Nook);
    EXPECT_NE(msg().resuText().find("      ORDRE DE GRANDEUR : 0.1             \n"), std::string::npos);
}

TEST_F(TestTableFixture, ValeAbs) {
    auto t = realTable("T", "V", {-2.0});
    run(t, keywords({{"NOM_PARA", std::string("V")}, {"VALE_CALC", 2.0}, {"VALE_ABS", std::string("OUI")}}));
    EXPECT_EQ(testReport().lines().back().status, TestLine::Status::Ok);
    EXPECT_NE(msg().resuText().find(" OK   NON_REGRESSION   XXXX             2.0                2.0 "),
              std::string::npos);
    run(t, keywords({{"NOM_PARA", std::string("V")}, {"VALE_CALC", 2.0}}));
    EXPECT_EQ(testReport().lines().back().status, TestLine::Status::Nook);
}

// Legacy VALE= (§1.8): one line labelled REFERENCE, tolerance PRECISION, label line before it.
TEST_F(TestTableFixture, LegacyValeSingleReferenceLine) {
    auto t = realTable("DEPZON_1", "DX", {-0.25, -0.2500001});
    run(t, keywords({{"NOM_PARA", std::string("DX")},
                     {"TYPE_TEST", std::string("MIN")},
                     {"VALE", -0.25},
                     {"PRECISION", 1e-3},
                     {"REFERENCE", std::string("ANALYTIQUE")}}));
    ASSERT_EQ(testReport().lines().size(), 1u);
    EXPECT_EQ(testReport().lines()[0].kind, "ANALYTIQUE");
    EXPECT_EQ(testReport().lines()[0].status, TestLine::Status::Ok);
    const std::string expected =
        "\n"
        "--------------------------------------------------------------------------------\n"
        " ---- TABLE            NOM_PARA         TYPE_TEST\n"
        "      DEPZON_1         DX               MIN\n"
        "      REFERENCE        LEGENDE          VALE_REFE          VALE_CALC          ERREUR           TOLE\n"
        " OK   ANALYTIQUE       XXXX             -0.25              -0.2500001          4.000000E-05%   0.1%\n"
        "\n";
    EXPECT_EQ(stripped(msg().resuText()), expected);
    // without REFERENCE the line is NON_REGRESSION, still with PRECISION (default 1e-3)
    run(t, keywords({{"NOM_PARA", std::string("DX")}, {"TYPE_TEST", std::string("MAX")}, {"VALE", -0.2501}}));
    EXPECT_EQ(testReport().lines().back().kind, "NON_REGRESSION");
    EXPECT_EQ(testReport().lines().back().status, TestLine::Status::Ok);
}

TEST_F(TestTableFixture, Reductions) {
    auto t = realTable("T", "V", {1.5, -4.0, 2.5});
    t->set(t->addRow(), 0, Cell{});  // an empty cell is ignored
    std::vector<size_t> rows{0, 1, 2, 3};
    EXPECT_EQ(std::get<double>(testedValue(*t, rows, "V", Reduction::Min, ColumnType::Real)), -4.0);
    EXPECT_EQ(std::get<double>(testedValue(*t, rows, "V", Reduction::Max, ColumnType::Real)), 2.5);
    EXPECT_EQ(std::get<double>(testedValue(*t, rows, "V", Reduction::Sum, ColumnType::Real)), 0.0);
    EXPECT_EQ(std::get<double>(testedValue(*t, rows, "V", Reduction::SumAbs, ColumnType::Real)), 8.0);
    // an all-empty selection gives code_aster's start values
    EXPECT_EQ(std::get<double>(testedValue(*t, {3}, "V", Reduction::Min, ColumnType::Real)), DBL_MAX);
    EXPECT_EQ(std::get<double>(testedValue(*t, {3}, "V", Reduction::Max, ColumnType::Real)), -DBL_MAX);
    // through the command: SOMM and SOMM_ABS
    run(t, keywords({{"NOM_PARA", std::string("V")}, {"TYPE_TEST", std::string("SOMM_ABS")}, {"VALE_CALC", 8.0}}));
    EXPECT_EQ(testReport().lines().back().status, TestLine::Status::Ok);
    run(t, keywords({{"NOM_PARA", std::string("V")}, {"TYPE_TEST", std::string("SOMM")}, {"VALE_CALC", 1.0}}));
    EXPECT_EQ(testReport().lines().back().status, TestLine::Status::Nook);
}

TEST_F(TestTableFixture, IntegerAndTextValues) {
    auto t = std::make_shared<Table>();
    t->name = "T";
    t->addColumn("NUME_ORDRE", ColumnType::integer());
    t->addColumn("NOEUD", ColumnType::text(8));
    const size_t r = t->addRow();
    t->set(r, 0, 3LL);
    t->set(r, 1, std::string("N12"));
    run(t, keywords({{"NOM_PARA", std::string("NUME_ORDRE")}, {"VALE_CALC_I", 3LL}}));
    EXPECT_EQ(testReport().lines().back().status, TestLine::Status::Ok);
    EXPECT_NE(msg().resuText().find(
                  " OK   NON_REGRESSION   XXXX             3                  3                  0.0%"),
              std::string::npos);
    run(t, keywords({{"NOM_PARA", std::string("NOEUD")}, {"VALE_CALC_K", std::string("N12")}}));
    EXPECT_EQ(testReport().lines().back().status, TestLine::Status::Ok);
    EXPECT_NE(msg().resuText().find(" OK   NON_REGRESSION   XXXX             N12                      N12"),
              std::string::npos);
    run(t, keywords({{"NOM_PARA", std::string("NOEUD")}, {"VALE_CALC_K", std::string("N13")}}));
    EXPECT_EQ(testReport().lines().back().status, TestLine::Status::Nook);
}

TEST_F(TestTableFixture, LegendIsSanitized) {
    EXPECT_EQ(sanitizeLegend("DX zone-1 (max) very long"), "DX_zone_1__max__");
    auto t = realTable("T", "V", {1.0});
    run(t, keywords({{"NOM_PARA", std::string("V")}, {"VALE_CALC", 1.0}, {"LEGENDE", std::string("a b")}}));
    EXPECT_NE(msg().resuText().find(" OK   NON_REGRESSION   a_b              1.0"), std::string::npos);
}

// Fortran filters: relative EQ is relative to the cell; empty cells never match.
TEST_F(TestTableFixture, FortranFilters) {
    auto t = std::make_shared<Table>();
    t->name = "T";
    t->addColumn("X", ColumnType::real());
    t->addColumn("V", ColumnType::real());
    for (auto [x, v] : std::vector<std::pair<double, double>>{{1000.0, 1}, {1000.9, 2}, {2.0, 3}, {-5.0, 4}}) {
        const size_t r = t->addRow();
        t->set(r, 0, x);
        t->set(r, 1, v);
    }
    t->addRow();  // empty row
    t->set(4, 1, 5.0);
    // |1001.0005 - cell| <= 1e-3 * |cell|: 1000 fails (1.0005 > 1.0) although it would pass relative
    // to the given value (1.0005 <= 1.0010005); 1000.9 passes
    TestFilter eq{"X", "EQ", 1001.0005, true, 1e-3};
    auto rows = filterRowsForTest(*t, {eq});
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0], 1u);
    TestFilter absEq{"X", "EQ", 1000.5, false, 0.5};
    EXPECT_EQ(filterRowsForTest(*t, {absEq}).size(), 2u);
    TestFilter ne{"X", "NE", 2.0};
    EXPECT_EQ(filterRowsForTest(*t, {ne}), (std::vector<size_t>{0, 1, 3}));  // the empty cell is not kept
    TestFilter lt{"X", "LT", 2.0};
    EXPECT_EQ(filterRowsForTest(*t, {lt}), (std::vector<size_t>{3}));
    TestFilter vide{"X", "VIDE", Cell{}};
    EXPECT_EQ(filterRowsForTest(*t, {vide}), (std::vector<size_t>{4}));
    TestFilter maxiAbs{"X", "MAXI_ABS", Cell{}};
    EXPECT_EQ(filterRowsForTest(*t, {maxiAbs}), (std::vector<size_t>{1}));
    TestFilter mini{"X", "MINI", Cell{}};
    EXPECT_EQ(filterRowsForTest(*t, {mini}), (std::vector<size_t>{3}));
    // in sequence
    TestFilter gt{"X", "GT", 0.0};
    EXPECT_EQ(filterRowsForTest(*t, {gt, TestFilter{"X", "MINI", Cell{}}}), (std::vector<size_t>{2}));
    // no row left: error
    TestFilter none{"X", "GT", 1e9};
    EXPECT_THROW(filterRowsForTest(*t, {none}), UserError);
    // wrong value type for the column
    TestFilter wrongType{"X", "EQ", 3LL};
    EXPECT_THROW(filterRowsForTest(*t, {wrongType}), UserError);
}

TEST_F(TestTableFixture, Errors) {
    auto t = realTable("T", "V", {1.0, 2.0});
    // missing column
    EXPECT_THROW(run(t,
                     keywords({{"NOM_PARA", std::string("W")}, {"TYPE_TEST", std::string("MAX")}, {"VALE_CALC", 1.0}})),
                 UserError);
    // type mismatch: integer expected value on a real column
    EXPECT_THROW(run(t, keywords(
                            {{"NOM_PARA", std::string("V")}, {"TYPE_TEST", std::string("MAX")}, {"VALE_CALC_I", 2LL}})),
                 UserError);
    // several rows without TYPE_TEST
    EXPECT_THROW(run(t, keywords({{"NOM_PARA", std::string("V")}, {"VALE_CALC", 1.0}})), UserError);
    // no row with a value
    auto empty = realTable("E", "V", {});
    empty->addColumn("K", ColumnType::text(8));
    empty->set(empty->addRow(), 1, std::string("A"));
    EXPECT_THROW(run(empty, keywords({{"NOM_PARA", std::string("V")}, {"VALE_CALC", 1.0}})), UserError);
    // REFERENCE without VALE_REFE
    EXPECT_THROW(run(t, keywords({{"NOM_PARA", std::string("V")},
                                  {"TYPE_TEST", std::string("MAX")},
                                  {"VALE_CALC", 2.0},
                                  {"REFERENCE", std::string("ANALYTIQUE")}})),
                 UserError);
}

TEST_F(TestTableFixture, SeveralExpectedValuesQuirk) {
    // distance to the first candidate is the running bound: the last closer one wins
    std::vector<Cell> expected{10.0, 2.0, 1.5, 3.0};
    EXPECT_EQ(chooseExpected(expected, Cell{1.0}), 3u);
    EXPECT_EQ(chooseExpected({1.0, 5.0}, Cell{1.0}), 0u);
}

TEST_F(TestTableFixture, NookIsRecordedWithDescription) {
    auto t = realTable("DEPZON_1", "DX", {-0.25});
    run(t, keywords({{"NOM_PARA", std::string("DX")},
                     {"TYPE_TEST", std::string("MIN")},
                     {"VALE_CALC", -0.25},
                     {"VALE_REFE", -0.2501},
                     {"PRECISION", 1e-6},
                     {"REFERENCE", std::string("ANALYTIQUE")}}));
    ASSERT_EQ(testReport().nookCount(), 1);
    const TestLine& l = testReport().lines()[1];
    EXPECT_EQ(l.kind, "ANALYTIQUE");
    EXPECT_NE(l.description.find("line 42"), std::string::npos);
    EXPECT_NE(l.description.find("DEPZON_1 DX MIN"), std::string::npos);
    EXPECT_NE(testReport().summary().find("NOOK"), std::string::npos);
}
