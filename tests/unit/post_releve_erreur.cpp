// POST_RELEVE_T extraction (commands_spec.md §2) and POST_ERREUR (§5) on small meshes with known
// fields: exact integrals, and the ssnv511 reference values of §5.2.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "core/Function.hpp"
#include "core/Messages.hpp"
#include "fe/ElementKinematics.hpp"
#include "fe/Material.hpp"
#include "fe/Model.hpp"
#include "fe/Result.hpp"
#include "parser/Catalog.hpp"
#include "parser/CommandRegistry.hpp"
#include "post/ErrorNorms.hpp"
#include "post/NodalExtraction.hpp"

using namespace ma;

namespace {

class LambdaFunction : public Function {
public:
    LambdaFunction(std::string n, std::vector<std::string> params, std::function<double(std::span<const double>)> f)
        : params_(std::move(params)), f_(std::move(f)) {
        name = std::move(n);
    }
    std::string typeName() const override { return "formule"; }
    const std::vector<std::string>& parameters() const override { return params_; }
    double evaluate(std::span<const double> args) const override { return f_(args); }

private:
    std::vector<std::string> params_;
    std::function<double(std::span<const double>)> f_;
};
using FunctionPtr = std::shared_ptr<LambdaFunction>;
FunctionPtr formula(const char* name, std::vector<std::string> params,
                    std::function<double(std::span<const double>)> f) {
    return std::make_shared<LambdaFunction>(name, std::move(params), std::move(f));
}

// n x n QUAD4 grid on [-5, 5]^2; groups SURF (all cells), Q1..Q4 (quadrants), NODES (all nodes).
std::shared_ptr<Mesh> squareMesh(int n) {
    auto mesh = std::make_shared<Mesh>();
    mesh->name = "MAILLAG";
    mesh->dim = 2;
    const double h = 10.0 / n;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) mesh->addNode({-5.0 + i * h, -5.0 + j * h, 0.0});
    std::vector<int> all, q[4];
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i;
            const int nodes[4] = {a, a + 1, a + n + 2, a + n + 1};
            const int c = mesh->addCell(CellType::QUAD4, nodes);
            all.push_back(c);
            const bool left = i < n / 2, top = j >= n / 2;
            q[left ? (top ? 0 : 1) : (top ? 2 : 3)].push_back(c);
        }
    mesh->cellGroups.set("SURF", all);
    for (int k = 0; k < 4; ++k) mesh->cellGroups.set("Q" + std::to_string(k + 1), q[k]);
    std::vector<int> nodes(size_t(mesh->nodeCount()));
    for (int i = 0; i < mesh->nodeCount(); ++i) nodes[size_t(i)] = i;
    mesh->nodeGroups.set("NODES", nodes);
    return mesh;
}

std::shared_ptr<Model> planeModel(const std::shared_ptr<Mesh>& mesh, Modelisation m) {
    auto model = std::make_shared<Model>();
    model->name = "MODELE";
    model->mesh = mesh;
    model->dim = 2;
    model->modelisation = m;
    for (int c = 0; c < mesh->cellCount(); ++c) model->elements.push_back({c, m});
    return model;
}

std::shared_ptr<NodalField> nodalField(const std::shared_ptr<Mesh>& mesh,
                                       std::function<std::array<double, 2>(double, double)> u) {
    auto f = std::make_shared<NodalField>();
    f->name = "UCAL";
    f->resize(mesh, {"DX", "DY"});
    for (int i = 0; i < mesh->nodeCount(); ++i) {
        const auto& x = mesh->coords[size_t(i)];
        const auto v = u(x[0], x[1]);
        f->set(i, 0, v[0]);
        f->set(i, 1, v[1]);
    }
    return f;
}

