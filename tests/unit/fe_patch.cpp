// Patch tests of the elasticity engine through the commands (AFFE_MODELE ... MECA_STATIQUE,
// STAT_NON_LINE, CREA_CHAMP): a linear displacement field is reproduced exactly (1e-12) at the
// nodes, and the constant stress at every Gauss point, on distorted meshes of every element.
#include <gtest/gtest.h>

#include <cmath>

#include "fe/DofNumbering.hpp"
#include "fe/Result.hpp"
#include "fe_test_support.hpp"

using namespace ma;
using namespace fetest;

namespace {

constexpr double E = 2.0e5, NU = 0.3;

struct Linear {
    double A[3][3];  // u = A x + c
    double c[3];
};

// A general linear field: tension in every direction, shear, and a rotation part.
Linear generalField(int dim) {
    Linear f{{{1.0e-3, 2.5e-4, 0.0}, {-1.5e-4, -4.0e-4, 0.0}, {0.0, 0.0, 0.0}}, {1.0e-3, -2.0e-3, 0.0}};
    if (dim == 3) {
        f.A[0][2] = 3.0e-4, f.A[1][2] = -1.0e-4, f.A[2][0] = 2.0e-4, f.A[2][1] = 5.0e-4, f.A[2][2] = 6.0e-4;
        f.c[2] = 5.0e-4;
    }
    return f;
}

// Stress of a constant strain (Voigt order SIXX SIYY SIZZ SIXY SIXZ SIYZ).
std::array<double, 6> stressOf(const Linear& f, int dim, Modelisation mod) {
    double eps[3][3] = {};
    for (int i = 0; i < dim; ++i)
        for (int j = 0; j < dim; ++j) eps[i][j] = 0.5 * (f.A[i][j] + f.A[j][i]);
    const double mu = E / (2 * (1 + NU));
    double lambda = E * NU / ((1 + NU) * (1 - 2 * NU));
    if (mod == Modelisation::C_PLAN) lambda = E * NU / (1 - NU * NU);
    const double tr = eps[0][0] + eps[1][1] + eps[2][2];
    auto s = [&](int i, int j) { return 2 * mu * eps[i][j] + (i == j ? lambda * tr : 0.0); };
    double szz = s(2, 2);
    if (mod == Modelisation::D_PLAN) szz = NU * (s(0, 0) + s(1, 1));
    if (mod == Modelisation::C_PLAN) szz = 0.0;
    return {s(0, 0), s(1, 1), szz, s(0, 1), s(0, 2), s(1, 2)};
}

std::shared_ptr<Function> component(const Linear& f, int c) {
    return std::make_shared<LambdaFunction>(
        [f, c](double x, double y, double z) { return f.A[c][0] * x + f.A[c][1] * y + f.A[c][2] * z + f.c[c]; });
}

std::shared_ptr<MechanicalLoad> imposeOnBoundary(const std::shared_ptr<Model>& model, const Linear& f) {
    KeywordSet kw;
    set(kw, "MODELE", model);
    auto& d = kw.addOccurrence("DDL_IMPO");
    setTexts(d, "GROUP_NO", {"BOUNDARY"});
    const char* names[] = {"DX", "DY", "DZ"};
    for (int c = 0; c < model->dim; ++c) set(d, names[c], ConceptPtr(component(f, c)));
    return std::dynamic_pointer_cast<MechanicalLoad>(run("AFFE_CHAR_MECA_F", kw, "CHAR"));
}

std::shared_ptr<Result> mecaStatique(const std::shared_ptr<Model>& model, const std::shared_ptr<MaterialField>& mat,
                                     const std::vector<std::shared_ptr<MechanicalLoad>>& loads,
                                     const std::string& method = "MUMPS") {
    KeywordSet kw;
    set(kw, "MODELE", model);
    set(kw, "CHAM_MATER", mat);
    for (const auto& l : loads) set(kw.addOccurrence("EXCIT"), "CHARGE", l);
    set(kw.addOccurrence("SOLVEUR"), "METHODE", method);
    return std::dynamic_pointer_cast<Result>(run("MECA_STATIQUE", kw, "RESU"));
}

double relErr(double a, double b, double scale) { return std::abs(a - b) / scale; }

// Checks DEPL at every node and SIEF_ELGA at every point of the last step.
void checkExact(const Result& res, const Model& model, const Linear& f, Modelisation mod) {
    const auto& step = res.steps.back();
    const auto depl = step.nodal("DEPL");
    const auto sief = step.gauss("SIEF_ELGA");
    ASSERT_TRUE(depl && sief);
    const Mesh& mesh = *model.mesh;
    const char* names[] = {"DX", "DY", "DZ"};
    double uscale = 0;
    for (int c = 0; c < model.dim; ++c)
        for (int j = 0; j < 3; ++j) uscale = std::max(uscale, std::abs(f.A[c][j]) * 2.0 + std::abs(f.c[c]));
    int checked = 0;
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        for (int c = 0; c < model.dim; ++c) {
            const int k = depl->componentIndex(names[c]);
            ASSERT_GE(k, 0);
            if (!depl->has(n, k)) continue;
            const auto& x = mesh.coords[n];
            const double exact = f.A[c][0] * x[0] + f.A[c][1] * x[1] + f.A[c][2] * x[2] + f.c[c];
            EXPECT_LT(relErr(depl->at(n, k), exact, uscale), 1e-12) << "node " << n << " " << names[c];
            ++checked;
        }
    }
    EXPECT_GT(checked, 0);
    const auto s = stressOf(f, model.dim, mod);
    double sscale = 0;
    for (double v : s) sscale = std::max(sscale, std::abs(v));
    const std::vector<std::string> comps =
        model.dim == 2 ? std::vector<std::string>{"SIXX", "SIYY", "SIZZ", "SIXY"}
                       : std::vector<std::string>{"SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ"};
    ASSERT_EQ(sief->components, comps);
    const size_t nc = comps.size();
    for (int p = 0; p < sief->pointCount(); ++p)
        for (size_t k = 0; k < nc; ++k)
            EXPECT_LT(relErr(sief->values[p * nc + k], s[k], sscale), 1e-12) << "point " << p << " " << comps[k];
    // Weights add up to the domain measure (L^dim with L = 2).
    double measure = 0;
    for (double w : sief->pointWeights) measure += w;
    EXPECT_NEAR(measure, std::pow(2.0, model.dim), 1e-12);
}

