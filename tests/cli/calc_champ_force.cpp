// CALC_CHAMP FORCE (FORC_NODA, REAC_NODA) and POST_RELEVE_T RESULTANTE / MOMENT: the reactions at
// the supports balance the applied loads, on classical patch tests (2D and 3D) and on code_aster's
// X-FEM scenes with three interfaces and contact (ssnv511e in 2D, ssnv511g in 3D). The loads are
// uniform pressures (ssnv511's p = 1 MPa for x < 0, 2 MPa for x > 0, and the same in y) on a
// 10 x 10 square (x 1 in depth in 3D): every total and moment below is a closed form.
#include <gtest/gtest.h>

#include <map>

#include "med_io/MedResultReader.hpp"
#include "med_test_support.hpp"
#include "parser_run.hpp"

namespace fs = std::filesystem;

namespace {

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

// The row of table `table` in the .resu whose INTITULE is `title`: column -> value (cells left
// empty, printed '-', are absent).
std::map<std::string, double> tableRow(const std::string& resu, const std::string& table, const std::string& title) {
    std::map<std::string, double> row;
    const auto at = resu.find("CONCEPT " + table + " ");
    if (at == std::string::npos) return row;
    std::istringstream in(resu.substr(resu.find('\n', at) + 1));
    std::string line;
    std::getline(in, line);
    const auto header = words(line);
    while (std::getline(in, line) && !line.empty() && line[0] != '#') {
        const auto cells = words(line);
        if (cells.size() != header.size() || cells[0] != title) continue;
        for (size_t i = 1; i < cells.size(); ++i)
            if (cells[i] != "-" && header[i] != "RESU" && header[i] != "NOM_CHAM") row[header[i]] = std::stod(cells[i]);
    }
    return row;
}

void expectRelative(const std::map<std::string, double>& row, const std::string& column, double exact,
                    double tolerance = 1e-10) {
    ASSERT_TRUE(row.count(column)) << column;
    EXPECT_NEAR(row.at(column), exact, tolerance * std::abs(exact)) << column;
}

// Appends `extra` to code_aster's file `name` before its FIN.
std::string originalWith(const std::string& name, const std::string& extra) {
    return ma::test::beforeFin(ma::test::readText(ma::test::astest(name)), extra);
}

// Classical D_PLAN square on ssnv511a's mesh: SIYY = -2 MPa, SIXX = -1 MPa, supports on LB (DY) and
// LG (DX). The nodal reactions are the consistent forces of the uniform stress: 2e7 N in y on LB,
// 1e7 in x on LG, moment of LB's about the corner (-5, -5): 2e6 * 10^2 / 2 = 1e8.
const char* kPatch2d = R"(DEBUT()
MA = LIRE_MAILLAGE(FORMAT='MED')
MA = DEFI_GROUP(reuse=MA, MAILLAGE=MA, CREA_GROUP_NO=(_F(GROUP_MA='LB'), _F(GROUP_MA='LG'), _F(GROUP_MA='LH'),
                                                     _F(GROUP_MA='SURF')))
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA=('SURF', 'LH', 'LD'), PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
ACIER = DEFI_MATERIAU(ELAS=_F(E=2.E11, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=ACIER))
CH = AFFE_CHAR_MECA(MODELE=MO, PRES_REP=(_F(GROUP_MA='LH', PRES=2.E6), _F(GROUP_MA='LD', PRES=1.E6)),
                    DDL_IMPO=(_F(GROUP_MA='LB', DY=0.), _F(GROUP_MA='LG', DX=0.)))
RES = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH))
RES = CALC_CHAMP(reuse=RES, RESULTAT=RES, FORCE=('FORC_NODA', 'REAC_NODA'))
R2 = CALC_CHAMP(RESULTAT=RES, FORCE='REAC_NODA', EXCIT=_F(CHARGE=CH, COEF_MULT=2.))
T = POST_RELEVE_T(ACTION=(
    _F(INTITULE='LB', OPERATION='EXTRACTION', RESULTAT=RES, NOM_CHAM='REAC_NODA', GROUP_NO='LB', RESULTANTE=('DX', 'DY')),
    _F(INTITULE='LG', OPERATION='EXTRACTION', RESULTAT=RES, NOM_CHAM='REAC_NODA', GROUP_NO='LG', RESULTANTE=('DX', 'DY')),
    _F(INTITULE='M', OPERATION='EXTRACTION', RESULTAT=RES, NOM_CHAM='REAC_NODA', GROUP_NO='LB',
       RESULTANTE=('DX', 'DY'), MOMENT='DRZ', POINT=(-5., -5.)),
    _F(INTITULE='LH', OPERATION='EXTRACTION', RESULTAT=RES, NOM_CHAM='FORC_NODA', GROUP_NO='LH', RESULTANTE='DY'),
    _F(INTITULE='ALL2', OPERATION='EXTRACTION', RESULTAT=R2, NOM_CHAM='REAC_NODA', GROUP_NO='SURF',
       RESULTANTE=('DX', 'DY'))))