// SIEF_ELGA on the model's own Gauss points, filled with a given stress function.
std::shared_ptr<GaussField> stressField(const Model& model, std::function<std::array<double, 4>(double, double)> s) {
    auto f = std::make_shared<GaussField>();
    f->name = "SCAL";
    f->mesh = model.mesh;
    f->components = {"SIXX", "SIYY", "SIZZ", "SIXY"};
    ElementIntegration ei;
    PointGeometry geo;
    for (const auto& e : model.elements) {
        elementIntegration(model, e.cell, false, ei);
        computePointGeometry(*model.mesh, e.cell, model.dim, false, ei, geo);
        f->cells.push_back(e.cell);
        for (size_t p = 0; p < ei.refPoints.size(); ++p) {
            f->pointCoords.push_back(geo.xyz[p]);
            f->pointWeights.push_back(geo.weight[p]);
            f->pointSubcell.push_back(0);
            f->pointRefCoords.push_back(ei.refPoints[p]);
            const auto v = s(geo.xyz[p][0], geo.xyz[p][1]);
            f->values.insert(f->values.end(), v.begin(), v.end());
        }
        f->pointOffsets.push_back(f->pointCount());
    }
    return f;
}

std::shared_ptr<MaterialField> steel(const std::shared_ptr<Mesh>& mesh) {
    auto mat = std::make_shared<Material>();
    mat->E = 100.0e6;
    mat->nu = 0.3;
    auto field = std::make_shared<MaterialField>();
    field->mesh = mesh;
    field->cellMaterial.assign(size_t(mesh->cellCount()), mat);
    return field;
}

double real(const Table& t, size_t row, const std::string& col) {
    return std::get<double>(t.cell(row, size_t(t.columnIndex(col))));
}

ConceptPtr runCommand(const char* name, const KeywordSet& kw, const std::string& resultName = "") {
    CommandContext ctx;
    ctx.command = name;
    ctx.resultName = resultName;
    const CommandFunction* fn = CommandRegistry::instance().find(name);
    EXPECT_NE(fn, nullptr);
    return (*fn)(validateKeywords(name, kw), ctx);
}

double pressure(double x) { return x < 0 ? 1e6 : 2e6; }

class PostTest : public ::testing::Test {
protected:
    void SetUp() override {
        msg().setEcho(false);
        msg().reset();
    }
};

}  // namespace

// ssnv511e (D_PLAN): energy of the reference stress over [-5,5]^2 = 1 397 500 (§5.2); the
// computed field equal to the reference gives DIFFERENCE 0 and the column ERREUR RELATIVE = 0.
TEST_F(PostTest, EnergyReferenceDPlanSsnv511e) {
    auto mesh = squareMesh(4);
    auto model = planeModel(mesh, Modelisation::D_PLAN);
    const double nu = 0.3;
    auto sref = [&](double x, double y) -> std::array<double, 4> {
        return {-pressure(y), -pressure(x), -nu * (pressure(x) + pressure(y)), 0.0};
    };
    auto sigma = stressField(*model, sref);
    ReferenceFormulas ref;
    ref.components = {"SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ"};
    ref.formulas.resize(6);
    ref.formulas[0] = {formula("SXX", {"X", "Y"}, [](auto a) { return -pressure(a[1]); })};
    ref.formulas[1] = {formula("SYY", {"X", "Y"}, [](auto a) { return -pressure(a[0]); })};
    ref.formulas[2] = {formula("SZZ", {"X", "Y"}, [&](auto a) { return -nu * (pressure(a[0]) + pressure(a[1])); })};
    auto table = energyErrorTable(*model, *sigma, *steel(mesh), {"SURF"}, ref);
    ASSERT_EQ(table->columnNames(),
              (std::vector<std::string>{"GROUP_MA", "DIFFERENCE", "REFERENCE", "ERREUR RELATIVE"}));
    ASSERT_EQ(table->rowCount(), 2u);
    EXPECT_EQ(std::get<std::string>(table->cell(1, 0)), "TOTAL");
    EXPECT_NEAR(real(*table, 1, "REFERENCE"), 1397500.0, 1e-9 * 1397500.0);
    EXPECT_EQ(real(*table, 1, "DIFFERENCE"), 0.0);
    EXPECT_EQ(real(*table, 1, "ERREUR RELATIVE"), 0.0);
    EXPECT_TRUE(isEmpty(table->cell(0, 3)));  // relative error only on TOTAL
    EXPECT_EQ(table->title, (std::vector<std::string>{"ERREUR EN NORME ENERGIE"}));
    // per quadrant (one formula per group): 373750 + 130000 + 520000 + 373750
    ReferenceFormulas perGroup = ref;
    for (int c : {0, 1, 2}) perGroup.formulas[size_t(c)].assign(4, ref.formulas[size_t(c)][0]);
    auto quadrants = energyErrorTable(*model, *sigma, *steel(mesh), {"Q1", "Q2", "Q3", "Q4"}, perGroup);
    const double expected[4] = {373750.0, 130000.0, 520000.0, 373750.0};
    for (size_t g = 0; g < 4; ++g) EXPECT_NEAR(real(*quadrants, g, "REFERENCE"), expected[g], 1e-6) << g;
    EXPECT_NEAR(real(*quadrants, 4, "REFERENCE"), 1397500.0, 1e-6);
}

