// LIRE_MAILLAGE FORMAT='ASTER' through the binary: the .export maps the .mail file to its unit, and
// an error in the file names both the .mail line and the .comm line (the reader itself:
// tests/unit/mesh_aster_reader.cpp).
#include <gtest/gtest.h>

#include "parser_run.hpp"

using namespace ma;

// The .export maps the .mail to unit 20; an error names the .mail line and
// the LIRE_MAILLAGE line of the .comm file.
TEST(AsterMeshReader, ExportUnitAndCommLineInErrors) {
    const auto dir = test::freshDir();
    test::writeText(dir / "case.comm", "DEBUT()\n\nMA = LIRE_MAILLAGE(FORMAT='ASTER')\nFIN()\n");
    test::writeText(dir / "case.export", "P actions make_etude\nF comm case.comm D 1\nF mail plate.mail D 20\n");
    test::writeText(dir / "plate.mail", "COOR_2D\nN1 0 0\nN2 1 0\nN3 0 1\nFINSF\nQUAD4\nM1 N1 N2 N3 N4\nFINSF\nFIN\n");
    auto r = test::runMiniaster(dir, "case.export");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("LIRE_MAILLAGE (case.comm, line 3): mesh file '" + (dir / "plate.mail").string() +
                            "', line 7: cell M1 names node 'N4', which no COOR block defines"),
              std::string::npos)
        << r.output;
    test::writeText(dir / "plate.mail",
                    "COOR_2D\nN1 0 0\nN2 1 0\nN3 0 1\nN4 1 1\nFINSF\nQUAD4\nM1 N1 N2 N4 N3\nFINSF\nFIN\n");
    r = test::runMiniaster(dir, "case.export");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.file("out/case.mess").find("NOMBRE DE NOEUDS                           4"), std::string::npos);
}
