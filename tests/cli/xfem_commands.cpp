// The X-FEM commands through the supervisor on ssnv511a's mesh: the log counts of DEFI_FISS_XFEM
// and MODI_MODELE_XFEM, and the user errors (order of FISSURE, POINT on the master interface,
// unsupported TYPE_DISCONTINUITE), the sub-cell rules in the log (with --subcell-quadrature).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <string>

#include "parser_run.hpp"
#include "ssnv511_scene.hpp"

using namespace ma::test;

namespace {

const std::string kMesh = std::string("--mesh '") + MINIASTER_SHARED_DIR + "/astest/ssnv511a.mmed'";

std::string head(const std::string& ln1) { return ssnv511Preamble({.ln1 = ln1, .prefix = "FISS", .interfaces = 1}); }

}  // namespace

TEST(XfemCommands, CountsInTheLog) {
    const auto r = runComm(ssnv511Preamble({.prefix = "FISS"}) +
                               "MX = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=(FISS1, FISS2, FISS3))\n"
                               "MV = POST_MAIL_XFEM(MODELE=MX)\n"
                               "FIN()\n",
                           kMesh);
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("interface (FISS1): 7 cut cells, 12 Heaviside-enriched nodes"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("interface (FISS2): 7 cut cells, 8 Heaviside-enriched nodes"), std::string::npos);
    EXPECT_NE(r.output.find("junction on FISS1: the interface exists where -1 * LSN(FISS1) < 0"), std::string::npos);
    EXPECT_NE(r.output.find("21 X-FEM elements (84 sub-cells), 20 enriched nodes (4 with several Heaviside"),
              std::string::npos);
    EXPECT_NE(r.output.find("9 element(s) seeing 3 interface(s), 3 Heaviside slot(s) per node"), std::string::npos);
    EXPECT_NE(r.output.find("smallest retained enrichment support fraction"), std::string::npos);
    EXPECT_NE(r.output.find("visualisation mesh: 164 nodes (16 copied, 148 new of which 64 on the interfaces in "
                            "group NFISSU), 88 cells (4 copied, 84 sub-cells MX...)"),
              std::string::npos);
}

TEST(XfemCommands, MasterMustComeFirst) {
    const auto r = runComm(head("Y") +
                               "FISS2 = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='INTERFACE', "
                               "DEFI_FISS=_F(FONC_LN=LN2), JONCTION=_F(FISSURE=FISS1, POINT=(0, 5)))\n"
                               "MX = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=(FISS2, FISS1))\n"
                               "FIN()\n",
                           kMesh);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("crack FISS2 is joined (JONCTION) to crack FISS1, which must be listed before it"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("MODI_MODELE_XFEM"), std::string::npos);
}

TEST(XfemCommands, PointOnTheMasterInterface) {
    // FISS1 through the node row y = 1: POINT=(0.9, 1) lies on it; (0.9, 1.2), whose closest node
    // (1, 1) lies on it, is above it (the side is the level set's at the point, tests/cli/input_checks.cpp).
    auto run = [](const std::string& point) {
        return runComm(head("Y-1") +
                           "FISS2 = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='INTERFACE', "
                           "DEFI_FISS=_F(FONC_LN=LN2), JONCTION=_F(FISSURE=FISS1, POINT=" +
                           point + "))\nFIN()\n",
                       kMesh);
    };
    auto r = run("(0.9, 1.0)");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("JONCTION[1]/POINT=(0.9, 1): the level set of the master interface FISS1 is 0 at that "
                            "point"),
              std::string::npos)
        << r.output;
    r = run("(0.9, 1.2)");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("junction on FISS1: the interface exists where -1 * LSN(FISS1) < 0"), std::string::npos)
        << r.output;
}

TEST(XfemCommands, OutsideAndUnsupported) {
    auto r = runComm(head("Y-20") + "FIN()\n", kMesh);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("does not cut any cell of the mesh"), std::string::npos) << r.output;
    r = runComm(head("Y") +
                    "F = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='FISSURE', DEFI_FISS=_F(FONC_LN=LN2))\n"
                    "FIN()\n",
                kMesh);
    EXPECT_NE(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("TYPE_DISCONTINUITE='FISSURE'"), std::string::npos) << r.output;
}