struct PatchCase {
    const char* name;
    bool threeD, simplices;
    const char* modelisation;
    Modelisation mod;
};

// STAT_NON_LINE's keywords for one load over the instants `insts`.
KeywordSet statNonLineKeywords(const ConceptPtr& model, const ConceptPtr& mat, const ConceptPtr& load,
                               std::vector<double> insts) {
    auto list = std::make_shared<RealList>();
    list->values = std::move(insts);
    KeywordSet s;
    set(s, "MODELE", model);
    set(s, "CHAM_MATER", mat);
    set(s.addOccurrence("EXCIT"), "CHARGE", load);
    set(s.addOccurrence("INCREMENT"), "LIST_INST", ConceptPtr(list));
    return s;
}

}  // namespace

class FePatchDdlImpo : public ::testing::TestWithParam<PatchCase> {};

TEST_P(FePatchDdlImpo, LinearFieldIsExact) {
    msg().setEcho(false);
    const auto& pc = GetParam();
    auto mesh = pc.threeD ? boxMesh(3, pc.simplices) : planeMesh(4, 3, pc.simplices);
    auto model = affeModele(mesh, pc.modelisation, {"ALL"});
    const Linear f = generalField(model->dim);
    auto mat = material(model, E, NU);
    auto res = mecaStatique(model, mat, {imposeOnBoundary(model, f)});
    ASSERT_EQ(res->steps.size(), 1u);
    EXPECT_EQ(res->steps[0].order, 1);
    EXPECT_EQ(res->steps[0].inst, 0.0);
    checkExact(*res, *model, f, pc.mod);
}