// ssnv511f-h (C_PLAN, no SIZZ): 1 825 000; a known stress error gives a known difference energy.
TEST_F(PostTest, EnergyReferenceCPlanAndDifference) {
    auto mesh = squareMesh(2);
    auto model = planeModel(mesh, Modelisation::C_PLAN);
    // computed = reference + a uniform shear of 1e5: difference energy = (1+nu)/E * 1e10 * area
    auto sigma = stressField(*model, [](double x, double y) -> std::array<double, 4> {
        return {-pressure(y), -pressure(x), 0.0, 1e5};
    });
    ReferenceFormulas ref;
    ref.components = {"SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ"};
    ref.formulas.resize(6);
    ref.formulas[0] = {formula("SXX", {"X", "Y"}, [](auto a) { return -pressure(a[1]); })};
    ref.formulas[1] = {formula("SYY", {"X", "Y"}, [](auto a) { return -pressure(a[0]); })};
    auto table = energyErrorTable(*model, *sigma, *steel(mesh), {"SURF"}, ref);
    EXPECT_NEAR(real(*table, 1, "REFERENCE"), 1825000.0, 1e-9 * 1825000.0);
    const double diff = 1.3 / 100.0e6 * 1e10 * 100.0;
    EXPECT_NEAR(real(*table, 1, "DIFFERENCE"), diff, 1e-12 * diff);
    EXPECT_NEAR(real(*table, 1, "ERREUR RELATIVE"), std::sqrt(diff / 1825000.0), 1e-14);
    // C_PLAN ignores SIZZ of the field and of the reference
    double s[6] = {1.0, 2.0, 50.0, 0.0, 0.0, 0.0};
    EXPECT_EQ(elasticEnergyDensity(s, 10.0, 0.25, true), (1.0 + 4.0 - 2 * 0.25 * 2.0) / 20.0);
}