IMPR_TABLE(TABLE=T, FORMAT_R='1PE23.15')
TEST_TABLE(TABLE=T, NOM_PARA='DY', FILTRE=_F(NOM_PARA='INTITULE', VALE_K='LB'), VALE_CALC=2.E7, VALE_REFE=2.E7,
           REFERENCE='ANALYTIQUE', PRECISION=1.E-10)
TEST_TABLE(TABLE=T, NOM_PARA='MOMENT_Z', FILTRE=_F(NOM_PARA='INTITULE', VALE_K='M'), VALE_CALC=1.E8,
           VALE_REFE=1.E8, REFERENCE='ANALYTIQUE', PRECISION=1.E-10)
TEST_RESU(RESU=_F(RESULTAT=RES, NOM_CHAM='REAC_NODA', NUME_ORDRE=1, GROUP_NO='LG', NOM_CMP='DX', TYPE_TEST='SOMM',
                  VALE_CALC=1.E7, VALE_REFE=1.E7, REFERENCE='ANALYTIQUE', PRECISION=1.E-10))
FIN()
)";

TEST(CalcChampForce, ReactionsOfAPatchTestBalanceThePressures) {
    const auto dir = ma::test::freshDir();
    ma::test::writeText(dir / "t.comm", kPatch2d);
    const auto r = ma::test::runMiniaster(dir, "t.comm", "--mesh '" + ma::test::astest("ssnv511a.mmed") + "'");
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string resu = r.file("out/t.resu");
    EXPECT_EQ(resu.find("NOOK"), std::string::npos) << resu;
    const auto lb = tableRow(resu, "T", "LB"), lg = tableRow(resu, "T", "LG"), m = tableRow(resu, "T", "M");
    expectRelative(lb, "DY", 2e7);
    expectRelative(lg, "DX", 1e7);
    expectRelative(m, "RESULT_Y", 2e7);
    expectRelative(m, "MOMENT_Z", 1e8);
    EXPECT_EQ(m.at("MOMENT_X"), 0.0);
    EXPECT_EQ(m.at("RESULT_Z"), 0.0);
    EXPECT_EQ(m.count("DX"), 0u);  // with MOMENT, RESULT_* replace the component columns (rvpara)
    // At the loaded nodes the element forces carry the pressure (free nodes: FORC_NODA = F_ext).
    expectRelative(tableRow(resu, "T", "LH"), "DY", -2e7);
    // COEF_MULT=2 doubles the loads: the sum over every node is twice their total, F_int summing to 0.
    const auto all = tableRow(resu, "T", "ALL2");
    expectRelative(all, "DX", 2e7, 1e-9);
    expectRelative(all, "DY", 4e7, 1e-9);
    EXPECT_NE(r.file("out/t.mess").find("REAC_NODA NUME_ORDRE 1: sum over the nodes DX 1.000000e+07 DY 2.000000e+07"),
              std::string::npos);
}

// ssnv511e (three interfaces, two junctions, contact on the three): the supports' reactions are
// the totals of the pressures, 1e6 * 5 + 2e6 * 5 = 1.5e7 on each side, and the moment of LB's about
// (-5, -5) is 1e6 * 5^2 / 2 + 2e6 * (10^2 - 5^2) / 2 = 8.75e7.
const char* kForces511e =
    R"(MAILLAG=DEFI_GROUP(reuse=MAILLAG, MAILLAGE=MAILLAG, CREA_GROUP_NO=(_F(GROUP_MA='LB'), _F(GROUP_MA='LG')))