INSTANTIATE_TEST_SUITE_P(Elements, FePatchDdlImpo,
                         ::testing::Values(PatchCase{"QUAD4_D_PLAN", false, false, "D_PLAN", Modelisation::D_PLAN},
                                           PatchCase{"QUAD4_C_PLAN", false, false, "C_PLAN", Modelisation::C_PLAN},
                                           PatchCase{"TRIA3_C_PLAN", false, true, "C_PLAN", Modelisation::C_PLAN},
                                           PatchCase{"TRIA3_D_PLAN", false, true, "D_PLAN", Modelisation::D_PLAN},
                                           PatchCase{"HEXA8_3D", true, false, "3D", Modelisation::TRI_D},
                                           PatchCase{"TETRA4_3D", true, true, "3D", Modelisation::TRI_D}),
                         [](const auto& testInfo) { return std::string(testInfo.param.name); });

// Biaxial stress state from pressures: sigma_xx = -px, sigma_yy = -py (sigma_zz = -pz in 3D),
// rollers on the opposite sides.
class FePatchPressure : public ::testing::TestWithParam<PatchCase> {};

TEST_P(FePatchPressure, UniformPressureGivesExactStress) {
    msg().setEcho(false);
    const auto& pc = GetParam();
    const double px = 3.0e2, py = -1.2e2, pz = 0.7e2;  // py < 0: traction
    std::shared_ptr<Mesh> mesh;
    std::shared_ptr<Model> model;
    if (pc.threeD) {
        mesh = boxMesh(3, pc.simplices);
        model = affeModele(mesh, "3D", {"ALL", "XMAX", "YMAX", "ZMAX"});
    } else {
        mesh = planeMesh(4, 3, pc.simplices);
        model = affeModele(mesh, pc.modelisation, {"ALL", "RIGHT", "TOP"});
    }
    auto mat = material(model, E, NU);
    KeywordSet kw;
    set(kw, "MODELE", model);
    auto roller = [&](const char* group, const char* dof) {
        auto& d = kw.addOccurrence("DDL_IMPO");
        setTexts(d, "GROUP_MA", {group});
        set(d, dof, 0.0);
    };
    auto pressure = [&](const char* group, double p) {
        auto& d = kw.addOccurrence("PRES_REP");
        setTexts(d, "GROUP_MA", {group});
        set(d, "PRES", p);
    };
    if (pc.threeD) {
        roller("XMIN", "DX"), roller("YMIN", "DY"), roller("ZMIN", "DZ");
        pressure("XMAX", px), pressure("YMAX", py), pressure("ZMAX", pz);
    } else {
        roller("LEFT", "DX"), roller("BOTTOM", "DY");
        pressure("RIGHT", px), pressure("TOP", py);
    }
    auto load = std::dynamic_pointer_cast<MechanicalLoad>(run("AFFE_CHAR_MECA", kw, "CHAR"));
    auto res = mecaStatique(model, mat, {load});
    // Exact strains from the compliance.
    const int dim = model->dim;
    double s[3] = {-px, -py, pc.threeD ? -pz : 0.0};
    if (pc.mod == Modelisation::D_PLAN) s[2] = NU * (s[0] + s[1]);
    Linear f{};
    for (int i = 0; i < 3; ++i) f.A[i][i] = (s[i] - NU * (s[(i + 1) % 3] + s[(i + 2) % 3])) / E;
    if (dim == 2) f.A[2][2] = 0.0;
    checkExact(*res, *model, f, pc.mod);
}

INSTANTIATE_TEST_SUITE_P(Elements, FePatchPressure,
                         ::testing::Values(PatchCase{"QUAD4_D_PLAN", false, false, "D_PLAN", Modelisation::D_PLAN},
                                           PatchCase{"TRIA3_C_PLAN", false, true, "C_PLAN", Modelisation::C_PLAN},
                                           PatchCase{"HEXA8_3D", true, false, "3D", Modelisation::TRI_D},
                                           PatchCase{"TETRA4_3D", true, true, "3D", Modelisation::TRI_D}),
                         [](const auto& testInfo) { return std::string(testInfo.param.name); });