// ssnv511a DEPL_RELA: reference sqrt(25 * 1.875) = 6.846531968814576 for the piecewise DX; a
// linear computed field is interpolated exactly, so the difference of a constant shift c is
// |c| * sqrt(area).
TEST_F(PostTest, DisplacementNorms) {
    auto mesh = squareMesh(4);
    auto model = planeModel(mesh, Modelisation::D_PLAN);
    auto depx = formula("DEPL_X", {"X", "Y"}, [](auto a) {
        const double x = a[0], y = a[1];
        if (y > 0 && x < 0) return -0.25;
        if (y < 0 && x < 0) return -0.5;
        if (y > 0 && x > 0) return 0.75;
        if (y < 0 && x > 0) return 1.0;
        return 0.0;
    });
    auto zero = nodalField(mesh, [](double, double) -> std::array<double, 2> { return {0.0, 0.0}; });
    ReferenceFormulas ref{{"DX", "DY"}, {{depx}, {}}};
    auto table = displacementErrorTable(*model, *zero, {"SURF"}, ref);
    EXPECT_NEAR(real(*table, 1, "REFERENCE"), 6.846531968814576, 1e-14);
    EXPECT_NEAR(real(*table, 1, "DIFFERENCE"), 6.846531968814576, 1e-14);
    EXPECT_EQ(table->title, (std::vector<std::string>{"ERREUR EN NORME L2 DU DEPLACEMENT"}));

    auto linear = [](double x, double y) -> std::array<double, 2> { return {0.01 * x + 0.02 * y, -0.03 * x}; };
    auto uh = nodalField(mesh, linear);
    auto ux = formula("UX", {"X", "Y"}, [](auto a) { return 0.01 * a[0] + 0.02 * a[1] + 0.5; });
    auto uy = formula("UY", {"X"}, [](auto a) { return -0.03 * a[0]; });
    ReferenceFormulas shifted{{"DX", "DY"}, {{ux}, {uy}}};
    auto t2 = displacementErrorTable(*model, *uh, {"SURF"}, shifted);
    EXPECT_NEAR(real(*t2, 1, "DIFFERENCE"), 0.5 * 10.0, 1e-12);
    // exact L2 norm of the reference: int (0.01x+0.02y+0.5)^2 + (0.03x)^2 over [-5,5]^2
    const double a2 = 100.0 * (0.25 + (0.0001 + 0.0004 + 0.0009) * 25.0 / 3.0);
    EXPECT_NEAR(real(*t2, 1, "REFERENCE"), std::sqrt(a2), 1e-12);
    EXPECT_NEAR(real(*t2, 1, "ERREUR RELATIVE"), 5.0 / std::sqrt(a2), 1e-13);
    // groups: TOTAL = sqrt(sum of squares)
    ReferenceFormulas perGroup{{"DX", "DY"}, {{ux, ux, ux, ux}, {uy, uy, uy, uy}}};
    auto t3 = displacementErrorTable(*model, *uh, {"Q1", "Q2", "Q3", "Q4"}, perGroup);
    for (size_t g = 0; g < 4; ++g) EXPECT_NEAR(real(*t3, g, "DIFFERENCE"), 0.5 * 5.0, 1e-12);
    EXPECT_NEAR(real(*t3, 4, "DIFFERENCE"), 5.0, 1e-12);
    // one formula per group is required
    EXPECT_THROW(displacementErrorTable(*model, *uh, {"Q1", "Q2"}, shifted), UserError);
    EXPECT_THROW(displacementErrorTable(*model, *uh, {"NOPE"}, shifted), UserError);
}

// A zero reference: no ERREUR RELATIVE column at all.
TEST_F(PostTest, ZeroReferenceHasNoRelativeColumn) {
    auto mesh = squareMesh(2);
    auto model = planeModel(mesh, Modelisation::D_PLAN);
    auto uh = nodalField(mesh, [](double x, double) -> std::array<double, 2> { return {x, 0.0}; });
    auto table = displacementErrorTable(*model, *uh, {"SURF"}, ReferenceFormulas{{"DX", "DY"}, {{}, {}}});
    EXPECT_EQ(table->columnNames(), (std::vector<std::string>{"GROUP_MA", "DIFFERENCE", "REFERENCE"}));
    EXPECT_EQ(real(*table, 1, "REFERENCE"), 0.0);
    EXPECT_NEAR(real(*table, 1, "DIFFERENCE"), std::sqrt(2500.0 / 3.0), 1e-12);  // int x^2 over [-5,5]^2
}

