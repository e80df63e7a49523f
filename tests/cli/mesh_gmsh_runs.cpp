// LIRE_MAILLAGE FORMAT='GMSH' through the binary: a plate [0,2]x[0,1] of two QUAD4 read from a MSH 2
// file (unit 19 of the .export), loaded through its GMn groups, gives the exact uniaxial field
// (the reader itself: tests/unit/mesh_gmsh_reader.cpp).
#include <gtest/gtest.h>

#include "parser_run.hpp"

using namespace ma;

namespace {
const char* kPlate = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$Nodes
6
1 0 0 0
2 1 0 0
3 2 0 0
4 0 1 0
5 1 1 0
6 2 1 0
$EndNodes
$Elements
5
10 3 2 1 1 1 2 5 4
11 3 2 1 1 2 3 6 5
3 1 2 4 4 3 6
4 1 2 5 5 4 1
20 15 2 6 6 1
$EndElements
)";

// C_PLAN, DX = 0 on the left edge (GM5), DY = 0 at the origin (node group GM6), DX = 0.02 on the
// right edge (GM4): strain 0.01 along x, DY = -nu 0.01 y, exactly representable.
const char* kComm = R"(DEBUT()
MA = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=19)
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA='GM1', PHENOMENE='MECANIQUE', MODELISATION='C_PLAN'))
MAT = DEFI_MATERIAU(ELAS=_F(E=1.0, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))
CH = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='GM5', DX=0.0), _F(GROUP_NO='GM6', DY=0.0),
                                         _F(GROUP_MA='GM4', DX=0.02)))
RES = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH))
MA = DEFI_GROUP(reuse=MA, MAILLAGE=MA, CREA_GROUP_NO=_F(GROUP_MA='GM1'))
T = POST_RELEVE_T(ACTION=_F(INTITULE='DEPL', GROUP_NO='GM1', RESULTAT=RES, NOM_CHAM='DEPL', NUME_ORDRE=1,
                            TOUT_CMP='OUI', OPERATION='EXTRACTION'))
TEST_TABLE(TABLE=T, NOM_PARA='DX', TYPE_TEST='MAX', REFERENCE='ANALYTIQUE', VALE_REFE=0.02, VALE_CALC=0.02,
           PRECISION=1.0E-12)
TEST_TABLE(TABLE=T, NOM_PARA='DY', TYPE_TEST='MIN', REFERENCE='ANALYTIQUE', VALE_REFE=-0.003, VALE_CALC=-0.003,
           PRECISION=1.0E-12)
TEST_TABLE(TABLE=T, NOM_PARA='DX', FILTRE=_F(NOM_PARA='NOEUD', VALE_K='N5'), REFERENCE='ANALYTIQUE',
           VALE_REFE=0.01, VALE_CALC=0.01, PRECISION=1.0E-12)
FIN()
)";
}  // namespace

TEST(GmshMeshRuns, UniaxialPlateFromGmshGroups) {
    const auto dir = test::freshDir();
    test::writeText(dir / "plate.msh", kPlate);
    test::writeText(dir / "case.comm", kComm);
    test::writeText(dir / "case.export", "P actions make_etude\nF comm case.comm D 1\nF msh plate.msh D 19\n");
    auto r = test::runMiniaster(dir, "case.export");
    EXPECT_EQ(r.status, 0) << r.output;
    const std::string resu = r.file("out/case.resu");
    EXPECT_EQ(resu.find("NOOK"), std::string::npos) << resu;
    size_t ok = 0;
    for (size_t p = resu.find(" OK "); p != std::string::npos; p = resu.find(" OK ", p + 1)) ++ok;
    EXPECT_GE(ok, 3u) << resu;
    EXPECT_NE(r.file("out/case.mess").find("FORMAT='GMSH'"), std::string::npos);
}