// Plane strain vs plane stress under the same imposed strain: SIZZ = nu (SIXX + SIYY) vs 0, and
// the in-plane stresses differ through the effective moduli exactly.
TEST(FePlaneModels, PlaneStrainAndPlaneStressDifferAsTheory) {
    msg().setEcho(false);
    auto mesh = planeMesh(3, 3, false);
    const Linear f = generalField(2);
    std::array<double, 4> s[2];
    int i = 0;
    for (const char* mod : {"D_PLAN", "C_PLAN"}) {
        auto model = affeModele(mesh, mod, {"ALL"});
        auto res = mecaStatique(model, material(model, E, NU), {imposeOnBoundary(model, f)});
        const auto sief = res->steps[0].gauss("SIEF_ELGA");
        for (int k = 0; k < 4; ++k) s[i][k] = sief->values[k];
        ++i;
    }
    EXPECT_NEAR(s[0][2], NU * (s[0][0] + s[0][1]), 1e-12 * std::abs(s[0][0]));
    EXPECT_EQ(s[1][2], 0.0);
    // Same shear (mu is the same), different normal stresses: sigma = lambda' tr + 2 mu eps.
    EXPECT_NEAR(s[0][3], s[1][3], 1e-12 * std::abs(s[0][3]));
    const double tr = f.A[0][0] + f.A[1][1];
    const double lambdaPlaneStrain = E * NU / ((1 + NU) * (1 - 2 * NU)), lambdaPlaneStress = E * NU / (1 - NU * NU);
    EXPECT_NEAR(s[0][0] - s[1][0], (lambdaPlaneStrain - lambdaPlaneStress) * tr, 1e-11 * std::abs(s[0][0]));
    EXPECT_NEAR(s[0][1] - s[1][1], (lambdaPlaneStrain - lambdaPlaneStress) * tr, 1e-11 * std::abs(s[0][0]));
}

// STAT_NON_LINE with 1 and with 4 increments of a ramp reach the same final state; order 0 is
// the initial state; CREA_CHAMP extracts the fields by NUME_ORDRE and by INST.
TEST(FeStatNonLine, OneAndFourIncrementsGiveTheSameFinalState) {
    msg().setEcho(false);
    auto mesh = planeMesh(4, 4, false);
    auto model = affeModele(mesh, "D_PLAN", {"ALL", "RIGHT", "TOP"});
    auto mat = material(model, E, NU);
    KeywordSet kw;
    set(kw, "MODELE", model);
    auto& d1 = kw.addOccurrence("DDL_IMPO");
    setTexts(d1, "GROUP_MA", {"LEFT"});
    set(d1, "DX", 0.0);
    auto& d2 = kw.addOccurrence("DDL_IMPO");
    setTexts(d2, "GROUP_MA", {"BOTTOM"});
    set(d2, "DY", 0.0);
    auto& p = kw.addOccurrence("PRES_REP");
    setTexts(p, "GROUP_MA", {"RIGHT", "TOP"});
    set(p, "PRES", 1.0e2);
    auto load = std::dynamic_pointer_cast<MechanicalLoad>(run("AFFE_CHAR_MECA", kw, "CHAR"));
    auto ramp = std::make_shared<TimeFunction>([](double t) { return t; });
    std::shared_ptr<Result> results[2];
    int r = 0;
    for (int steps : {1, 4}) {
        auto list = std::make_shared<RealList>();
        for (int i = 0; i <= steps; ++i) list->values.push_back(double(i) / steps);
        KeywordSet s;
        set(s, "MODELE", model);
        set(s, "CHAM_MATER", mat);
        auto& ex = s.addOccurrence("EXCIT");
        set(ex, "CHARGE", load);
        set(ex, "FONC_MULT", ConceptPtr(ramp));
        set(s.addOccurrence("INCREMENT"), "LIST_INST", ConceptPtr(list));
        auto& conv = s.addOccurrence("CONVERGENCE");
        set(conv, "RESI_GLOB_RELA", 1e-10);
        set(conv, "ITER_GLOB_MAXI", 5LL);
        results[r] = std::dynamic_pointer_cast<Result>(run("STAT_NON_LINE", s, "RESNL"));
        ASSERT_EQ(results[r]->steps.size(), size_t(steps + 1));
        EXPECT_EQ(results[r]->steps[0].order, 0);
        const auto u0 = results[r]->steps[0].nodal("DEPL");
        for (double v : u0->values) EXPECT_EQ(v, 0.0);
        ++r;
    }
    // Final state via CREA_CHAMP.
    auto extract = [&](const std::shared_ptr<Result>& res, bool byInst, const char* type, const char* field) {
        KeywordSet c;
        set(c, "OPERATION", std::string("EXTR"));
        set(c, "TYPE_CHAM", std::string(type));
        set(c, "RESULTAT", res);
        set(c, "NOM_CHAM", std::string(field));
        if (byInst) set(c, "INST", 1.0);
        else set(c, "NUME_ORDRE", static_cast<long long>(res->steps.back().order));
        return run("CREA_CHAMP", c, "CH");
    };
    auto u1 = std::dynamic_pointer_cast<NodalField>(extract(results[0], false, "NOEU_DEPL_R", "DEPL"));
    auto u4 = std::dynamic_pointer_cast<NodalField>(extract(results[1], true, "NOEU_DEPL_R", "DEPL"));
    ASSERT_TRUE(u1 && u4);
    ASSERT_EQ(u1->values.size(), u4->values.size());
    double scale = 0;
    for (double v : u1->values) scale = std::max(scale, std::abs(v));
    ASSERT_GT(scale, 0.0);
    for (size_t i = 0; i < u1->values.size(); ++i) EXPECT_NEAR(u1->values[i], u4->values[i], 1e-12 * scale);
    auto s1 = std::dynamic_pointer_cast<GaussField>(extract(results[0], false, "ELGA_SIEF_R", "SIEF_ELGA"));
    auto s4 = std::dynamic_pointer_cast<GaussField>(extract(results[1], true, "ELGA_SIEF_R", "SIEF_ELGA"));
    for (size_t i = 0; i < s1->values.size(); ++i) EXPECT_NEAR(s1->values[i], s4->values[i], 1e-10);
    EXPECT_NEAR(s1->values[0], -1.0e2, 1e-9);  // SIXX = -p
    // Wrong TYPE_CHAM for the field is refused.
    EXPECT_THROW(extract(results[0], false, "ELGA_SIEF_R", "DEPL"), UserError);
}

