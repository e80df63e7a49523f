// CALC_TABLE operations (commands_spec.md §3) and IMPR_TABLE's TABLEAU layout (§4.2).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "core/FortranFormat.hpp"
#include "core/Function.hpp"
#include "core/Messages.hpp"
#include "core/Units.hpp"
#include "parser/Catalog.hpp"
#include "parser/CommandRegistry.hpp"
#include "post/TableOperations.hpp"
#include "post/TablePrinter.hpp"

using namespace ma;

namespace {

// A FORMULE stand-in: a C++ lambda; counts batch calls.
class LambdaFunction : public Function {
public:
    LambdaFunction(std::vector<std::string> params, std::function<double(std::span<const double>)> f)
        : params_(std::move(params)), f_(std::move(f)) {}
    std::string typeName() const override { return "formule"; }
    const std::vector<std::string>& parameters() const override { return params_; }
    double evaluate(std::span<const double> args) const override { return f_(args); }
    std::vector<double> evaluateMany(std::span<const double> args, size_t npoints) const override {
        ++batches;
        return Function::evaluateMany(args, npoints);
    }
    mutable int batches = 0;

private:
    std::vector<std::string> params_;
    std::function<double(std::span<const double>)> f_;
};

// NOEUD/COOR_X/COOR_Y/DX/DY like the DEP tables of ssnv511.
std::shared_ptr<Table> depTable() {
    auto t = std::make_shared<Table>();
    t->name = "DEP";
    t->title = {"TITLE OF DEP"};
    t->addColumn("INTITULE", ColumnType::text(16));
    t->addColumn("NOEUD", ColumnType::text(8));
    t->addColumn("COOR_X", ColumnType::real());
    t->addColumn("COOR_Y", ColumnType::real());
    t->addColumn("DX", ColumnType::real());
    t->addColumn("DY", ColumnType::real());
    struct Row {
        const char* node;
        double x, y, dx, dy;
    };
    for (const Row& r : std::vector<Row>{{"NP000001", -2.0, 0.0, -0.25, 0.0},
                                         {"NM000002", -2.0, 0.0, -0.5, 0.0},
                                         {"NP000003", 3.0, 0.0, 0.75, 1e-17},
                                         {"NM000004", 3.0, 0.0, 1.0, -1e-17},
                                         {"XNPQ", 0.0, 4.0, 0.1, 0.2}}) {
        const size_t i = t->addRow();
        t->set(i, "INTITULE", std::string("DEPLE"));
        t->set(i, "NOEUD", std::string(r.node));
        t->set(i, "COOR_X", r.x);
        t->set(i, "COOR_Y", r.y);
        t->set(i, "DX", r.dx);
        t->set(i, "DY", r.dy);
    }
    return t;
}

std::vector<std::string> nodes(const Table& t) {
    std::vector<std::string> out;
    for (const auto& c : t.column("NOEUD").cells) out.push_back(std::get<std::string>(c));
    return out;
}

ConceptPtr runCommand(const char* name, KeywordSet kw, ConceptPtr reused = nullptr, Units* units = nullptr) {
    CommandContext ctx;
    ctx.command = name;
    ctx.reused = reused;
    ctx.units = units;
    const CommandFunction* fn = CommandRegistry::instance().find(name);
    EXPECT_NE(fn, nullptr);
    return (*fn)(validateKeywords(name, kw), ctx);
}

class CalcTableTest : public ::testing::Test {
protected:
    void SetUp() override {
        msg().setEcho(false);
        msg().reset();
    }
};

}  // namespace

TEST_F(CalcTableTest, ExtrKeepsColumnsInGivenOrder) {
    auto t = depTable();
    extractColumns(*t, {"DX", "NOEUD"});
    EXPECT_EQ(t->columnNames(), (std::vector<std::string>{"DX", "NOEUD"}));
    EXPECT_EQ(t->rowCount(), 5u);
    EXPECT_THROW(extractColumns(*t, {"DZ"}), UserError);
    // rows left empty disappear
    auto u = depTable();
    u->set(u->addRow(), "DX", 3.0);
    extractColumns(*u, {"NOEUD"});
    EXPECT_EQ(u->rowCount(), 5u);
}

