// CALC_CHAMP CRITERES (SIEQ_*) and DEFORMATION (EPSI_*): on patch tests, where the strain and
// stress are uniform and known in closed form (3D general linear field, plane-stress TRIA3 with
// its free EPZZ), every component at every point, cell node and node is tested by TEST_RESU
// against the exact value computed in the command file; on ssnv511e's X-FEM result (three
// interfaces, junction, contact) the nodal fields read back from MED are each node's block state.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "med_io/MedResultReader.hpp"
#include "med_test_support.hpp"
#include "parser_run.hpp"

namespace fs = std::filesystem;

namespace {

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

// TEST_RESU lines for MIN and MAX of every component of the uniform fields: `sig` and `eps` are
// Python expressions of the case's exact 3x3 stress and strain (numpy arrays).
std::string uniformChecks(const std::string& result, const std::string& sig, const std::string& eps) {
    return "import numpy as np\n"
           "S = np.array(" +
           sig + "); EPS = np.array(" + eps +
           ")\n"
           "w = np.linalg.eigvalsh(S); tr = np.trace(S); dev = S - tr / 3 * np.eye(3)\n"
           "vm = float(np.sqrt(1.5 * np.sum(dev * dev)))\n"
           "sieq = {'VMIS': vm, 'TRESCA': w[2] - w[0], 'PRIN_1': w[0], 'PRIN_2': w[1], 'PRIN_3': w[2],\n"
           "        'VMIS_SG': vm if tr >= 0 else -vm, 'TRSIG': tr, 'TRIAX': tr / 3 / vm}\n"
           "epsi = {'EPXX': EPS[0][0], 'EPYY': EPS[1][1], 'EPZZ': EPS[2][2], 'EPXY': EPS[0][1]}\n"
           "if len(S) == 3 and DIM == 3: epsi.update({'EPXZ': EPS[0][2], 'EPYZ': EPS[1][2]})\n"
           "scale = {'SIEQ': vm, 'EPSI': float(np.max(np.abs(EPS)))}\n"
           "for family, exact in (('SIEQ', sieq), ('EPSI', epsi)):\n"
           "    for place in ('ELGA', 'ELNO', 'NOEU'):\n"
           "        for cmp, v in exact.items():\n"
           "            for tt in ('MIN', 'MAX'):\n"
           "                TEST_RESU(RESU=_F(RESULTAT=" +
           result +
           ", NUME_ORDRE=1, NOM_CHAM=family + '_' + place,\n"
           "                    NOM_CMP=cmp, TYPE_TEST=tt, VALE_CALC=float(v), VALE_REFE=float(v),\n"
           "                    REFERENCE='ANALYTIQUE', CRITERE='ABSOLU', PRECISION=1.E-9 * scale[family]))\n";
}

const char* kCalc =
    "=CALC_CHAMP(RESULTAT=RES1, CRITERES=('SIEQ_ELGA', 'SIEQ_ELNO', 'SIEQ_NOEU'),\n"
    "                  DEFORMATION=('EPSI_ELGA', 'EPSI_ELNO', 'EPSI_NOEU'))\n";

// HEXA8, u = A x + c imposed on the whole skin: eps = sym(A), sigma = lambda tr(eps) I + 2 mu eps.
TEST(CalcChampCriteria, UniformGeneralStateIn3dAtEveryPlace) {
    const auto dir = ma::test::freshDir();
    const std::string src = std::string(MINIASTER_SOURCE_DIR) + "/astest/fe_patch_hexa8";
    const std::string extra = std::string("DIM = 3\nR1") + kCalc + uniformChecks("R1", "sig", "eps");
    ma::test::writeText(dir / "t.comm", ma::test::beforeFin(ma::test::readText(src + ".comm"), extra));
    const auto r = ma::test::runMiniaster(dir, "t.comm", "--mesh '" + src + ".mmed'");
    ASSERT_EQ(r.status, 0) << r.output << r.file("out/t.mess");
    const std::string resu = r.file("out/t.resu");
    EXPECT_EQ(count(resu, "NOOK"), 0u) << resu;
    // 3 places x (8 SIEQ + 6 EPSI components) x (MIN, MAX), each with its analytic check.
    EXPECT_EQ(count(resu, "SIEQ_E") + count(resu, "SIEQ_NOEU"), 3u * 8u * 2u) << resu;
    EXPECT_EQ(count(resu, "EPSI_E") + count(resu, "EPSI_NOEU"), 3u * 6u * 2u) << resu;
    EXPECT_GE(count(resu, " OK   ANALYTIQUE"), 3u * 14u * 2u) << resu;
}

// TRIA3 in plane stress: SIZZ = 0 and EPZZ = -nu / (1 - nu) (EPXX + EPYY), the free contraction.
TEST(CalcChampCriteria, PlaneStressHasItsFreeThicknessStrain) {
    const auto dir = ma::test::freshDir();
    const std::string src = std::string(MINIASTER_SOURCE_DIR) + "/astest/fe_patch_tria3";
    const std::string extra = std::string("DIM = 2\nR1") + kCalc +
                              "sxx = lamc * (exx + eyy) + 2 * mu * exx; syy = lamc * (exx + eyy) + 2 * mu * eyy\n"
                              "ezz = -nu / (1 - nu) * (exx + eyy)\n" +
                              uniformChecks("R1", "[[sxx, 2 * mu * exy, 0], [2 * mu * exy, syy, 0], [0, 0, 0]]",
                                            "[[exx, exy, 0], [exy, eyy, 0], [0, 0, ezz]]");
    ma::test::writeText(dir / "t.comm", ma::test::beforeFin(ma::test::readText(src + ".comm"), extra));
    const auto r = ma::test::runMiniaster(dir, "t.comm", "--mesh '" + src + ".mmed'");
    ASSERT_EQ(r.status, 0) << r.output << r.file("out/t.mess");
    const std::string resu = r.file("out/t.resu");
    EXPECT_EQ(count(resu, "NOOK"), 0u) << resu;
    EXPECT_NE(resu.find("R1               1                EPSI_NOEU        MAX              EPZZ"), std::string::npos)
        << resu;
    EXPECT_EQ(count(resu, "EPSI_ELNO"), 4u * 2u) << resu;
}

// ssnv511e (D_PLAN, E = 100 MPa, nu = 0.3): each block's uniform state (docs/post.md); SIEQ_NOEU
// and EPSI_NOEU at every node are that state's, read back from the MED file by miniaster's reader
// and by mdump4; on POST_CHAM_XFEM's result their extremes are the blocks' extremes.
TEST(CalcChampCriteria, XfemBlockStatesAtEveryNodeInTheMedFile) {
    const auto dir = ma::test::freshDir();
    const std::string extra =
        "UTOT1=CALC_CHAMP(reuse=UTOT1, RESULTAT=UTOT1, CRITERES=('SIEQ_ELNO', 'SIEQ_NOEU'),\n"
        "                 DEFORMATION=('EPSI_ELGA', 'EPSI_NOEU'))\n"
        "IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(RESULTAT=UTOT1, NOM_CHAM=('SIEQ_NOEU', 'EPSI_NOEU', 'SIEQ_ELNO')))\n"
        // code_aster's users compute them on POST_CHAM_XFEM's result, with a material on its mesh.
        "CMV = AFFE_MATERIAU(MAILLAGE=MA_XFEM, AFFE=_F(TOUT='OUI', MATER=ACIER))\n"
        "RES_XFEM = CALC_CHAMP(reuse=RES_XFEM, RESULTAT=RES_XFEM, CRITERES='SIEQ_NOEU', CHAM_MATER=CMV,\n"
        "                      DEFORMATION='EPSI_NOEU')\n"
        "import numpy as np\n"
        "blocks = [np.diag([sx, sy, nu * (sx + sy)]) for sx in (-2e6, -1e6) for sy in (-2e6, -1e6)]\n"
        "vmis = [float(np.sqrt(1.5 * np.sum((S - np.trace(S) / 3 * np.eye(3))**2))) for S in blocks]\n"
        "epxx = [((1 + nu) * S[0][0] - nu * np.trace(S)) / E for S in blocks]\n"
        "for cham, cmp, values in (('SIEQ_NOEU', 'VMIS', vmis), ('EPSI_NOEU', 'EPXX', epxx)):\n"
        "    for tt, v in (('MIN', min(values)), ('MAX', max(values))):\n"
        "        TEST_RESU(RESU=_F(RESULTAT=RES_XFEM, NUME_ORDRE=1, NOM_CHAM=cham, NOM_CMP=cmp, TYPE_TEST=tt,\n"
        "                          VALE_CALC=v, VALE_REFE=v, REFERENCE='ANALYTIQUE', PRECISION=1.E-9))\n";
    ma::test::writeText(dir / "t.comm",
                        ma::test::beforeFin(ma::test::readText(ma::test::astest("ssnv511e.comm")), extra));
    const auto r = ma::test::runMiniaster(dir, "t.comm", "--mesh '" + ma::test::astest("ssnv511a.mmed") + "'");
    ASSERT_EQ(r.status, 2) << r.output;  // ssnv511e's own inexact NON_REGRESSION values (README)
    const std::string resu = r.file("out/t.resu");
    EXPECT_EQ(count(resu, "NOOK ANALYTIQUE"), 0u) << resu;
    EXPECT_EQ(count(resu, "RES_XFEM         1                "), 4u) << resu;
    const auto meshes = ma::med::readResults((dir / "out/fort.80").string());
    ASSERT_EQ(meshes.size(), 1u);
    const auto& mesh = *meshes[0].mesh;
    const double E = 100.0e6, nu = 0.3;
    int checked = 0;
    for (const auto& field : meshes[0].fields) {
        const auto& last = field.steps.at(1);
        if (field.name == "UTOT1___SIEQ_ELNO") {
            ASSERT_TRUE(last.cellPoints);
            EXPECT_TRUE(last.cellPoints->atNodes);
            continue;
        }
        ASSERT_TRUE(last.nodal) << field.name;
        for (int n = 0; n < mesh.nodeCount(); ++n) {
            const double x = mesh.coords[size_t(n)][0], y = mesh.coords[size_t(n)][1];
            const double sxx = y > 0 ? -2e6 : -1e6, syy = x > 0 ? -2e6 : -1e6, szz = nu * (sxx + syy);
            if (field.name == "UTOT1___EPSI_NOEU") {
                const double tr = sxx + syy + szz;
                const double exx = ((1 + nu) * sxx - nu * tr) / E, eyy = ((1 + nu) * syy - nu * tr) / E;
                const double exact[4] = {exx, eyy, 0.0, 0.0};
                for (int c = 0; c < 4; ++c, ++checked)
                    EXPECT_NEAR(last.nodal->at(n, c), exact[c], 2e-2 * 1e-9) << "node " << n << " cmp " << c;
            } else if (field.name == "UTOT1___SIEQ_NOEU") {
                Eigen::Vector3d p(sxx, syy, szz);
                std::sort(p.data(), p.data() + 3);
                const double mean = p.sum() / 3;
                const double vmis = std::sqrt(1.5 * (p.array() - mean).square().sum());
                const double exact[5] = {vmis, p[2] - p[0], p[0], p[1], p[2]};
                for (int c = 0; c < 5; ++c, ++checked)
                    EXPECT_NEAR(last.nodal->at(n, c), exact[c], 2e6 * 1e-9) << "node " << n << " cmp " << c;
            }
        }
    }
    EXPECT_EQ(checked, 36 * (4 + 5));
    const std::string dump = ma::test::runCommand("timeout 60 mdump4 '" + (dir / "out/fort.80").string() +
                                                  "' NODALE FULL_INTERLACE 0 </dev/null");
    EXPECT_NE(dump.find("CHAMP |UTOT1___SIEQ_NOEU|"), std::string::npos);
    EXPECT_NE(dump.find("CHAMP |UTOT1___EPSI_NOEU|"), std::string::npos);
    EXPECT_NE(dump.find("MED_NOEUD_MAILLE de type geometrique MED_QUAD4"), std::string::npos);
}

// The options miniaster does not compute are refused before any command runs.
TEST(CalcChampCriteria, OtherCriteriaAndStrainsAreRefusedStatically) {
    const auto dir = ma::test::freshDir();
    const std::string src = std::string(MINIASTER_SOURCE_DIR) + "/astest/fe_patch_tria3";
    const std::string extra = "R1=CALC_CHAMP(RESULTAT=RES1, CRITERES='EPEQ_NOEU', DEFORMATION='EPSG_ELGA')\n";
    ma::test::writeText(dir / "t.comm", ma::test::beforeFin(ma::test::readText(src + ".comm"), extra));
    const auto r = ma::test::runMiniaster(dir, "t.comm", "--mesh '" + src + ".mmed'");
    EXPECT_EQ(r.status, 1) << r.output;
    const std::string mess = r.file("out/t.mess");
    EXPECT_NE(mess.find("CALC_CHAMP: keyword CRITERES: value 'EPEQ_NOEU' is not supported by miniaster"),
              std::string::npos)
        << mess;
    EXPECT_NE(mess.find("CALC_CHAMP: keyword DEFORMATION: value 'EPSG_ELGA' is not supported by miniaster"),
              std::string::npos)
        << mess;
    EXPECT_EQ(mess.find("MECA_STATIQUE("), std::string::npos);  // nothing ran
}

}  // namespace