UTOT1=CALC_CHAMP(reuse=UTOT1, RESULTAT=UTOT1, NUME_ORDRE=1, FORCE=('FORC_NODA', 'REAC_NODA'))
TR = POST_RELEVE_T(ACTION=(
    _F(INTITULE='LB', OPERATION='EXTRACTION', RESULTAT=UTOT1, NOM_CHAM='REAC_NODA', NUME_ORDRE=1, GROUP_NO='LB',
       RESULTANTE=('DX', 'DY')),
    _F(INTITULE='LG', OPERATION='EXTRACTION', RESULTAT=UTOT1, NOM_CHAM='REAC_NODA', NUME_ORDRE=1, GROUP_NO='LG',
       RESULTANTE=('DX', 'DY')),
    _F(INTITULE='M', OPERATION='EXTRACTION', RESULTAT=UTOT1, NOM_CHAM='REAC_NODA', NUME_ORDRE=1, GROUP_NO='LB',
       RESULTANTE=('DX', 'DY'), MOMENT='DRZ', POINT=(-5., -5.))))
IMPR_TABLE(TABLE=TR, FORMAT_R='1PE23.15')
IMPR_RESU(FORMAT='MED', UNITE=81, RESU=_F(RESULTAT=UTOT1, NUME_ORDRE=1, NOM_CHAM=('DEPL', 'FORC_NODA', 'REAC_NODA')))
)";

TEST(CalcChampForce, ReactionsBalanceTheLoadsOnSsnv511eWithContact) {
    const auto dir = ma::test::freshDir();
    ma::test::writeText(dir / "t.comm", originalWith("ssnv511e.comm", kForces511e));
    const auto r = ma::test::runMiniaster(dir, "t.comm", "--mesh '" + ma::test::astest("ssnv511a.mmed") + "'");
    ASSERT_EQ(r.status, 2) << r.output;  // ssnv511e's own inexact NON_REGRESSION values (README)
    const std::string resu = r.file("out/t.resu");
    expectRelative(tableRow(resu, "TR", "LB"), "DY", 1.5e7);
    expectRelative(tableRow(resu, "TR", "LG"), "DX", 1.5e7);
    expectRelative(tableRow(resu, "TR", "M"), "MOMENT_Z", 8.75e7);

    // The MED file read back: REAC_NODA is zero (to the solve's residual) at every node that is
    // not on a support, FORC_NODA carries H1X... on the enriched nodes.
    const auto meshes = ma::med::readResults((dir / "out/fort.81").string());
    ASSERT_EQ(meshes.size(), 1u);
    const auto& mesh = *meshes[0].mesh;
    const ma::NodalField* reac = nullptr;
    const ma::NodalField* forc = nullptr;
    for (const auto& f : meshes[0].fields) {
        if (f.name.find("REAC_NODA") != std::string::npos) reac = f.steps.at(0).nodal.get();
        if (f.name.find("FORC_NODA") != std::string::npos) forc = f.steps.at(0).nodal.get();
    }
    ASSERT_TRUE(reac && forc);
    EXPECT_GE(forc->componentIndex("H1X"), 0);
    const int dx = reac->componentIndex("DX"), dy = reac->componentIndex("DY");
    int free = 0;
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        const auto& x = mesh.coords[size_t(n)];
        if (std::abs(x[0] + 5) < 1e-9 || std::abs(x[1] + 5) < 1e-9 || !reac->has(n, dx)) continue;
        ++free;
        EXPECT_NEAR(reac->at(n, dx), 0.0, 1e-6) << mesh.nodeNames[size_t(n)];
        EXPECT_NEAR(reac->at(n, dy), 0.0, 1e-6) << mesh.nodeNames[size_t(n)];
    }
    EXPECT_GT(free, 20);
    // mdump4 reads the nodal fields (MED_NODE, DEPL_R components).
    int status = 0;
    const std::string dump = ma::test::runCommand("timeout 60 mdump4 '" + (dir / "out/fort.81").string() +
                                                      "' NODALE FULL_INTERLACE 0 </dev/null",
                                                  &status);
    EXPECT_NE(dump.find("CHAMP |UTOT1___REAC_NODA|"), std::string::npos) << dump.substr(0, 2000);
    EXPECT_NE(dump.find("CHAMP |UTOT1___FORC_NODA|"), std::string::npos);
    // and so does miniaster convert (VTU).
    const std::string out =
        ma::test::runCommand(std::string(MINIASTER_BINARY) + " convert '" + (dir / "out/fort.81").string() + "' '" +
                                 (dir / "r.vtu").string() + "' 2>&1",
                             &status);
    EXPECT_EQ(status, 0) << out;
    EXPECT_NE(ma::test::readText((dir / "r.vtu").string()).find("REAC_NODA"), std::string::npos);
}

