// TEST_RESU through the binary on ssnv511a's mesh (a 6 x 6 grid of nodes from -5 to 5, 25 QUAD4 in
// SURF) with the displacement imposed at every node: DX = 1e-3 (X + 2), DY = 2e-3 Y, so DEPL is known
// exactly at every node and SIEF_ELGA is the uniform state of that strain (E = 1e8, NU = 0.3, D_PLAN:
// SIXX = 250000, SIYY = 326923.0769..., SIZZ = 173076.9230..., SIXY = 0).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "parser_run.hpp"

using namespace ma::test;

namespace {

const std::string kMesh = std::string("--mesh '") + MINIASTER_SHARED_DIR + "/astest/ssnv511a.mmed'";

const std::string kScene = R"(DEBUT()
MA = LIRE_MAILLAGE(FORMAT='MED')
MA = DEFI_GROUP(reuse=MA, MAILLAGE=MA, CREA_GROUP_NO=_F(GROUP_MA='SURF', NOM='TOUS'))
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA='SURF', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
MAT = DEFI_MATERIAU(ELAS=_F(E=100.0E6, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))
UX = FORMULE(VALE='1.e-3*(X+2.)', NOM_PARA=['X', 'Y'])
UY = FORMULE(VALE='2.e-3*Y', NOM_PARA=['X', 'Y'])
CH = AFFE_CHAR_MECA_F(MODELE=MO, DDL_IMPO=_F(GROUP_MA='SURF', DX=UX, DY=UY))
U = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH))
UN = CREA_CHAMP(OPERATION='EXTR', TYPE_CHAM='NOEU_DEPL_R', RESULTAT=U, NOM_CHAM='DEPL', NUME_ORDRE=1)
SI = CREA_CHAMP(OPERATION='EXTR', TYPE_CHAM='ELGA_SIEF_R', RESULTAT=U, NOM_CHAM='SIEF_ELGA', NUME_ORDRE=1)
T = POST_RELEVE_T(ACTION=_F(INTITULE='U', GROUP_NO='TOUS', RESULTAT=U, NOM_CHAM='DEPL', NUME_ORDRE=1,
                            TOUT_CMP='OUI', OPERATION='EXTRACTION'))
IMPR_TABLE(TABLE=T, UNITE=38, NOM_PARA=('NOEUD', 'COOR_X', 'COOR_Y', 'DX', 'DY'), FORMAT_R='E25.17')
)";

RunResult run(const std::string& tests) { return runComm(kScene + tests + "FIN()\n", kMesh); }

struct Row {
    std::string node;
    double x, y, dx, dy;
};

// The POST_RELEVE_T table written to unit 38: every node of the mesh with its DX, DY.
std::vector<Row> table(const RunResult& r) {
    std::istringstream in(r.file("out/fort.38"));
    std::vector<Row> rows;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        Row row;
        if (line.rfind("N", 0) == 0 && fields >> row.node >> row.x >> row.y >> row.dx >> row.dy) rows.push_back(row);
    }
    return rows;
}