// The .mess of MODI_MODELE_XFEM tells which rule each kind of sub-cell uses and whether it comes
// from the catalogue or from `--subcell-quadrature` (the skin keeps the catalogue's rule).
TEST(XfemCommands, SubcellQuadratureInTheLog) {
    const std::string comm = ssnv511Preamble({.groups = "('SURF', 'LH', 'LD')", .prefix = "FISS"}) +
                             "MX = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=(FISS1, FISS2, FISS3))\n"
                             "FIN()\n";
    // Sub-cells per kind, read from the catalogue run and checked against the rule sizes.
    const std::regex line(R"(      (volume|skin) sub-cells, (one interface|several interfaces): (SEG2|TRIA3) (FPG\d+) )"
                          R"(\(degree (\d), ([^)]*)\), (\d+) sub-cells, (\d+) points)");
    struct Kind {
        std::string type, rule, origin;
        int degree = 0, subcells = 0, points = 0;
    };
    auto kinds = [&](const std::string& out) {
        std::map<std::string, Kind> k;
        for (std::sregex_iterator it(out.begin(), out.end(), line), end; it != end; ++it) {
            const auto& m = *it;
            k[m[1].str() + ", " + m[2].str()] = {m[3], m[4], m[6], std::stoi(m[5]), std::stoi(m[7]), std::stoi(m[8])};
        }
        return k;
    };

    const auto r0 = runComm(comm, kMesh);
    ASSERT_EQ(r0.status, 0) << r0.output;
    const std::string mess = r0.file("out/t.mess");
    EXPECT_NE(mess.find("    sub-cell quadrature: catalogue (the rules of code_aster's X-FEM element catalogues)\n"),
              std::string::npos)
        << mess;
    const auto k0 = kinds(mess);
    ASSERT_EQ(k0.size(), 3u) << mess;  // volume with one and several interfaces, skin with one (LH, LD)
    const auto& mono = k0.at("volume, one interface");
    const auto& multi = k0.at("volume, several interfaces");
    EXPECT_EQ(mono.type + " " + mono.rule + " " + mono.origin, "TRIA3 FPG12 catalogue");
    EXPECT_EQ(multi.type + " " + multi.rule + " " + multi.origin, "TRIA3 FPG4 catalogue");
    EXPECT_EQ(k0.at("skin, one interface").type + " " + k0.at("skin, one interface").rule, "SEG2 FPG4");
    EXPECT_EQ(mono.subcells + multi.subcells, 84);  // the 84 sub-cells of XfemCommands.CountsInTheLog
    EXPECT_EQ(mono.points, 12 * mono.subcells);
    EXPECT_EQ(multi.points, 4 * multi.subcells);
    const int skinPoints = k0.at("skin, one interface").points;
    EXPECT_EQ(skinPoints, 4 * k0.at("skin, one interface").subcells);
    // 21 volume X-FEM elements (XfemCommands.CountsInTheLog), 6 skin ones (27 X-FEM elements in all)
    EXPECT_NE(mess.find(
                  fmt::format("    sub-cell integration points: {} (volume {} in 21 elements, skin {} in 6) on 92 "
                              "sub-cells\n",
                              mono.points + multi.points + skinPoints, mono.points + multi.points, skinPoints)),
              std::string::npos)
        << mess;

    const auto r2 = runComm(comm, kMesh + " --subcell-quadrature 2");
    ASSERT_EQ(r2.status, 0) << r2.output;
    const std::string mess2 = r2.file("out/t.mess");
    EXPECT_NE(mess2.find("    sub-cell quadrature: degree 2 (--subcell-quadrature 2, a miniaster run option, not a "
                         "code_aster keyword)"),
              std::string::npos)
        << mess2;
    const auto k2 = kinds(mess2);
    ASSERT_EQ(k2.size(), 3u);
    EXPECT_EQ(k2.at("volume, one interface").rule + " " + k2.at("volume, one interface").origin,
              "FPG3 override of the catalogue's FPG12");
    EXPECT_EQ(k2.at("volume, several interfaces").rule + " " + k2.at("volume, several interfaces").origin,
              "FPG3 override of the catalogue's FPG4");
    EXPECT_EQ(k2.at("volume, one interface").degree, 2);
    EXPECT_EQ(k2.at("volume, one interface").points + k2.at("volume, several interfaces").points, 3 * 84);
    EXPECT_EQ(k2.at("skin, one interface").rule + " " + k2.at("skin, one interface").origin,
              "FPG4 catalogue, not overridden");
    EXPECT_EQ(k2.at("skin, one interface").points, k0.at("skin, one interface").points);

    const auto r6 = runComm(comm, kMesh + " --subcell-quadrature 6");
    ASSERT_EQ(r6.status, 0) << r6.output;
    const auto k6 = kinds(r6.file("out/t.mess"));
    EXPECT_EQ(k6.at("volume, one interface").origin, "override, the same as the catalogue's FPG12");
    EXPECT_EQ(k6.at("volume, several interfaces").rule, "FPG12");
    EXPECT_EQ(k6.at("volume, several interfaces").points, 12 * multi.subcells);
}

