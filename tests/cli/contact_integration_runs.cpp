// ZONE/INTEGRATION and ORDRE_INT of DEFI_CONTACT through the miniaster binary: each zone's rule in
// the .mess, the catalogue's ranges of ORDRE_INT, the 3D schemes code_aster does not define
// (SIMPSON of order > 1, NCOTES) refused, and the vertex rule on HEXA8 replaced, announced and exact.
// The rules themselves are tested in process: tests/unit/contact_integration.cpp.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "parser_run.hpp"
#include "ssnv511_scene.hpp"

namespace {

using namespace ma::test;

const std::string kMesh2d = std::string("--mesh '") + MINIASTER_SHARED_DIR + "/astest/ssnv511a.mmed'";
const std::string kMesh3d = std::string("--mesh '") + MINIASTER_SOURCE_DIR + "/astest/contact_tetra4_n5.mmed'";

// DEFI_CONTACT on the ssnv511 interfaces with `zone` in every ZONE (2D D_PLAN or 3D), then FIN.
std::string definition(bool threeD, const std::string& zone) {
    return ssnv511Preamble({.groups = threeD ? "'VOLU'" : "'SURF'", .threeD = threeD}) +
           "MX = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=(F1, F2, F3), CONTACT='STANDARD')\n"
           "CT = DEFI_CONTACT(MODELE=MX, FORMULATION='XFEM',\n"
           "                  ZONE=(_F(FISS_MAIT=F1, " +
           zone + "), _F(FISS_MAIT=F2), _F(FISS_MAIT=F3, " + zone +
           ")))\n"
           "FIN()\n";
}

}  // namespace

TEST(ContactIntegration, EachZoneIsLoggedWithItsRule) {
    const auto r = runComm(definition(false, "INTEGRATION='NOEUD'"), kMesh2d);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("contact zone on F1: ALGO_CONT='STANDARD'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("INTEGRATION='NOEUD' (facet vertices)"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("INTEGRATION='GAUSS', ORDRE_INT=6 (SE2 FPG4)"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("ZONE[1]/INTEGRATION ("), std::string::npos) << r.output;  // not in the ignored list
    const auto n = runComm(definition(false, "INTEGRATION='NCOTES', ORDRE_INT=5"), kMesh2d);
    ASSERT_EQ(n.status, 0) << n.output;
    EXPECT_NE(n.output.find("INTEGRATION='NCOTES', ORDRE_INT=5 (SE2 COTES1)"), std::string::npos) << n.output;
    const auto t = runComm(definition(true, "INTEGRATION='GAUSS', ORDRE_INT=2"), kMesh3d);
    ASSERT_EQ(t.status, 0) << t.output;
    EXPECT_NE(t.output.find("INTEGRATION='GAUSS', ORDRE_INT=2 (TR3 FPG3)"), std::string::npos) << t.output;
    EXPECT_NE(t.output.find("INTEGRATION='GAUSS', ORDRE_INT=6 (TR3 FPG12)"), std::string::npos) << t.output;
}

TEST(ContactIntegration, OrdersOutOfTheCatalogueRangeAreRefused) {
    const std::pair<const char*, const char*> cases[] = {{"INTEGRATION='GAUSS', ORDRE_INT=7", "[1, 6]"},
                                                         {"INTEGRATION='GAUSS', ORDRE_INT=0", "[1, 6]"},
                                                         {"INTEGRATION='SIMPSON', ORDRE_INT=5", "[1, 4]"},
                                                         {"INTEGRATION='NCOTES', ORDRE_INT=2", "[3, 8]"},
                                                         {"INTEGRATION='NCOTES', ORDRE_INT=9", "[3, 8]"}};
    for (const auto& [zone, range] : cases) {
        const auto r = runComm(definition(false, zone), kMesh2d);
        EXPECT_EQ(r.status, 1) << zone << "\n" << r.output;
        EXPECT_NE(r.output.find("ZONE[1]/ORDRE_INT"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(std::string("out of range ") + range), std::string::npos) << r.output;
    }
    // NOEUD has no order.
    const auto r = runComm(definition(false, "INTEGRATION='NOEUD', ORDRE_INT=2"), kMesh2d);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("ORDRE_INT"), std::string::npos) << r.output;
}

TEST(ContactIntegration, SchemesWithoutATriangleRuleAreNotImplementedIn3D) {
    for (const char* zone :
         {"INTEGRATION='SIMPSON', ORDRE_INT=2", "INTEGRATION='NCOTES'", "INTEGRATION='NCOTES', ORDRE_INT=8"}) {
        const auto r = runComm(definition(true, zone), kMesh3d);
        EXPECT_EQ(r.status, 1) << zone;
        EXPECT_FALSE(r.exists("out/t.resu")) << "no result file after an error";
        EXPECT_NE(r.output.find("DEFI_CONTACT (t.comm, line 10): ZONE[1]/INTEGRATION='"), std::string::npos)
            << r.output;
        EXPECT_NE(r.output.find("does not substitute another one"), std::string::npos) << r.output;
    }
    // The same schemes are defined on 2D segment facets.
    const auto r = runComm(definition(false, "INTEGRATION='SIMPSON', ORDRE_INT=2"), kMesh2d);
    EXPECT_EQ(r.status, 0) << r.output;
}

namespace {

// contact_compression_3d.comm (exact uniform compression, TEST_TABLEs of the errors to 1e-8 / 1e-10)
// with `zone` added to every ZONE.
std::string compression3d(const std::string& zone) {
    std::ifstream in(std::string(MINIASTER_SOURCE_DIR) + "/astest/contact_compression_3d.comm");
    std::stringstream text;
    text << in.rdbuf();
    std::string comm = text.str();
    const std::string key = "CONTACT_INIT='OUI')";
    const auto at = comm.find(key);
    EXPECT_NE(at, std::string::npos);
    return comm.replace(at, key.size(), "CONTACT_INIT='OUI', " + zone + ")");
}

}  // namespace

TEST(ContactIntegration, TheVertexRuleOnHexa8IsReplacedAnnouncedAndExact) {
    const std::string hexa = std::string("--mesh '") + MINIASTER_SOURCE_DIR + "/astest/contact_hexa8_n5.mmed'";
    const auto r = runComm(compression3d("INTEGRATION='NOEUD'"), hexa);
    EXPECT_EQ(r.status, 0) << r.output;  // the round-off TEST_TABLEs pass: the facets took TR3 FPG3
    EXPECT_NE(r.output.find("<A> <CONTACT_INTEGRATION>"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("FISS"), std::string::npos);
    EXPECT_NE(r.output.find("with INTEGRATION='GAUSS', ORDRE_INT=1 (TR3 FPG3) instead"), std::string::npos) << r.output;
    // GAUSS 1 (TR3 FPG3, degree 2) integrates the bilinear traces as asked: exact, no alarm.
    const auto g = runComm(compression3d("INTEGRATION='GAUSS', ORDRE_INT=1"), hexa);
    EXPECT_EQ(g.status, 0) << g.output;
    EXPECT_EQ(g.output.find("CONTACT_INTEGRATION"), std::string::npos);
    // TETRA4: linear traces, the vertex rule is exact and kept, silently.
    const std::string tetra = std::string("--mesh '") + MINIASTER_SOURCE_DIR + "/astest/contact_tetra4_n5.mmed'";
    const auto t = runComm(compression3d("INTEGRATION='NOEUD'"), tetra);
    EXPECT_EQ(t.status, 0) << t.output;
    EXPECT_EQ(t.output.find("CONTACT_INTEGRATION"), std::string::npos);
}
