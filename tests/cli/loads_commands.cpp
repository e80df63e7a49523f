// The loads of issue 25 through the miniaster binary: what the user is told when a load does not fit
// its model (PRES_REP FISSURE on an interface of another model, CISA_2D on a 3D model, FORCE_CONTOUR
// on a 3D model, LIAISON_DDL and LIAISON_GROUP lists that do not match), what the static check
// refuses before any command (rotated LIAISON_GROUP pairings, COEF_MULT_FONC, moments of
// FORCE_ARETE), and IMPR_RESU FORMAT='GMSH' of a mesh alone read back by Debian's gmsh. The exact
// answers of the loads are the validation cases astest/loads_*.
#include <gtest/gtest.h>

#include <cstdlib>
#include <iterator>
#include <regex>
#include <set>
#include <string>

#include "parser_run.hpp"

namespace {

using ma::test::freshDir;
using ma::test::runMiniaster;
using ma::test::writeText;

const std::string kBar = std::string(MINIASTER_SOURCE_DIR) + "/astest/loads_bar_quad4.mail";
const std::string kBox = std::string(MINIASTER_SOURCE_DIR) + "/astest/loads_box_hexa8.mail";

// A command file on the 2D bar (model MO with its sides, interface FISS at X = 0.73 in MOX) or the
// 3D box (model MO with SD, SG), then `body`.
std::string scene2d(const std::string& body) {
    return "DEBUT()\n"
           "MA = LIRE_MAILLAGE(FORMAT='ASTER', UNITE=20)\n"
           "MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA=('SURF', 'LB', 'LD', 'LH', 'LG'), "
           "PHENOMENE='MECANIQUE', MODELISATION='C_PLAN'))\n"
           "LN = FORMULE(VALE='X-0.73', NOM_PARA=['X', 'Y'])\n"
           "FISS = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='INTERFACE', DEFI_FISS=_F(FONC_LN=LN))\n"
           "MOX = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=FISS)\n" +
           body + "FIN()\n";
}

std::string scene3d(const std::string& body) {
    return "DEBUT()\n"
           "MA = LIRE_MAILLAGE(FORMAT='ASTER', UNITE=20)\n"
           "MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA=('VOLU', 'SD', 'SG'), PHENOMENE='MECANIQUE', "
           "MODELISATION='3D'))\n" +
           body + "FIN()\n";
}

ma::test::RunResult run(const std::string& comm, const std::string& mesh) {
    const auto dir = freshDir();
    writeText(dir / "case.comm", comm);
    return runMiniaster(dir, "case.comm", "--mesh '" + mesh + "'");
}

void expectLoadError(const ma::test::RunResult& r, const std::string& text) {
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find(text), std::string::npos) << r.output;
}

TEST(LoadsCommands, LipPressureNeedsAnInterfaceOfTheModel) {
    // FISS is not an interface of the classical model MO.
    expectLoadError(run(scene2d("C = AFFE_CHAR_MECA(MODELE=MO, PRES_REP=_F(FISSURE=FISS, PRES=1.))\n"), kBar),
                    "PRES_REP[1]/FISSURE: the interface FISS is not one of the model MO");
    expectLoadError(run(scene2d("C = AFFE_CHAR_MECA(MODELE=MOX, PRES_REP=_F(FISSURE=FISS, GROUP_MA='LD', PRES=1.))\n"),
                        kBar),
                    "FISSURE loads the lips of the interfaces, GROUP_MA/MAILLE the boundary cells");
}

TEST(LoadsCommands, PlaneLoadsOnA3DModelAreRefused) {
    expectLoadError(run(scene3d("C = AFFE_CHAR_MECA(MODELE=MO, PRES_REP=_F(GROUP_MA='SD', CISA_2D=1.))\n"), kBox),
                    "CISA_2D is a shear for plane models; the model MO is 3D");
    expectLoadError(run(scene3d("C = AFFE_CHAR_MECA(MODELE=MO, FORCE_CONTOUR=_F(GROUP_MA='SD', FX=1.))\n"), kBox),
                    "FORCE_CONTOUR is for plane (FORCE_CONTOUR) models");
    expectLoadError(run(scene3d("C = AFFE_CHAR_MECA(MODELE=MO, FACE_IMPO=_F(GROUP_MA='SD', DTAN=0.))\n"), kBox),
                    "the tangential displacement of 3D faces has two directions");
}