TEST_F(CalcTableTest, FiltreRegexpIsASearch) {
    auto t = depTable();
    RowFilter f;
    f.column = "NOEUD";
    f.comparison = "REGEXP";
    f.texts = {"NP"};
    filterRows(*t, f);
    EXPECT_EQ(nodes(*t), (std::vector<std::string>{"NP000001", "NP000003", "XNPQ"}));
    auto u = depTable();
    f.texts = {"^NM0+4$"};
    filterRows(*u, f);
    EXPECT_EQ(nodes(*u), (std::vector<std::string>{"NM000004"}));
}

TEST_F(CalcTableTest, FiltreComparisons) {
    auto check = [](RowFilter f, std::vector<std::string> expected) {
        auto t = depTable();
        filterRows(*t, f);
        EXPECT_EQ(nodes(*t), expected) << f.describe();
    };
    RowFilter gt{"COOR_X", "GT", {0.02}, {}, {}};
    check(gt, {"NP000003", "NM000004"});
    RowFilter lt{"COOR_X", "LT", {-0.02}, {}, {}};
    check(lt, {"NP000001", "NM000002"});
    RowFilter ge{"COOR_X", "GE", {0.0, 5.0}, {}, {}};  // lists: GE compares with the smallest value
    check(ge, {"NP000003", "NM000004", "XNPQ"});
    RowFilter le{"COOR_X", "LE", {-2.0, 0.0}, {}, {}};  // LE with the largest
    check(le, {"NP000001", "NM000002", "XNPQ"});
    // EQ relative to the given value: s*x*(1-P) <= s*v <= s*x*(1+P)
    RowFilter eq{"DX", "EQ", {-0.2502}, {}, {}};
    check(eq, {"NP000001"});  // |-0.25 - -0.2502| = 2e-4 <= 2.502e-4
    RowFilter eqTight{"DX", "EQ", {-0.2502}, {}, {}};
    eqTight.precision = 1e-4;
    check(eqTight, {});
    RowFilter eqAbs{"DX", "EQ", {0.7, 1.0}, {}, {}};
    eqAbs.relative = false;
    eqAbs.precision = 0.06;
    check(eqAbs, {"NP000003", "NM000004"});
    RowFilter eqExact{"DX", "EQ", {0.75}, {}, {}};
    eqExact.precision = 0.0;
    check(eqExact, {"NP000003"});
    RowFilter ne{"DX", "NE", {0.75, 1.0}, {}, {}};
    check(ne, {"NP000001", "NM000002", "XNPQ"});
    RowFilter eqText{"NOEUD", "EQ", {}, {}, {"XNPQ ", "NM000002"}};  // stripped comparison
    check(eqText, {"NM000002", "XNPQ"});
    RowFilter eqInt{"COOR_Y", "EQ", {}, {4}, {}};
    check(eqInt, {"XNPQ"});
    RowFilter maxi{"DX", "MAXI", {}, {}, {}};
    check(maxi, {"NM000004"});
    RowFilter mini{"DY", "MINI", {}, {}, {}};
    check(mini, {"NM000004"});
    RowFilter maxiAbs{"DY", "MAXI_ABS", {}, {}, {}};
    check(maxiAbs, {"XNPQ"});
    RowFilter miniAbs{"DY", "MINI_ABS", {}, {}, {}};
    check(miniAbs, {"NP000001", "NM000002"});
}