int count(const std::string& text, const std::string& what) {
    int n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

// MIN / MAX / SOMM / SOMM_ABS over DX, SOMM_ABS over every component, on the result (RESU) and on the
// extracted field (CHAM_NO), against the sums of the POST_RELEVE_T table computed here.
TEST(TestResu, EachTypeTestOverTheNodalField) {
    auto r = run(R"(
for typ, val in (('MIN', -3.e-3), ('MAX', 7.e-3), ('SOMM', 0.072), ('SOMM_ABS', 0.120)):
    TEST_RESU(RESU=_F(RESULTAT=U, NUME_ORDRE=1, NOM_CHAM='DEPL', TYPE_TEST=typ, NOM_CMP='DX', VALE_CALC=val,
                      REFERENCE='ANALYTIQUE', VALE_REFE=val, PRECISION=1e-12),
              CHAM_NO=_F(CHAM_GD=UN, TYPE_TEST=typ, NOM_CMP='DX', VALE_CALC=val))
TEST_RESU(RESU=(_F(RESULTAT=U, INST=0., NOM_CHAM='DEPL', TYPE_TEST='SOMM_ABS', VALE_CALC=0.336,
                   REFERENCE='ANALYTIQUE', VALE_REFE=0.336, PRECISION=1e-12),
                _F(RESULTAT=U, NUME_ORDRE=1, NOM_CHAM='DEPL', TYPE_TEST='MAX', NOM_CMP='DY', GROUP_NO='P1',
                   VALE_CALC=1.e-2)),
          CHAM_NO=_F(CHAM_GD=UN, TYPE_TEST='SOMM', VALE_CALC=0.072))
)");
    ASSERT_EQ(r.status, 0) << r.output;
    const auto rows = table(r);
    ASSERT_EQ(rows.size(), 36u);
    double mn = 1e300, mx = -1e300, sum = 0, sumAbs = 0, all = 0;
    for (const auto& row : rows) {
        EXPECT_NEAR(row.dx, 1e-3 * (row.x + 2), 1e-15) << row.node;
        mn = std::min(mn, row.dx);
        mx = std::max(mx, row.dx);
        sum += row.dx;
        sumAbs += std::abs(row.dx);
        all += std::abs(row.dx) + std::abs(row.dy);
    }
    EXPECT_NEAR(mn, -3e-3, 1e-15);
    EXPECT_NEAR(mx, 7e-3, 1e-15);
    EXPECT_NEAR(sum, 0.072, 1e-14);
    EXPECT_NEAR(sumAbs, 0.120, 1e-14);
    EXPECT_NEAR(all, 0.336, 1e-14);
    const std::string resu = r.file("out/t.resu");
    EXPECT_EQ(count(resu, "\n OK   NON_REGRESSION"), 11) << resu;
    EXPECT_EQ(count(resu, "\n OK   ANALYTIQUE"), 5) << resu;
    EXPECT_EQ(count(resu, "NOOK"), 0) << resu;
    EXPECT_NE(r.output.find("reference checks                 5        0      0"), std::string::npos) << r.output;
    // TYPE_TEST with a place: the place is ignored, with code_aster's alarm.
    EXPECT_NE(r.output.find("<A> <CALCULEL6_96>"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("RESU[2]: TYPE_TEST tests a quantity computed over the whole field; GROUP_NO is not taken"),
              std::string::npos)
        << r.output;
}

// One value at a node (NOEUD, GROUP_NO of one node) and at an integration point (MAILLE + POINT),
// against the imposed displacement and the uniform stress.
TEST(TestResu, ValuesAtANodeAndAtAPoint) {
    auto r = run(R"(
TEST_RESU(RESU=(_F(RESULTAT=U, NUME_ORDRE=1, NOM_CHAM='DEPL', NOEUD='N1', NOM_CMP='DX', VALE_CALC=-3.e-3,
                   REFERENCE='ANALYTIQUE', VALE_REFE=-3.e-3, PRECISION=1e-12),
                _F(RESULTAT=U, NUME_ORDRE=1, NOM_CHAM='DEPL', GROUP_NO='P1', NOM_CMP='DY', VALE_CALC=-1.e-2,
                   REFERENCE='ANALYTIQUE', VALE_REFE=-1.e-2, PRECISION=1e-12),
                _F(RESULTAT=U, NUME_ORDRE=1, NOM_CHAM='SIEF_ELGA', MAILLE='M1', POINT=3, NOM_CMP='SIYY',
                   VALE_CALC=326923.07692307692, REFERENCE='ANALYTIQUE', VALE_REFE=326923.07692307692,
                   PRECISION=1e-10)),
          CHAM_NO=_F(CHAM_GD=UN, NOEUD='N1', NOM_CMP='DY', VALE_CALC=-1.e-2),
          CHAM_ELEM=(_F(CHAM_GD=SI, MAILLE='M1', POINT=1, NOM_CMP='SIXX', VALE_CALC=250000.,
                        REFERENCE='ANALYTIQUE', VALE_REFE=250000., PRECISION=1e-10),
                     _F(CHAM_GD=SI, TYPE_TEST='SOMM', NOM_CMP='SIXX', VALE_CALC=2.5e7,
                        REFERENCE='ANALYTIQUE', VALE_REFE=2.5e7, PRECISION=1e-10),
                     _F(CHAM_GD=SI, TYPE_TEST='MAX', NOM_CMP='SIZZ', VALE_CALC=173076.92307692308,
                        REFERENCE='ANALYTIQUE', VALE_REFE=173076.92307692308, PRECISION=1e-10)))
T1 = POST_RELEVE_T(ACTION=_F(INTITULE='P1', GROUP_NO='P1', RESULTAT=U, NOM_CHAM='DEPL', NUME_ORDRE=1, NOM_CMP='DY',
                             OPERATION='EXTRACTION'))
IMPR_TABLE(TABLE=T1, UNITE=39, NOM_PARA=('NOEUD', 'COOR_X', 'COOR_Y', 'DX', 'DY'), FORMAT_R='E25.17')
)");
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string resu = r.file("out/t.resu");
    EXPECT_EQ(count(resu, "NOOK"), 0) << resu;
    EXPECT_EQ(count(resu, "\n OK   ANALYTIQUE"), 6) << resu;
    // P1, the one node of its group, is at Y = -5: DY = 2e-3 Y = -1e-2 as tested above.
    const std::string p1 = r.file("out/fort.39");
    const std::regex row(R"(\n(N\d+) +(\S+) +(\S+))");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(p1, m, row)) << p1;
    EXPECT_EQ(std::stod(m[3]), -5.0) << p1;
}

// The text of each kind of block, written by hand from code_aster's Fortran: trresu builds two lines
// of 17-column fields after a 21-column "---- RESULTAT" / "     <name>" start (NUME_ORDRE, NOM_CHAM,
// then NOM_CMP, NOEUD or TYPE_TEST, NOM_CMP), written with list-directed output (a leading blank);
// trchno starts with NOM_CMP, then TYPE_TEST and tresu_champ_cmp's second NOM_CMP; trchel writes its
// label line with format (A) (no leading blank) and no blank line after a TYPE_TEST occurrence;
// tresu_print's check lines follow (4 + 2 + 16 + 1 + 16 + 1, then value columns of max(16, len) + 2).
TEST(TestResu, PrintsCodeAsterLayout) {
    auto r = run(R"(
TEST_RESU(RESU=_F(RESULTAT=U, NUME_ORDRE=1, NOM_CHAM='DEPL', NOEUD='N1', NOM_CMP='DX', VALE_CALC=-3.e-3,
                  CRITERE='ABSOLU', LEGENDE='au noeud N1'),
          CHAM_NO=_F(CHAM_GD=UN, TYPE_TEST='MAX', NOM_CMP='DX', VALE_CALC=7.e-3, CRITERE='ABSOLU'),
          CHAM_ELEM=(_F(CHAM_GD=SI, TYPE_TEST='SOMM', NOM_CMP='SIXY', VALE_CALC=0., ORDRE_GRANDEUR=100.,
                        CRITERE='ABSOLU'),
                     _F(CHAM_GD=SI, MAILLE='M1', POINT=2, NOM_CMP='SIXX', VALE_CALC=250000., VALE_ABS='OUI')))
)");
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string resu = r.file("out/t.resu");
    const std::string labels =
        "      REFERENCE        LEGENDE          VALE_REFE          VALE_CALC          ERREUR           TOLE"
        "            \n";
    const std::string expected =
        "\n" + std::string(80, '-') + "\n" +
        " ---- CHAM_NO          NOM_CMP          TYPE_TEST        NOM_CMP\n"
        "      UN               DX               MAX              DX\n" +
        labels +
        " OK   NON_REGRESSION   XXXX             0.007              0.007              0.0              1E-06"
        "           \n"
        "  \n"
        " ---- CHAM_ELEM        NOM_CMP          TYPE_TEST        NOM_CMP\n"
        "      SI               SIXY             SOMM             SIXY\n"
        "      ORDRE DE GRANDEUR : 100.0           \n";
    EXPECT_NE(resu.find(expected), std::string::npos) << "expected:\n" << expected << "\ngot:\n" << resu;
    const std::string point =
        "---- CHAM_ELEM        NOM_CMP          VALE_ABS         MAILLE           POINT\n"
        "      SI               SIXX             OUI              M1               2\n";
    EXPECT_NE(resu.find("\n" + point), std::string::npos) << resu;
    const std::string node =
        " ---- RESULTAT         NUME_ORDRE       NOM_CHAM         NOM_CMP          NOEUD\n"
        "      U                1                DEPL             DX               N1\n" +
        labels +
        " OK   NON_REGRESSION   au_noeud_N1      -0.003             -0.003             0.0              1E-06"
        "           \n"
        "  \n";
    EXPECT_NE(resu.find(node), std::string::npos) << resu;
}

// A wrong reference value: the NOOK line, the summary, NOOK_TEST_RESU and exit status 2.
TEST(TestResu, WrongReferenceIsNook) {
    auto r = run(R"(
TEST_RESU(RESU=_F(RESULTAT=U, NUME_ORDRE=1, NOM_CHAM='DEPL', TYPE_TEST='SOMM_ABS', NOM_CMP='DX', VALE_CALC=0.120,
                  REFERENCE='ANALYTIQUE', VALE_REFE=0.121, PRECISION=1e-3))
)");
    EXPECT_EQ(r.status, 2) << r.output;
    const std::string resu = r.file("out/t.resu");
    EXPECT_NE(resu.find("\nNOOK  ANALYTIQUE       XXXX             0.121"), std::string::npos) << resu;
    EXPECT_NE(resu.find("\n OK   NON_REGRESSION"), std::string::npos) << resu;
    EXPECT_NE(r.output.find("--- DIAGNOSTIC JOB : NOOK_TEST_RESU"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("reference checks                 0        1      0"), std::string::npos) << r.output;
}

// An unknown node, component or cell: an error naming the keyword and the entity, exit 1, no .resu.
TEST(TestResu, UnknownPlaceOrComponentIsAnError) {
    const std::pair<std::string, std::string> cases[] = {
        {"RESU=_F(RESULTAT=U, NUME_ORDRE=1, NOM_CHAM='DEPL', NOEUD='N999', NOM_CMP='DX', VALE_CALC=1.)",
         "RESU[1]/NOEUD: mesh MA has no node N999"},
        {"RESU=_F(RESULTAT=U, NUME_ORDRE=1, NOM_CHAM='DEPL', NOEUD='N1', NOM_CMP='DZ', VALE_CALC=1.)",
         "RESU[1]: the field (DEPL_R) has no component DZ (components: DX, DY)"},
        {"CHAM_NO=_F(CHAM_GD=UN, GROUP_NO='TOUS', NOM_CMP='DX', VALE_CALC=1.)",
         "CHAM_NO[1]/GROUP_NO: group TOUS holds 36 nodes, TEST_RESU tests one (code_aster CALCULEL5_20)"},
        {"CHAM_ELEM=_F(CHAM_GD=SI, MAILLE='M1', POINT=5, NOM_CMP='SIXX', VALE_CALC=1.)",
         "CHAM_ELEM[1]: cell M1 has 4 integration points in this field, POINT=5 is not one of them"},
        {"RESU=_F(RESULTAT=U, NUME_ORDRE=1, NOM_CHAM='SIGM_NOEU', NOEUD='N1', NOM_CMP='SIXX', VALE_CALC=1.)",
         "RESU[1]/NOM_CHAM: result U has no field SIGM_NOEU at NUME_ORDRE 1"},
    };
    for (const auto& [call, error] : cases) {
        auto r = run("TEST_RESU(" + call + ")\n");
        EXPECT_EQ(r.status, 1) << call << "\n" << r.output;
        EXPECT_NE(r.output.find(error), std::string::npos) << call << "\n" << r.output;
        EXPECT_FALSE(r.exists("out/t.resu")) << call;
    }
}

// What TEST_RESU does not do is refused before any command runs.
TEST(TestResu, UnsupportedKeywordsAreRefusedStatically) {
    auto r = run(R"(
TEST_RESU(RESU=_F(RESULTAT=U, NUME_ORDRE=1, PARA='ITER_GLOB', VALE_CALC_I=1))
)");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("PARA"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("miniaster's results store no parameters to test, only fields"), std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("end of MECA_STATIQUE"), std::string::npos) << "refused before the solve";
    EXPECT_EQ(r.output.find("end of DEBUT"), std::string::npos) << "refused before any command runs";
}

// The enriched components of an X-FEM result, as code_aster's DEPL holds them: ssnv173f's two blocks
// on either side of the interface Y = 2.5, the lower one fixed, the upper one moved by DEPY = 1e-6,
// open by DEPY: H1Y, half the jump, is DEPY / 2 at the most; N1 (a corner, far from the interface)
// carries no H1Y.
TEST(TestResu, EnrichedComponentsOfAnXfemResult) {
    std::ifstream in(std::string(MINIASTER_SHARED_DIR) + "/astest/ssnv173f.comm");
    std::stringstream original;
    original << in.rdbuf();
    const std::string text = original.str();
    const auto end = text.find("MA_XFEM=POST_MAIL_XFEM");
    ASSERT_NE(end, std::string::npos);
    const std::string mesh = std::string("--mesh '") + MINIASTER_SHARED_DIR + "/astest/ssnv173f.mmed'";
    auto r = runComm(text.substr(0, end) + R"(
TEST_RESU(RESU=_F(RESULTAT=UTOT1, NUME_ORDRE=1, NOM_CHAM='DEPL', TYPE_TEST='MAX', NOM_CMP='H1Y', VALE_CALC=5.e-7,
                  REFERENCE='ANALYTIQUE', VALE_REFE=5.e-7, PRECISION=1e-9))
FIN()
)",
                     mesh);
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.file("out/t.resu").find("\n OK   ANALYTIQUE       XXXX             5E-07 "), std::string::npos)
        << r.file("out/t.resu");
    auto bad = runComm(text.substr(0, end) + R"(
TEST_RESU(RESU=_F(RESULTAT=UTOT1, NUME_ORDRE=1, NOM_CHAM='DEPL', NOEUD='N1', NOM_CMP='H1Y', VALE_CALC=5.e-7))
FIN()
)",
                       mesh);
    EXPECT_EQ(bad.status, 1) << bad.output;
    EXPECT_NE(bad.output.find("RESU[1]: node N1 does not carry component H1Y in this field (code_aster CALCULEL6_93)"),
              std::string::npos)
        << bad.output;
}