// ssnv511g (3D, HEXA8, three interfaces with contact, 1 m thick): 1.5e7 N on SB in y and on SG in x,
// the z reactions on FACE balance nothing (0); moments of SB's about (-5, -5, 0): x -1.5e7 * 0.5,
// z 8.75e7.
const char* kForces511g =
    R"(MAILLAG=DEFI_GROUP(reuse=MAILLAG, MAILLAGE=MAILLAG, CREA_GROUP_NO=(_F(GROUP_MA='SB'), _F(GROUP_MA='SG'), _F(GROUP_MA='FACE')))
UTOT1=CALC_CHAMP(reuse=UTOT1, RESULTAT=UTOT1, NUME_ORDRE=1, FORCE='REAC_NODA')
TR = POST_RELEVE_T(ACTION=(
    _F(INTITULE='SB', OPERATION='EXTRACTION', RESULTAT=UTOT1, NOM_CHAM='REAC_NODA', NUME_ORDRE=1, GROUP_NO='SB',
       RESULTANTE=('DX', 'DY', 'DZ')),
    _F(INTITULE='SG', OPERATION='EXTRACTION', RESULTAT=UTOT1, NOM_CHAM='REAC_NODA', NUME_ORDRE=1, GROUP_NO='SG',
       RESULTANTE=('DX', 'DY', 'DZ')),
    _F(INTITULE='FACE', OPERATION='EXTRACTION', RESULTAT=UTOT1, NOM_CHAM='REAC_NODA', NUME_ORDRE=1, GROUP_NO='FACE',
       RESULTANTE=('DX', 'DY', 'DZ')),
    _F(INTITULE='M', OPERATION='EXTRACTION', RESULTAT=UTOT1, NOM_CHAM='REAC_NODA', NUME_ORDRE=1, GROUP_NO='SB',
       RESULTANTE=('DX', 'DY', 'DZ'), MOMENT=('DRX', 'DRY', 'DRZ'), POINT=(-5., -5., 0.))))
IMPR_TABLE(TABLE=TR, FORMAT_R='1PE23.15')
)";

TEST(CalcChampForce, ReactionsBalanceTheLoadsOnSsnv511gIn3dWithContact) {
    const auto dir = ma::test::freshDir();
    ma::test::writeText(dir / "t.comm", originalWith("ssnv511g.comm", kForces511g));
    const auto r = ma::test::runMiniaster(dir, "t.comm", "--mesh '" + ma::test::astest("ssnv511g.mmed") + "'");
    ASSERT_EQ(r.status, 2) << r.output;  // ssnv511g's own inexact NON_REGRESSION values (README)
    const std::string resu = r.file("out/t.resu");
    const auto sb = tableRow(resu, "TR", "SB"), face = tableRow(resu, "TR", "FACE"), m = tableRow(resu, "TR", "M");
    expectRelative(sb, "DY", 1.5e7);
    expectRelative(tableRow(resu, "TR", "SG"), "DX", 1.5e7);
    EXPECT_NEAR(face.at("DZ"), 0.0, 1.5e7 * 1e-10);
    expectRelative(m, "MOMENT_X", -7.5e6);
    expectRelative(m, "MOMENT_Z", 8.75e7);
}

// FORCE on a result without a model (POST_CHAM_XFEM's) or values miniaster does not compute are
// refused before any command runs.
TEST(CalcChampForce, ShellResultantComponentsAreRefusedBeforeTheSolve) {
    const auto dir = ma::test::freshDir();
    std::string comm = kPatch2d;
    comm.insert(
        comm.rfind("FIN()"),
        "T2 = POST_RELEVE_T(ACTION=_F(INTITULE='N', OPERATION='EXTRACTION', RESULTAT=RES, NOM_CHAM='REAC_NODA', "
        "GROUP_NO='LB', RESULTANTE='NXX'))\n");
    ma::test::writeText(dir / "t.comm", comm);
    const auto r = ma::test::runMiniaster(dir, "t.comm", "--mesh '" + ma::test::astest("ssnv511a.mmed") + "'");
    EXPECT_EQ(r.status, 1) << r.output;
    const std::string mess = r.file("out/t.mess");
    EXPECT_NE(mess.find("value 'NXX' is not supported by miniaster"), std::string::npos) << mess;
    EXPECT_EQ(mess.find("MECA_STATIQUE("), std::string::npos);  // nothing ran
}

}  // namespace
