// CALC_CHAMP CONTRAINTE on ssnv511e's X-FEM result (three interfaces with junctions, contact): the
// fields stored in the result are read by TEST_RESU and CREA_CHAMP, printed in MED and read back
// by mdump4 and by miniaster's MED reader with the exact stresses of the four blocks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "med_io/MedResultReader.hpp"
#include "med_test_support.hpp"
#include "parser_run.hpp"

namespace fs = std::filesystem;

namespace {

const char* kCalcChamp =
    "UTOT1=CALC_CHAMP(reuse=UTOT1, RESULTAT=UTOT1, CONTRAINTE=('SIGM_ELGA','SIGM_ELNO','SIGM_NOEU'))\n"
    "IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(RESULTAT=UTOT1, NOM_CHAM=('SIGM_ELGA','SIGM_ELNO','SIGM_NOEU')))\n"
    "SN=CREA_CHAMP(TYPE_CHAM='NOEU_SIEF_R', OPERATION='EXTR', RESULTAT=UTOT1, NOM_CHAM='SIGM_NOEU', NUME_ORDRE=1)\n"
    "SE=CREA_CHAMP(TYPE_CHAM='ELNO_SIEF_R', OPERATION='EXTR', RESULTAT=UTOT1, NOM_CHAM='SIGM_ELNO', NUME_ORDRE=1)\n"
    "TEST_RESU(RESU=(_F(RESULTAT=UTOT1, NOM_CHAM='SIGM_NOEU', NUME_ORDRE=1, NOM_CMP='SIXX', TYPE_TEST='MIN',\n"
    "                   VALE_CALC=-2.E6, VALE_REFE=-2.E6, REFERENCE='ANALYTIQUE', PRECISION=1.E-9),\n"
    "                _F(RESULTAT=UTOT1, NOM_CHAM='SIGM_NOEU', NUME_ORDRE=1, NOM_CMP='SIYY', TYPE_TEST='MAX',\n"
    "                   VALE_CALC=-1.E6, VALE_REFE=-1.E6, REFERENCE='ANALYTIQUE', PRECISION=1.E-9),\n"
    "                _F(RESULTAT=UTOT1, NOM_CHAM='SIGM_ELGA', NUME_ORDRE=1, NOM_CMP='SIXY', TYPE_TEST='MAX',\n"
    "                   VALE_CALC=0., VALE_REFE=0., REFERENCE='ANALYTIQUE', CRITERE='ABSOLU', PRECISION=1.E-3)))\n";

class CalcChampSsnv511e : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = fs::temp_directory_path() / ("miniaster-calc-champ." + std::to_string(getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        ma::test::writeText(dir_ / "t.comm",
                            ma::test::beforeFin(ma::test::readText(ma::test::astest("ssnv511e.comm")), kCalcChamp));
        run_ = ma::test::runMiniaster(dir_, "t.comm", "--mesh '" + ma::test::astest("ssnv511a.mmed") + "'");
    }
    static void TearDownTestSuite() { fs::remove_all(dir_); }
    static fs::path dir_;
    static ma::test::RunResult run_;
};
fs::path CalcChampSsnv511e::dir_;
ma::test::RunResult CalcChampSsnv511e::run_;

// The exact plane-strain state of the block holding (x, y): the pressure of the loaded side of
// each direction, 2 MPa above / right of the interfaces, 1 MPa below / left (ssnv511e's ux*, uy*).
std::array<double, 4> exactStress(double x, double y) {
    const double sxx = y > 0 ? -2e6 : -1e6, syy = x > 0 ? -2e6 : -1e6;
    return {sxx, syy, 0.3 * (sxx + syy), 0.0};
}

TEST_F(CalcChampSsnv511e, TestResuReadsTheStoredFields) {
    // Exit 2: ssnv511e's own inexact NON_REGRESSION values (README); ours are all OK.
    ASSERT_EQ(run_.status, 2) << run_.output;
    const std::string resu = run_.file("out/t.resu");
    EXPECT_NE(resu.find("UTOT1            1                SIGM_NOEU        MIN              SIXX"), std::string::npos);
    EXPECT_EQ(resu.find("NOOK  ANALYTIQUE"), std::string::npos) << resu;
    EXPECT_NE(resu.find(" OK   ANALYTIQUE"), std::string::npos) << resu;
    EXPECT_NE(run_.file("out/t.mess").find("SIGM_ELGA, SIGM_ELNO, SIGM_NOEU computed at 2 order(s) of UTOT1"),
              std::string::npos);
}

TEST_F(CalcChampSsnv511e, SigmNoeuIsTheExactBlockStateAtEveryNode) {
    ASSERT_EQ(run_.status, 2) << run_.output;
    const auto meshes = ma::med::readResults((dir_ / "out/fort.80").string());
    ASSERT_EQ(meshes.size(), 1u);
    const auto& mesh = *meshes[0].mesh;
    int checked = 0, elnoChecked = 0;
    for (const auto& field : meshes[0].fields) {
        ASSERT_EQ(field.steps.size(), 2u) << field.name;
        const auto& last = field.steps[1];
        if (field.name == "UTOT1___SIGM_ELGA") {
            ASSERT_TRUE(last.cellPoints);
            EXPECT_FALSE(last.cellPoints->atNodes);
        } else if (field.name == "UTOT1___SIGM_NOEU") {
            ASSERT_TRUE(last.nodal);
            for (int n = 0; n < mesh.nodeCount(); ++n) {
                const auto exact = exactStress(mesh.coords[size_t(n)][0], mesh.coords[size_t(n)][1]);
                for (int c = 0; c < 4; ++c, ++checked)
                    EXPECT_NEAR(last.nodal->at(n, c), exact[size_t(c)], 2e6 * 1e-9) << "node " << n << " cmp " << c;
            }
        } else if (field.name == "UTOT1___SIGM_ELNO") {
            ASSERT_TRUE(last.cellPoints);
            const auto& g = *last.cellPoints;
            EXPECT_TRUE(g.atNodes);  // read from MED_NODE_ELEMENT
            for (size_t e = 0; e < g.cells.size(); ++e) {
                const auto nodes = mesh.cellNodes(g.cells[e]);
                ASSERT_EQ(g.pointOffsets[e + 1] - g.pointOffsets[e], int(nodes.size()));
                for (size_t a = 0; a < nodes.size(); ++a) {
                    // MED node order = internal order for QUAD4.
                    const auto& x = mesh.coords[size_t(nodes[a])];
                    const auto exact = exactStress(x[0], x[1]);
                    const size_t row = (size_t(g.pointOffsets[e]) + a) * 4;
                    for (int c = 0; c < 4; ++c, ++elnoChecked)
                        EXPECT_NEAR(g.values[row + size_t(c)], exact[size_t(c)], 2e6 * 1e-9);
                }
            }
        }
    }
    EXPECT_EQ(checked, 36 * 4);
    EXPECT_EQ(elnoChecked, 25 * 4 * 4);
}

TEST_F(CalcChampSsnv511e, Mdump4ReadsTheFieldsWithTheirEntities) {
    ASSERT_EQ(run_.status, 2) << run_.output;
    const std::string dump = ma::test::runCommand("timeout 60 mdump4 '" + (dir_ / "out/fort.80").string() +
                                                  "' NODALE FULL_INTERLACE 0 </dev/null");
    EXPECT_NE(dump.find("CHAMP |UTOT1___SIGM_NOEU|"), std::string::npos);
    EXPECT_NE(dump.find("CHAMP |UTOT1___SIGM_ELGA|"), std::string::npos);
    EXPECT_NE(dump.find("CHAMP |UTOT1___SIGM_ELNO|"), std::string::npos);
    EXPECT_NE(dump.find("MED_NOEUD_MAILLE de type geometrique MED_QUAD4"), std::string::npos);
    EXPECT_NE(dump.find("-2000000.000000  -2000000.000000  -1200000.000000"), std::string::npos);
}

// MECA_STATIQUE on a classical QUAD4 model (fe_patch_quad4's RES2: the uniform state SIXX = -p1,
// SIYY = -p2): a new result without reuse=, NUME_ORDRE and GROUP_MA, its MED file read back by
// `miniaster convert`.
TEST(CalcChampClassical, PatchTestStressesAtNodesAndInTheMedFile) {
    const auto dir = ma::test::freshDir();
    const std::string comm = ma::test::readText(std::string(MINIASTER_SOURCE_DIR) + "/astest/fe_patch_quad4.comm");
    const std::string extra =
        "R2 = CALC_CHAMP(RESULTAT=RES2, NUME_ORDRE=1, GROUP_MA='SURF', CONTRAINTE=('SIGM_NOEU', 'SIEF_ELNO'))\n"
        "TEST_RESU(RESU=(_F(RESULTAT=R2, NOM_CHAM='SIGM_NOEU', NUME_ORDRE=1, NOM_CMP='SIXX', TYPE_TEST='MIN',\n"
        "                   VALE_CALC=-2.E6, VALE_REFE=-2.E6, REFERENCE='ANALYTIQUE', PRECISION=1.E-9),\n"
        "                _F(RESULTAT=R2, NOM_CHAM='SIGM_NOEU', NUME_ORDRE=1, NOM_CMP='SIXX', TYPE_TEST='MAX',\n"
        "                   VALE_CALC=-2.E6, VALE_REFE=-2.E6, REFERENCE='ANALYTIQUE', PRECISION=1.E-9),\n"
        "                _F(RESULTAT=R2, NOM_CHAM='SIGM_NOEU', NUME_ORDRE=1, NOM_CMP='SIYY', TYPE_TEST='MAX',\n"
        "                   VALE_CALC=0.5E6, VALE_REFE=0.5E6, REFERENCE='ANALYTIQUE', PRECISION=1.E-9)))\n"
        "IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(RESULTAT=R2, NOM_CHAM=('SIGM_NOEU', 'SIEF_ELNO')))\n";
    ma::test::writeText(dir / "t.comm", ma::test::beforeFin(comm, extra));
    const auto r =
        ma::test::runMiniaster(dir, "t.comm",
                               "--mesh '" + std::string(MINIASTER_SOURCE_DIR) + "/astest/fe_patch_quad4.mmed'");
    ASSERT_EQ(r.status, 0) << r.output << r.file("out/t.mess");
    const std::string resu = r.file("out/t.resu");
    EXPECT_NE(resu.find("R2               1                SIGM_NOEU        MAX              SIYY"), std::string::npos)
        << resu;
    EXPECT_EQ(resu.find("NOOK"), std::string::npos) << resu;
    // RES2 itself keeps only its own fields.
    const auto meshes = ma::med::readResults((dir / "out/fort.80").string());
    ASSERT_EQ(meshes.size(), 1u);
    ASSERT_EQ(meshes[0].fields.size(), 2u);
    const auto noeu = std::find_if(meshes[0].fields.begin(), meshes[0].fields.end(),
                                   [](const auto& f) { return f.name == "R2______SIGM_NOEU"; });
    ASSERT_NE(noeu, meshes[0].fields.end());
    const auto& values = *noeu->steps.at(0).nodal;
    for (int n = 0; n < values.mesh->nodeCount(); ++n) EXPECT_NEAR(values.at(n, 0), -2e6, 2e-3) << n;
    int status = 0;
    const std::string out =
        ma::test::runCommand(std::string(MINIASTER_BINARY) + " convert '" + (dir / "out/fort.80").string() + "' '" +
                                 (dir / "r2.vtu").string() + "' 2>&1",
                             &status);
    EXPECT_EQ(status, 0) << out;
    const std::string vtu = ma::test::readText((dir / "r2.vtu").string());
    EXPECT_NE(vtu.find("SIGM_NOEU"), std::string::npos) << out;
    EXPECT_NE(vtu.find("SIEF_ELNO"), std::string::npos) << out;
}

// What miniaster's CALC_CHAMP does not compute is refused by the static check, before any command.
TEST(CalcChampStatic, UnsupportedOptionsAreRefusedBeforeTheSolve) {
    const auto dir = ma::test::freshDir();
    const std::string comm = ma::test::readText(ma::test::astest("ssnv511e.comm"));
    const std::string extra =
        "UTOT1=CALC_CHAMP(reuse=UTOT1, RESULTAT=UTOT1, CONTRAINTE='SIGM_NOEU', ENERGIE='EPOT_ELEM')\n"
        "R=CALC_CHAMP(RESULTAT=UTOT1, CONTRAINTE='EFGE_ELNO')\n";
    ma::test::writeText(dir / "t.comm", ma::test::beforeFin(comm, extra));
    const auto r = ma::test::runMiniaster(dir, "t.comm", "--mesh '" + ma::test::astest("ssnv511a.mmed") + "'");
    EXPECT_EQ(r.status, 1) << r.output;
    const std::string mess = r.file("out/t.mess");
    EXPECT_NE(mess.find("problems found in the command file before its first command (none was run)"),
              std::string::npos)
        << mess;
    EXPECT_NE(mess.find(": CALC_CHAMP: keyword ENERGIE is not supported by miniaster (miniaster's CALC_CHAMP computes "
                        "CONTRAINTE"),
              std::string::npos)
        << mess;
    EXPECT_NE(mess.find(": CALC_CHAMP: keyword CONTRAINTE: value 'EFGE_ELNO' is not supported by miniaster"),
              std::string::npos)
        << mess;
    EXPECT_EQ(mess.find("STAT_NON_LINE("), std::string::npos);  // nothing ran
}

}  // namespace