// Without enough Dirichlet conditions the system is singular: a clear NumericalError.
TEST(FeSingular, MissingBoundaryConditionIsReportedAsSingular) {
    msg().setEcho(false);
    for (const char* method : {"MUMPS", "MULT_FRONT"}) {
        auto mesh = planeMesh(3, 3, false);
        auto model = affeModele(mesh, "D_PLAN", {"ALL", "RIGHT"});
        auto mat = material(model, E, NU);
        KeywordSet kw;
        set(kw, "MODELE", model);
        auto& d = kw.addOccurrence("DDL_IMPO");
        setTexts(d, "GROUP_MA", {"LEFT"});
        set(d, "DX", 0.0);  // DY free everywhere: vertical rigid translation
        auto& p = kw.addOccurrence("PRES_REP");
        setTexts(p, "GROUP_MA", {"RIGHT"});
        set(p, "PRES", 1.0);
        auto load = std::dynamic_pointer_cast<MechanicalLoad>(run("AFFE_CHAR_MECA", kw, "CHAR"));
        try {
            mecaStatique(model, mat, {load}, method);
            ADD_FAILURE() << method << ": no error for a singular system";
        } catch (const NumericalError& e) {
            EXPECT_NE(std::string(e.what()).find("singular"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("boundary condition"), std::string::npos) << e.what();
        }
    }
}

// MUMPS and Eigen give the same solution (round-off).
TEST(FeSolvers, MumpsAndEigenAgree) {
    msg().setEcho(false);
    auto mesh = boxMesh(4, false);
    auto model = affeModele(mesh, "3D", {"ALL", "XMAX"});
    auto mat = material(model, E, NU);
    KeywordSet kw;
    set(kw, "MODELE", model);
    auto& d = kw.addOccurrence("DDL_IMPO");
    setTexts(d, "GROUP_MA", {"XMIN"});
    set(d, "DX", 0.0), set(d, "DY", 0.0), set(d, "DZ", 0.0);
    auto& p = kw.addOccurrence("FORCE_INTERNE");
    set(p, "TOUT", std::string("OUI"));
    set(p, "FZ", -10.0);
    auto load = std::dynamic_pointer_cast<MechanicalLoad>(run("AFFE_CHAR_MECA", kw, "CHAR"));
    auto a = mecaStatique(model, mat, {load}, "MUMPS")->steps[0].nodal("DEPL");
    auto b = mecaStatique(model, mat, {load}, "MULT_FRONT")->steps[0].nodal("DEPL");
    auto c = mecaStatique(model, mat, {load}, "LDLT")->steps[0].nodal("DEPL");
    double scale = 0;
    for (double v : a->values) scale = std::max(scale, std::abs(v));
    ASSERT_GT(scale, 1e-6);
    for (size_t i = 0; i < a->values.size(); ++i) {
        EXPECT_NEAR(a->values[i], b->values[i], 1e-11 * scale);
        EXPECT_NEAR(a->values[i], c->values[i], 1e-11 * scale);
    }
}

// A two-term relation (Lagrange multiplier path): DY(corner) + DY(top-left corner) = 2 v0
// replaces the point support of a pressure-loaded plate; the solution is exact.
TEST(FeRelations, TwoTermRelationIsImposedExactly) {
    msg().setEcho(false);
    for (const char* method : {"MUMPS", "MULT_FRONT"}) {
        auto mesh = planeMesh(4, 4, true);
        auto model = affeModele(mesh, "C_PLAN", {"ALL", "RIGHT"});
        auto mat = material(model, E, NU);
        KeywordSet kw;
        set(kw, "MODELE", model);
        auto& d = kw.addOccurrence("DDL_IMPO");
        setTexts(d, "GROUP_MA", {"LEFT"});
        set(d, "DX", 0.0);
        auto& p = kw.addOccurrence("PRES_REP");
        setTexts(p, "GROUP_MA", {"RIGHT"});
        set(p, "PRES", -50.0);
        auto load = std::dynamic_pointer_cast<MechanicalLoad>(run("AFFE_CHAR_MECA", kw, "CHAR"));
        const double v0 = 1e-3;
        const int bl = mesh->nodeGroups.get("CORNER")[0], tl = mesh->nodeGroups.get("CORNER_TL")[0];
        std::const_pointer_cast<MechanicalLoad>(load)->relations.push_back(
            {{{bl, "DY", 1.0}, {tl, "DY", 1.0}}, 2 * v0});
        auto res = mecaStatique(model, mat, {load}, method);
        const double sxx = 50.0;
        Linear f{};
        f.A[0][0] = sxx / E;
        f.A[1][1] = -NU * sxx / E;
        f.c[1] = v0 - f.A[1][1] * 2.0 / 2;  // u_y(0) + u_y(L) = 2 v0 with L = 2
        checkExact(*res, *model, f, Modelisation::C_PLAN);
    }
}

// Errors a user can make.
TEST(FeErrors, ClearMessages) {
    msg().setEcho(false);
    auto mesh = planeMesh(2, 2, false);
    // Unknown group.
    EXPECT_THROW(affeModele(mesh, "D_PLAN", {"NOPE"}), UserError);
    // NU = 0.5 in plane strain.
    auto model = affeModele(mesh, "D_PLAN", {"ALL"});
    auto mat = material(model, E, 0.5);
    KeywordSet kw;
    set(kw, "MODELE", model);
    auto& d = kw.addOccurrence("DDL_IMPO");
    setTexts(d, "GROUP_NO", {"BOUNDARY"});
    set(d, "DX", 0.0), set(d, "DY", 0.0);
    auto load = std::dynamic_pointer_cast<MechanicalLoad>(run("AFFE_CHAR_MECA", kw, "CHAR"));
    try {
        mecaStatique(model, mat, {load});
        ADD_FAILURE() << "NU = 0.5 accepted in D_PLAN";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("incompressible"), std::string::npos) << e.what();
    }
    // DZ in a plane model.
    KeywordSet k2;
    set(k2, "MODELE", model);
    auto& d2 = k2.addOccurrence("DDL_IMPO");
    setTexts(d2, "GROUP_NO", {"BOUNDARY"});
    set(d2, "DZ", 0.0);
    EXPECT_THROW(run("AFFE_CHAR_MECA", k2, "CHAR"), UserError);
    // A quadratic cell in the model.
    auto m2 = planeMesh(1, 1, false);
    m2->addCell(CellType::TRIA6, std::vector<int>{0, 1, 2, 0, 1, 2});
    m2->cellGroups.set("Q", {m2->cellCount() - 1});
    try {
        affeModele(m2, "D_PLAN", {"Q"});
        ADD_FAILURE() << "TRIA6 accepted";
    } catch (const NotImplemented& e) {
        EXPECT_NE(std::string(e.what()).find("TRIA6"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("GROUP_MA=Q"), std::string::npos) << e.what();
    }
}

// Non-convergence is never silenced: NumericalError with ARRET='OUI', alarm and continue with
// ARRET='NON' (here an unreachable RESI_GLOB_MAXI).
TEST(FeStatNonLine, NonConvergenceStopsOrAlarms) {
    msg().setEcho(false);
    auto mesh = planeMesh(3, 3, false);
    auto model = affeModele(mesh, "D_PLAN", {"ALL", "RIGHT"});
    auto mat = material(model, E, NU);
    KeywordSet kw;
    set(kw, "MODELE", model);
    auto& d = kw.addOccurrence("DDL_IMPO");
    setTexts(d, "GROUP_MA", {"LEFT"});
    set(d, "DX", 0.0), set(d, "DY", 0.0);
    auto& p = kw.addOccurrence("PRES_REP");
    setTexts(p, "GROUP_MA", {"RIGHT"});
    set(p, "PRES", 1.0e3);
    auto load = run("AFFE_CHAR_MECA", kw, "CHAR");
    for (const char* arret : {"OUI", "NON"}) {
        KeywordSet s = statNonLineKeywords(model, mat, load, {0.0, 1.0, 2.0});
        auto& conv = s.addOccurrence("CONVERGENCE");
        set(conv, "RESI_GLOB_MAXI", 1e-300);
        set(conv, "ITER_GLOB_MAXI", 2LL);
        set(conv, "ARRET", arret[0] == 'O' ? std::string("OUI") : std::string("NON"));
        const int alarmsBefore = msg().alarmCount();
        if (arret[0] == 'O') {
            try {
                run("STAT_NON_LINE", s, "RESNL");
                ADD_FAILURE() << "non-convergence not reported";
            } catch (const NumericalError& e) {
                EXPECT_NE(std::string(e.what()).find("did not converge"), std::string::npos) << e.what();
            }
        } else {
            auto res = std::dynamic_pointer_cast<Result>(run("STAT_NON_LINE", s, "RESNL"));
            EXPECT_EQ(res->steps.size(), 3u);
            EXPECT_EQ(msg().alarmCount(), alarmsBefore + 2);  // one per increment
        }
    }
}

// A rigid translation imposed on two sides and no load: the reactions are zero, and an iterative
// solver's answer leaves them at its tolerance's noise (CG + JACOBI at RESI_RELA = 1e-8 here), far
// above round-off. That noise is no load: RESI_GLOB_RELA is taken against the elastic force scale
// and the first Newton iteration converges, where measuring it against the noise asked for more.
TEST(FeStatNonLine, RigidMotionSolvedByKrylovConvergesAtOnce) {
    msg().setEcho(false);
    auto mesh = planeMesh(30, 30, false);
    auto model = affeModele(mesh, "D_PLAN", {"ALL", "RIGHT"});
    auto mat = material(model, E, NU);
    KeywordSet kw;
    set(kw, "MODELE", model);
    auto& d = kw.addOccurrence("DDL_IMPO");
    setTexts(d, "GROUP_MA", {"LEFT", "RIGHT"});
    set(d, "DX", 0.5), set(d, "DY", -0.25);
    auto load = run("AFFE_CHAR_MECA", kw, "CHAR");
    KeywordSet s = statNonLineKeywords(model, mat, load, {0.0, 1.0});
    auto& solver = s.addOccurrence("SOLVEUR");
    set(solver, "METHODE", std::string("PETSC")), set(solver, "ALGORITHME", std::string("CG"));
    set(solver, "PRE_COND", std::string("JACOBI")), set(solver, "RESI_RELA", 1e-8);
    const size_t from = msg().messText().size();
    auto res = std::dynamic_pointer_cast<Result>(run("STAT_NON_LINE", s, "RESNL"));
    const std::string mess = msg().messText().substr(from);
    EXPECT_NE(mess.find("below 1e-06 of it): RESI_GLOB_RELA is taken relative to the force scale"), std::string::npos)
        << mess;
    EXPECT_NE(mess.find("INST 1: converged after 1 iteration(s)"), std::string::npos) << mess;
    const auto depl = res->steps.back().nodal("DEPL");
    ASSERT_TRUE(depl);
    double gap = 0.0;
    for (int n = 0; n < mesh->nodeCount(); ++n)
        gap = std::max({gap, std::abs(depl->at(n, 0) - 0.5), std::abs(depl->at(n, 1) + 0.25)});
    EXPECT_LT(gap, 1e-6);
}

// MECA_STATIQUE with LIST_INST cut by INST_FIN and a FONC_MULT: one order per instant, each a
// linear solve scaled by the multiplier; CREA_CHAMP refuses a missing order.
TEST(FeMecaStatique, ListInstAndFoncMult) {
    msg().setEcho(false);
    auto mesh = planeMesh(2, 2, false);
    auto model = affeModele(mesh, "C_PLAN", {"ALL", "RIGHT"});
    auto mat = material(model, E, NU);
    KeywordSet kw;
    set(kw, "MODELE", model);
    auto& d = kw.addOccurrence("DDL_IMPO");
    setTexts(d, "GROUP_MA", {"LEFT"});
    set(d, "DX", 0.0);
    auto& c = kw.addOccurrence("DDL_IMPO");
    setTexts(c, "GROUP_NO", {"CORNER"});
    set(c, "DY", 0.0);
    auto& p = kw.addOccurrence("PRES_REP");
    setTexts(p, "GROUP_MA", {"RIGHT"});
    set(p, "PRES", -100.0);
    auto load = run("AFFE_CHAR_MECA", kw, "CHAR");
    auto list = std::make_shared<RealList>();
    list->values = {0.0, 0.5, 1.0, 2.0};
    KeywordSet s;
    set(s, "MODELE", model);
    set(s, "CHAM_MATER", mat);
    auto& ex = s.addOccurrence("EXCIT");
    set(ex, "CHARGE", load);
    set(ex, "FONC_MULT", ConceptPtr(std::make_shared<TimeFunction>([](double t) { return 3.0 * t; })));
    set(s, "LIST_INST", ConceptPtr(list));
    set(s, "INST_FIN", 1.0);
    auto res = std::dynamic_pointer_cast<Result>(run("MECA_STATIQUE", s, "RESU"));
    ASSERT_EQ(res->steps.size(), 3u);
    const double strain = 3.0 * 100.0 / E;  // sigma_xx = 3 t * 100 at t = 1
    const int right = mesh->cellNodes(mesh->cellGroups.get("RIGHT").front())[0];
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(res->steps[k].order, k + 1);
        const auto u = res->steps[k].nodal("DEPL");
        EXPECT_NEAR(u->at(right, 0), 2.0 * strain * list->values[k], 1e-14);
    }
    KeywordSet bad;
    set(bad, "OPERATION", std::string("EXTR"));
    set(bad, "TYPE_CHAM", std::string("NOEU_DEPL_R"));
    set(bad, "RESULTAT", res);
    set(bad, "NOM_CHAM", std::string("DEPL"));
    set(bad, "NUME_ORDRE", 7LL);
    EXPECT_THROW(run("CREA_CHAMP", bad, "CH"), UserError);
}