TEST(LoadsCommands, RelationListsMustMatch) {
    expectLoadError(run(scene2d("C = AFFE_CHAR_MECA(MODELE=MO, LIAISON_DDL=_F(NOEUD=('N1', 'N2'), DDL=('DX',), "
                                "COEF_MULT=(1., 1.), COEF_IMPO=0.))\n"),
                        kBar),
                    "LIAISON_DDL[1]: 2 node(s), 1 DDL and 2 COEF_MULT: one of each per node");
    expectLoadError(run(scene2d("C = AFFE_CHAR_MECA(MODELE=MO, LIAISON_DDL=_F(NOEUD=('N1', 'N2'), DDL=('DX', 'DZ'), "
                                "COEF_MULT=(1., 1.), COEF_IMPO=0.))\n"),
                        kBar),
                    "'DZ' is not a displacement component of the C_PLAN model MO");
    // LB has 6 nodes, LD 3.
    expectLoadError(run(scene2d("C = AFFE_CHAR_MECA(MODELE=MO, LIAISON_GROUP=_F(GROUP_MA_1='LB', GROUP_MA_2='LD', "
                                "DDL_1='DX', COEF_MULT_1=1., DDL_2='DX', COEF_MULT_2=-1., COEF_IMPO=0.))\n"),
                        kBar),
                    "the sides must face each other node by node");
}

TEST(LoadsCommands, StaticCheckRefusesWhatIsNotModelled) {
    const auto r = run(scene2d("C = AFFE_CHAR_MECA(MODELE=MO, LIAISON_GROUP=_F(GROUP_MA_1='LG', GROUP_MA_2='LD', "
                               "DDL_1='DX', COEF_MULT_1=1., DDL_2='DX', COEF_MULT_2=-1., COEF_IMPO=0., "
                               "ANGL_NAUT=(90.,)))\n"
                               "F = FORMULE(VALE='1.', NOM_PARA='INST')\n"
                               "D = AFFE_CHAR_MECA_F(MODELE=MO, LIAISON_DDL=_F(NOEUD=('N1',), DDL=('DX',), "
                               "COEF_MULT_FONC=(F,), COEF_IMPO=F))\n"),
                       kBar);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("problems found in the command file before its first command"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("LIAISON_GROUP[1]/ANGL_NAUT is not supported"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("LIAISON_DDL[1]/COEF_MULT_FONC is not supported"), std::string::npos) << r.output;
    const auto moments = run(scene3d("C = AFFE_CHAR_MECA(MODELE=MO, FORCE_ARETE=_F(GROUP_MA='ARD', MX=1.))\n"), kBox);
    EXPECT_NE(moments.output.find("FORCE_ARETE[1]/MX is not supported"), std::string::npos) << moments.output;
}

// gmsh reads the mesh format 1.0 file back: its node and element counts, and a node's coordinates.
TEST(LoadsCommands, GmshMeshFormatIsReadBackByGmsh) {
    const auto dir = freshDir();
    writeText(dir / "case.comm",
              "DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='ASTER', UNITE=20)\n"
              "IMPR_RESU(FORMAT='GMSH', UNITE=81, RESU=_F(MAILLAGE=MA))\nFIN()\n");
    const auto r = runMiniaster(dir, "case.comm", "--mesh '" + kBox + "'");
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string file = (dir / "out" / "fort.81").string();
    ASSERT_TRUE(std::filesystem::exists(file)) << r.output;
    const std::string msh = (dir / "back.msh").string();
    ASSERT_EQ(std::system(("gmsh '" + file + "' -0 -format msh2 -o '" + msh + "' >/dev/null 2>&1").c_str()), 0);
    const std::string text = r.file("back.msh");
    EXPECT_NE(text.find("$Nodes\n12\n"), std::string::npos) << text;
    EXPECT_NE(text.find("$Elements\n20\n"), std::string::npos) << text;  // 8 SEG2, 10 QUAD4, 2 HEXA8
    // Every node of the box once: x in {0, 1, 2}, y and z in {0, 1}.
    std::set<std::string> corners;
    const std::regex node(R"(\n\d+ ([012]) ([01]) ([01])(?=\n))");
    for (std::sregex_iterator it(text.begin(), text.end(), node), end; it != end; ++it)
        corners.insert((*it)[1].str() + (*it)[2].str() + (*it)[3].str());
    EXPECT_EQ(corners.size(), 12u) << text;
    // The HEXA8 cells (gmsh type 5) in VOLU, the first cell group (region 10001, both tags); the SEG2
    // edges (type 1) in ARD and ARG, the 8th and 9th groups (10008, 10009).
    const std::regex hexa(R"(\n\d+ 5 2 10001 10001( \d+){8}(?=\n))");
    EXPECT_EQ(std::distance(std::sregex_iterator(text.begin(), text.end(), hexa), std::sregex_iterator()), 2) << text;
    const std::regex edge(R"(\n\d+ 1 2 1000[89] 1000[89] \d+ \d+(?=\n))");
    EXPECT_EQ(std::distance(std::sregex_iterator(text.begin(), text.end(), edge), std::sregex_iterator()), 8) << text;
}

}  // namespace