// HEXA8 parents with degree 1 on their sub-tetrahedra: the trilinear strains are not integrated
// exactly, the uniform stress with contact of astest/contact_hexa8_n5 is lost (its TEST_TABLEs are
// NOOK) and the .mess says why (alarm XFEM_SUBCELL_RULE); degree 2 keeps the exact answer.
TEST(XfemCommands, Hexa8AtDegreeOneIsAlarmed) {
    auto dir = freshDir();
    const std::string exportFile = std::string(MINIASTER_SOURCE_DIR) + "/astest/contact_hexa8_n5.export";
    auto r = runMiniaster(dir, exportFile, "--subcell-quadrature 1");
    EXPECT_EQ(r.status, 2) << r.output;
    const std::string mess = r.file("out/contact_hexa8_n5.mess");
    EXPECT_NE(mess.find("! <A> <XFEM_SUBCELL_RULE>"), std::string::npos) << mess;
    EXPECT_NE(mess.find("--subcell-quadrature 1: the strains of the HEXA8 shape functions are polynomials of degree 2 "
                        "on the sub-cells, which the rule FPG1 does not integrate exactly"),
              std::string::npos)
        << mess;
    EXPECT_NE(mess.find("--- DIAGNOSTIC JOB : NOOK_TEST_RESU"), std::string::npos);
    r = runMiniaster(freshDir(), exportFile, "--subcell-quadrature 2");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.file("out/contact_hexa8_n5.mess").find("XFEM_SUBCELL_RULE"), std::string::npos);
}

// JONCTION/POINT with fewer coordinates than the mesh: the missing ones are 0, as code_aster
// (ssnv510f gives POINT=(0,4) on a 3D mesh); same interface as with (0, 5, 0).
TEST(XfemCommands, JonctionPointMissingCoordinatesAreZero) {
    const std::string mesh = std::string("--mesh '") + MINIASTER_SHARED_DIR + "/astest/ssnv511g.mmed'";
    auto run = [&](const std::string& point) {
        return runComm(
            "DEBUT()\n"
            "MA = LIRE_MAILLAGE(FORMAT='MED')\n"
            "LN1 = FORMULE(VALE='Y', NOM_PARA=['X', 'Y', 'Z'])\n"
            "LN2 = FORMULE(VALE='X', NOM_PARA=['X', 'Y', 'Z'])\n"
            "FISS1 = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='INTERFACE', DEFI_FISS=_F(FONC_LN=LN1))\n"
            "FISS2 = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='INTERFACE', DEFI_FISS=_F(FONC_LN=LN2),"
            " JONCTION=_F(FISSURE=FISS1, POINT=" +
                point +
                "))\n"
                "FIN()\n",
            mesh);
    };
    const auto two = run("(0, 5)"), three = run("(0, 5, 0)");
    ASSERT_EQ(two.status, 0) << two.output;
    ASSERT_EQ(three.status, 0) << three.output;
    EXPECT_NE(two.output.find(
                  "JONCTION[1]/POINT: 2 coordinate(s) given on a mesh of dimension 3; the missing ones are 0"),
              std::string::npos)
        << two.output;
    const std::regex counts("interface \\(FISS2\\): [^\\n]*");
    std::smatch a, b;
    ASSERT_TRUE(std::regex_search(two.output, a, counts));
    ASSERT_TRUE(std::regex_search(three.output, b, counts));
    EXPECT_EQ(a.str(), b.str());
    EXPECT_NE(two.output.find("junction on FISS1: the interface exists where -1 * LSN(FISS1) < 0"), std::string::npos);
}