TEST_F(CalcTableTest, FiltreEmptyCells) {
    auto t = depTable();
    t->set(1, "DY", Cell{});
    RowFilter vide{"DY", "VIDE", {}, {}, {}};
    filterRows(*t, vide);
    EXPECT_EQ(nodes(*t), (std::vector<std::string>{"NM000002"}));
    auto u = depTable();
    u->set(1, "DY", Cell{});
    RowFilter nonVide{"DY", "NON_VIDE", {}, {}, {}};
    filterRows(*u, nonVide);
    EXPECT_EQ(u->rowCount(), 4u);
    // an empty result is allowed here
    auto w = depTable();
    RowFilter none{"COOR_X", "GT", {100.0}, {}, {}};
    filterRows(*w, none);
    EXPECT_EQ(w->rowCount(), 0u);
    // a number on a text column, a pattern on a real column: user errors
    auto e = depTable();
    EXPECT_THROW(filterRows(*e, RowFilter{"NOEUD", "GT", {1.0}, {}, {}}), UserError);
    EXPECT_THROW(filterRows(*e, RowFilter{"DX", "REGEXP", {}, {}, {"1"}}), UserError);
    EXPECT_THROW(filterRows(*e, RowFilter{"DZ", "GT", {1.0}, {}, {}}), UserError);
}

TEST_F(CalcTableTest, CombWithoutKeysConcatenates) {
    auto a = depTable();
    auto b = depTable();
    extractColumns(*b, {"NOEUD", "DX"});
    b->addColumn("EXTRA", ColumnType::integer());
    b->set(0, "EXTRA", 7LL);
    combineTables(*a, *b, {}, false);
    EXPECT_EQ(a->rowCount(), 10u);
    EXPECT_EQ(a->columnNames().back(), "EXTRA");
    EXPECT_TRUE(isEmpty(a->cell(0, size_t(a->columnIndex("EXTRA")))));
    EXPECT_EQ(std::get<long long>(a->cell(5, size_t(a->columnIndex("EXTRA")))), 7);
    EXPECT_TRUE(isEmpty(a->cell(5, size_t(a->columnIndex("COOR_X")))));
}

TEST_F(CalcTableTest, CombWithKeysMergesUniqueKeys) {
    auto a = std::make_shared<Table>();
    a->addColumn("K", ColumnType::text(8));
    a->addColumn("V", ColumnType::real());
    for (auto [k, v] : std::vector<std::pair<const char*, double>>{{"A", 1}, {"B", 2}, {"B", 3}, {"C", 4}}) {
        const size_t r = a->addRow();
        a->set(r, 0, std::string(k));
        a->set(r, 1, v);
    }
    auto b = std::make_shared<Table>();
    b->addColumn("K", ColumnType::text(8));
    b->addColumn("W", ColumnType::real());
    for (auto [k, w] : std::vector<std::pair<const char*, double>>{{"A", 10}, {"B", 20}, {"D", 40}}) {
        const size_t r = b->addRow();
        b->set(r, 0, std::string(k));
        b->set(r, 1, w);
    }
    auto merged = std::make_shared<Table>(*a);
    combineTables(*merged, *b, {"K"}, false);
    // A merged; B not unique in the first table: appended; D new: appended
    ASSERT_EQ(merged->rowCount(), 6u);
    const size_t w = size_t(merged->columnIndex("W"));
    EXPECT_EQ(std::get<double>(merged->cell(0, w)), 10.0);
    EXPECT_TRUE(isEmpty(merged->cell(1, w)));
    EXPECT_EQ(std::get<std::string>(merged->cell(4, 0)), "B");
    EXPECT_EQ(std::get<std::string>(merged->cell(5, 0)), "D");
    auto restricted = std::make_shared<Table>(*a);
    combineTables(*restricted, *b, {"K"}, true);
    EXPECT_EQ(restricted->rowCount(), 4u);
    EXPECT_THROW(combineTables(*restricted, *b, {"V"}, false), UserError);
}

