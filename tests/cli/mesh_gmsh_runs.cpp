// LIRE_MAILLAGE FORMAT='GMSH' through the binary: a plate [0,2]x[0,1] read from a MSH 2 file (unit
// 19 of the .export), written by hand or by Debian's gmsh, loaded through its GMn groups, gives the
// exact uniaxial field (the reader itself: tests/unit/mesh_gmsh_reader.cpp).
#include <gtest/gtest.h>

#include <cstdlib>

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

size_t okLines(const std::string& resu) {
    size_t ok = 0;
    for (size_t p = resu.find(" OK "); p != std::string::npos; p = resu.find(" OK ", p + 1)) ++ok;
    return ok;
}

// The same plate meshed by gmsh (4 x 2 QUAD4, physical surface 7, left edge 11, right edge 12,
// origin 13), saved as MSH 2 text.
const char* kGeo = R"(Point(1) = {0, 0, 0, 0.5};
Point(2) = {2, 0, 0, 0.5};
Point(3) = {2, 1, 0, 0.5};
Point(4) = {0, 1, 0, 0.5};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Surface{1};
Transfinite Curve{1, 3} = 5;
Transfinite Curve{2, 4} = 3;
Recombine Surface{1};
Physical Surface(7) = {1};
Physical Curve(11) = {4};
Physical Curve(12) = {2};
Physical Point(13) = {1};
)";
}  // namespace

TEST(GmshMeshRuns, UniaxialPlateFromAMeshGmshWrote) {
    const auto dir = test::freshDir();
    test::writeText(dir / "plate.geo", kGeo);
    const std::string gmsh = "cd '" + dir.string() + "' && gmsh -2 -format msh2 plate.geo -o plate.msh >gmsh.out 2>&1";
    ASSERT_EQ(std::system(gmsh.c_str()), 0) << "gmsh (Debian package gmsh) could not mesh plate.geo";
    std::string comm = kComm;
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"'GM1'", "'GM7'"},
                                   {"'GM5'", "'GM11'"},
                                   {"'GM6'", "'GM13'"},
                                   {"'GM4'", "'GM12'"},
                                   {"'N5'", "'N14'"}})
        for (size_t p = comm.find(from); p != std::string::npos; p = comm.find(from, p + 1))
            comm.replace(p, from.size(), to);
    test::writeText(dir / "case.comm", comm);
    test::writeText(dir / "case.export", "P actions make_etude\nF comm case.comm D 1\nF msh plate.msh D 19\n");
    auto r = test::runMiniaster(dir, "case.export");
    EXPECT_EQ(r.status, 0) << r.output;
    const std::string resu = r.file("out/case.resu");
    EXPECT_EQ(resu.find("NOOK"), std::string::npos) << resu;
    EXPECT_GE(okLines(resu), 3u) << resu;
    // 15 nodes, 8 QUAD4 + 2 + 2 SEG2 + 1 POI1, groups GM7 GM11 GM12 GM13 (and node group GM13).
    const std::string mess = r.file("out/case.mess");
    EXPECT_NE(mess.find("15 nodes used by the elements, 13 cells, 4 groups GMn"), std::string::npos) << mess;
}

TEST(GmshMeshRuns, UniaxialPlateFromGmshGroups) {
    const auto dir = test::freshDir();
    test::writeText(dir / "plate.msh", kPlate);
    test::writeText(dir / "case.comm", kComm);
    test::writeText(dir / "case.export", "P actions make_etude\nF comm case.comm D 1\nF msh plate.msh D 19\n");
    auto r = test::runMiniaster(dir, "case.export");
    EXPECT_EQ(r.status, 0) << r.output;
    const std::string resu = r.file("out/case.resu");
    EXPECT_EQ(resu.find("NOOK"), std::string::npos) << resu;
    EXPECT_GE(okLines(resu), 3u) << resu;
    EXPECT_NE(r.file("out/case.mess").find("FORMAT='GMSH'"), std::string::npos);
}