// The POST_ERREUR command with one formula given as a list of one.
TEST_F(PostTest, PostErreurCommand) {
    auto mesh = squareMesh(2);
    auto model = planeModel(mesh, Modelisation::D_PLAN);
    auto uh = nodalField(mesh, [](double x, double) -> std::array<double, 2> { return {x, 0.0}; });
    KeywordSet kw;
    kw.setValues("OPTION", {std::string("DEPL_RELA")});
    kw.setValues("MODELE", {ConceptPtr(model)});
    kw.setValues("CHAM_GD", {ConceptPtr(uh)});
    kw.setValues("GROUP_MA", {std::string("SURF")});
    kw.setValues("DX", {ConceptPtr(formula("UX", {"X"}, [](auto a) { return a[0]; }))});
    auto table = std::dynamic_pointer_cast<Table>(runCommand("POST_ERREUR", kw));
    ASSERT_TRUE(table);
    EXPECT_NEAR(real(*table, 1, "DIFFERENCE"), 0.0, 1e-13);
    EXPECT_NEAR(real(*table, 1, "ERREUR RELATIVE"), 0.0, 1e-14);
}

// POST_RELEVE_T: columns and rows in code_aster's order, restriction to nodes carrying the
// components, cumulative ABSC_CURV.
TEST_F(PostTest, ReleveExtractionColumnsAndRows) {
    auto mesh = squareMesh(2);                      // 9 nodes, N1..N9
    mesh->nodeGroups.set("LINE", {6, 7, 8, 4, 7});  // top row then the centre; N8 repeated
    auto depl = std::make_shared<NodalField>();
    depl->resize(mesh, {"DX", "DY", "H1X"});
    for (int i = 0; i < mesh->nodeCount(); ++i) {
        if (i == 7) continue;  // N8 carries nothing: dropped
        depl->set(i, 0, 0.1 * i);
        depl->set(i, 1, -0.1 * i);
    }
    depl->set(4, 2, 9.0);  // only N5 is enriched
    auto result = std::make_shared<Result>("evol_noli");
    result->name = "RESU";
    result->mesh = mesh;
    result->steps.resize(2);
    result->steps[0].order = 0;
    result->steps[0].inst = 0.0;
    result->steps[0].nodalFields = {{"DEPL", depl}};
    result->steps[1].order = 1;
    result->steps[1].inst = 1.0;
    result->steps[1].nodalFields = {{"DEPL", depl}};

    KeywordSet kw;
    KeywordSet& a = kw.addOccurrence("ACTION");
    a.setValues("OPERATION", {std::string("EXTRACTION")});
    a.setValues("INTITULE", {std::string("DEPLE")});
    a.setValues("GROUP_NO", {std::string("LINE")});
    a.setValues("NOEUD", {std::string("N1")});
    a.setValues("RESULTAT", {ConceptPtr(result)});
    a.setValues("NOM_CHAM", {std::string("DEPL")});
    a.setValues("NUME_ORDRE", {1LL});
    a.setValues("TOUT_CMP", {std::string("OUI")});
    auto table = std::dynamic_pointer_cast<Table>(runCommand("POST_RELEVE_T", kw, "DEP"));
    ASSERT_TRUE(table);
    EXPECT_EQ(table->columnNames(),
              (std::vector<std::string>{"INTITULE", "NOEUD", "RESU", "NOM_CHAM", "NUME_ORDRE", "INST", "ABSC_CURV",
                                        "COOR_X", "COOR_Y", "COOR_Z", "DX", "DY", "H1X"}));
    EXPECT_EQ(table->column("INTITULE").type, ColumnType::text(16));
    EXPECT_EQ(table->column("NOEUD").type, ColumnType::text(8));
    EXPECT_EQ(table->column("NUME_ORDRE").type, ColumnType::integer());
    ASSERT_EQ(table->rowCount(), 4u);  // N1, N7, N9, N5 (N8 carries no component, N8 twice)
    std::vector<std::string> nodes;
    for (const auto& c : table->column("NOEUD").cells) nodes.push_back(std::get<std::string>(c));
    EXPECT_EQ(nodes, (std::vector<std::string>{"N1", "N7", "N9", "N5"}));
    // N1 (-5,-5) -> N7 (-5,5): 10; -> N9 (5,5): 10; -> N5 (0,0): sqrt(50)
    EXPECT_DOUBLE_EQ(real(*table, 0, "ABSC_CURV"), 0.0);
    EXPECT_DOUBLE_EQ(real(*table, 1, "ABSC_CURV"), 10.0);
    EXPECT_DOUBLE_EQ(real(*table, 2, "ABSC_CURV"), 20.0);
    EXPECT_DOUBLE_EQ(real(*table, 3, "ABSC_CURV"), 20.0 + std::sqrt(50.0));
    EXPECT_DOUBLE_EQ(real(*table, 1, "DX"), 0.6);
    EXPECT_DOUBLE_EQ(real(*table, 3, "INST"), 1.0);
    EXPECT_EQ(real(*table, 3, "COOR_Z"), 0.0);
    EXPECT_TRUE(isEmpty(table->cell(0, size_t(table->columnIndex("H1X")))));
    EXPECT_EQ(real(*table, 3, "H1X"), 9.0);
    EXPECT_EQ(std::get<std::string>(table->cell(0, 2)), "RESU");
    ASSERT_EQ(table->title.size(), 1u);
    EXPECT_NE(table->title[0].find("CONCEPT DEP CALCULE LE"), std::string::npos);

    // all orders ascending when no access keyword; NOM_CMP restricts the columns and the nodes
    a.remove("NUME_ORDRE");
    a.remove("TOUT_CMP");
    a.setValues("NOM_CMP", {std::string("H1X")});
    auto t2 = std::dynamic_pointer_cast<Table>(runCommand("POST_RELEVE_T", kw, "DEP2"));
    ASSERT_EQ(t2->rowCount(), 2u);  // N5 at orders 0 and 1
    EXPECT_EQ(t2->columnNames().back(), "H1X");
    EXPECT_EQ(std::get<long long>(t2->cell(0, size_t(t2->columnIndex("NUME_ORDRE")))), 0);
    EXPECT_EQ(std::get<long long>(t2->cell(1, size_t(t2->columnIndex("NUME_ORDRE")))), 1);
    // INST access
    a.setValues("INST", {1.0});
    auto t3 = std::dynamic_pointer_cast<Table>(runCommand("POST_RELEVE_T", kw, "DEP3"));
    ASSERT_EQ(t3->rowCount(), 1u);
    // errors: unknown component, unknown group
    a.remove("INST");
    a.setValues("NOM_CMP", {std::string("DZ")});
    EXPECT_THROW(runCommand("POST_RELEVE_T", kw, "X"), UserError);
    a.setValues("NOM_CMP", {std::string("DX")});
    a.setValues("GROUP_NO", {std::string("NOPE")});
    EXPECT_THROW(runCommand("POST_RELEVE_T", kw, "X"), UserError);
}

// CHAM_GD instead of RESULTAT: CHAM_GD column, no RESU/NOM_CHAM/NUME_ORDRE/INST.
TEST_F(PostTest, ReleveOnField) {
    auto mesh = squareMesh(2);
    auto field = nodalField(mesh, [](double x, double y) -> std::array<double, 2> { return {x, y}; });
    NodalExtraction x;
    x.title = "T";
    x.nodes = {"N9", "N1"};
    x.field = field;
    auto t = extractNodalValues({x});
    EXPECT_EQ(t->columnNames(), (std::vector<std::string>{"INTITULE", "NOEUD", "CHAM_GD", "ABSC_CURV", "COOR_X",
                                                          "COOR_Y", "COOR_Z", "DX", "DY"}));
    EXPECT_DOUBLE_EQ(real(*t, 1, "ABSC_CURV"), std::sqrt(200.0));
    EXPECT_DOUBLE_EQ(real(*t, 1, "DY"), -5.0);
}