TEST_F(CalcTableTest, OperEvaluatesInOneBatch) {
    auto t = depTable();
    t->set(4, "DX", Cell{});  // no value: the new cell stays empty
    LambdaFunction f({"DX", "COOR_X", "COOR_Y"}, [](std::span<const double> a) { return a[0] - (0.1 * a[1] + a[2]); });
    f.name = "depl_x1";
    addFormulaColumn(*t, f, "DX-DX", {});
    EXPECT_EQ(f.batches, 1);
    const Column& c = t->column("DX-DX");
    EXPECT_EQ(c.type.kind, ColumnType::Real);
    EXPECT_DOUBLE_EQ(std::get<double>(c.cells[0]), -0.25 + 0.2);
    EXPECT_DOUBLE_EQ(std::get<double>(c.cells[3]), 1.0 - 0.3);
    EXPECT_TRUE(isEmpty(c.cells[4]));
    EXPECT_EQ(t->columnNames().back(), "DX-DX");
    // NOM_COLONNE maps the formula parameters to other columns
    LambdaFunction g({"A", "B"}, [](std::span<const double> a) { return a[0] * a[1]; });
    addFormulaColumn(*t, g, "P", {"COOR_X", "DY"});
    EXPECT_DOUBLE_EQ(std::get<double>(t->column("P").cells[4]), 0.0);
    EXPECT_THROW(addFormulaColumn(*t, g, "P", {"COOR_X", "DY"}), UserError);       // exists
    EXPECT_THROW(addFormulaColumn(*t, g, "Q", {"COOR_X"}), UserError);             // count
    EXPECT_THROW(addFormulaColumn(*t, g, "Q", {"COOR_X", "DZ"}), UserError);       // missing column
    EXPECT_THROW(addFormulaColumn(*t, f, "Q", {"NOEUD", "DX", "DY"}), UserError);  // text argument
}

TEST_F(CalcTableTest, RenameRemoveSortAddColumn) {
    auto t = depTable();
    renameColumn(*t, "DX", "UX");
    EXPECT_TRUE(t->hasColumn("UX"));
    EXPECT_THROW(renameColumn(*t, "UX", "DY"), UserError);
    removeColumns(*t, {"INTITULE", "COOR_Y"});
    EXPECT_EQ(t->columnNames(), (std::vector<std::string>{"NOEUD", "COOR_X", "UX", "DY"}));
    sortRows(*t, {"COOR_X", "UX"}, false);
    EXPECT_EQ(nodes(*t), (std::vector<std::string>{"NM000004", "NP000003", "XNPQ", "NP000001", "NM000002"}));
    sortRows(*t, {"UX"}, true);
    EXPECT_EQ(nodes(*t).front(), "NM000002");
    addConstantColumns(*t, {"NUME", "NAME"}, {Cell{3LL}, Cell{std::string("ZONE_ONE_LONGER")}});
    EXPECT_EQ(t->column("NUME").type.kind, ColumnType::Integer);
    EXPECT_EQ(t->column("NAME").type, ColumnType::text(16));
    EXPECT_EQ(std::get<long long>(t->column("NUME").cells[4]), 3);
}

// The ssnv511e chain through the command: COMB then two OPER; title from the input table.
TEST_F(CalcTableTest, CommandActionsInSequenceAndTitles) {
    auto a = depTable();
    auto b = depTable();
    b->name = "DEPPLX";
    auto formula = std::make_shared<LambdaFunction>(std::vector<std::string>{"DY", "COOR_X", "COOR_Y"},
                                                    [](std::span<const double> x) { return x[0] - x[1]; });
    KeywordSet kw;
    kw.setValues("TABLE", {ConceptPtr(a)});
    KeywordSet& comb = kw.addOccurrence("ACTION");
    comb.setValues("OPERATION", {std::string("COMB")});
    comb.setValues("TABLE", {ConceptPtr(b)});
    KeywordSet& oper = kw.addOccurrence("ACTION");
    oper.setValues("OPERATION", {std::string("OPER")});
    oper.setValues("NOM_PARA", {std::string("DY-DY")});
    oper.setValues("FORMULE", {ConceptPtr(formula)});
    KeywordSet& filt = kw.addOccurrence("ACTION");
    filt.setValues("OPERATION", {std::string("FILTRE")});
    filt.setValues("NOM_PARA", {std::string("NOEUD")});
    filt.setValues("CRIT_COMP", {std::string("REGEXP")});
    filt.setValues("VALE_K", {std::string("^NP")});
    auto out = std::dynamic_pointer_cast<Table>(runCommand("CALC_TABLE", kw));
    ASSERT_TRUE(out);
    EXPECT_EQ(out->rowCount(), 4u);  // 2 NP rows from each table
    EXPECT_TRUE(out->hasColumn("DY-DY"));
    EXPECT_EQ(a->rowCount(), 5u);  // the input is untouched
    ASSERT_EQ(out->title.size(), 1u);
    EXPECT_EQ(out->title[0].rfind("ASTER miniaster-0.1 CONCEPT DEP CALCULE LE ", 0), 0u) << out->title[0];
    // reuse keeps the old title; TITRE overrides
    KeywordSet kw2;
    kw2.setValues("TABLE", {ConceptPtr(a)});
    KeywordSet& extr = kw2.addOccurrence("ACTION");
    extr.setValues("OPERATION", {std::string("EXTR")});
    extr.setValues("NOM_PARA", {std::string("NOEUD"), std::string("DX")});
    auto reused = std::dynamic_pointer_cast<Table>(runCommand("CALC_TABLE", kw2, a));
    EXPECT_EQ(reused->title, (std::vector<std::string>{"TITLE OF DEP"}));
    EXPECT_EQ(reused->columnNames(), (std::vector<std::string>{"NOEUD", "DX"}));
    kw2.setValues("TITRE", {std::string("MY TITLE")});
    auto titled = std::dynamic_pointer_cast<Table>(runCommand("CALC_TABLE", kw2));
    EXPECT_EQ(titled->title, (std::vector<std::string>{"MY TITLE"}));
}

TEST(AutomaticTitle, ReflowsAt80) {
    const auto lines = automaticTitle("DEPZON_1", "table_sdaster");
    ASSERT_GE(lines.size(), 1u);
    for (const auto& l : lines) EXPECT_LE(l.size(), 80u);
    std::string joined;
    for (const auto& l : lines) joined += (joined.empty() ? "" : " ") + l;
    EXPECT_NE(joined.find("CONCEPT DEPZON_1 CALCULE LE "), std::string::npos);
    EXPECT_NE(joined.find(" DE TYPE TABLE_SDASTER"), std::string::npos);
}

// §4.2's example, byte for byte.
TEST(ImprTable, TableauLayoutExact) {
    Table t;
    t.title = {"ERREUR EN NORME L2 DU DEPLACEMENT"};
    t.addColumn("GROUP_MA", ColumnType::text(8));
    t.addColumn("DIFFERENCE", ColumnType::real());
    t.addColumn("REFERENCE", ColumnType::real());
    t.addColumn("ERREUR RELATIVE", ColumnType::real());
    size_t r = t.addRow();
    t.set(r, 0, std::string("SURF"));
    t.set(r, 1, 6.6e-15);
    t.set(r, 2, 6.846531968814576);
    r = t.addRow();
    t.set(r, 0, std::string("TOTAL"));
    t.set(r, 1, 6.6e-15);
    t.set(r, 2, 6.846531968814576);
    t.set(r, 3, 9.67761363232E-16);
    const std::string expected =
        "#\n"
        "#--------------------------------------------------------------------------------\n"
        "##ERREUR EN NORME L2 DU DEPLACEMENT                                               \n"
        "GROUP_MA DIFFERENCE   REFERENCE    ERREUR RELATIVE\n"
        "SURF      6.60000E-15  6.84653E+00    -           \n"
        "TOTAL     6.60000E-15  6.84653E+00     9.67761E-16\n"
        "\n";
    EXPECT_EQ(formatTable(t), expected);
}

TEST(ImprTable, NoTitleEmptyColumnsIntegersAndSelection) {
    Table t;
    t.addColumn("NOEUD", ColumnType::text(8));
    t.addColumn("NUME_ORDRE", ColumnType::integer());
    t.addColumn("EMPTY", ColumnType::real());
    t.addColumn("DX", ColumnType::real());
    size_t r = t.addRow();
    t.set(r, 0, std::string("N1"));
    t.set(r, 1, 1LL);
    t.set(r, 3, -0.25);
    r = t.addRow();
    t.set(r, 0, std::string("N2"));
    t.set(r, 3, 1e-300);
    t.addRow();  // entirely empty: not printed
    const std::string expected =
        "#\n"
        "#--------------------------------------------------------------------------------\n"
        "#NOEUD    NUME_ORDRE   DX          \n"
        "N1                  1 -2.50000E-01\n"
        "N2       -            1.00000E-300\n"
        "\n";
    EXPECT_EQ(formatTable(t), expected);
    TablePrintOptions only;
    only.columns = {"DX", "NOEUD"};
    only.realFormat = "%10.3f";
    EXPECT_EQ(formatTable(t, only),
              "#\n#--------------------------------------------------------------------------------\n"
              "#DX         NOEUD   \n"
              "    -0.250 N1      \n"
              "     0.000 N2      \n\n");
}

TEST(ImprTable, AgrafWithScaleFactorAsCodeAsterPrintsIt) {
    // code_aster's table_py with FORMAT='AGRAF', FORMAT_R='1PE12.5' (fmtF2PY: ' %12.5E'): the real
    // column is 13 wide, its name and '-' start after the blank, an empty cell is preceded by '\'.
    Table t;
    t.addColumn("NOEUD", ColumnType::text(8));
    t.addColumn("DX", ColumnType::real());
    t.set(t.addRow(), 0, std::string("N1"));
    t.set(0, 1, -0.25);
    t.set(t.addRow(), 0, std::string("N2"));
    TablePrintOptions agraf;
    agraf.realFormat = fortranToPrintf("1PE12.5");
    agraf.agraf = true;
    EXPECT_EQ(formatTable(t, agraf),
              "#\n#--------------------------------------------------------------------------------\n"
              "#NOEUD     DX          \n"
              "N1        -2.50000E-01\n"
              "N2       \\ -           \n\n");
}

TEST(ImprTable, CommandWritesResuOrUnit) {
    msg().setEcho(false);
    msg().reset();
    auto t = depTable();
    KeywordSet kw;
    kw.setValues("TABLE", {ConceptPtr(t)});
    kw.setValues("NOM_PARA", {std::string("NOEUD"), std::string("DX")});
    runCommand("IMPR_TABLE", kw);
    EXPECT_EQ(msg().resuText().rfind("#\n#---", 0), 0u);
    EXPECT_NE(msg().resuText().find("##TITLE OF DEP"), std::string::npos);
    EXPECT_NE(msg().resuText().find("\nNOEUD    DX          \nNP000001 -2.50000E-01\n"), std::string::npos);

    const auto dir = std::filesystem::temp_directory_path() / "miniaster_impr_table_test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    Units units;
    units.setOutputDir(dir.string());
    kw.setValues("UNITE", {38LL});
    runCommand("IMPR_TABLE", kw, nullptr, &units);
    runCommand("IMPR_TABLE", kw, nullptr, &units);  // appended
    std::ifstream in(dir / "fort.38");
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string once = formatTable(*t, TablePrintOptions{{"NOEUD", "DX"}});
    EXPECT_EQ(ss.str(), once + once);
    std::filesystem::remove_all(dir);
}
