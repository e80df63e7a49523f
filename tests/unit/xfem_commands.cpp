// The X-FEM commands through the supervisor on ssnv511a's mesh: the log counts of DEFI_FISS_XFEM
// and MODI_MODELE_XFEM, and the user errors (order of FISSURE, POINT on the master interface,
// unsupported TYPE_DISCONTINUITE).
#include <gtest/gtest.h>

#include <string>

#include "parser_run.hpp"

using namespace ma::test;

namespace {

const std::string kMesh = std::string("--mesh '") + MINIASTER_SHARED_DIR + "/astest/ssnv511a.mmed'";

std::string head(const std::string& ln1) {
    return "DEBUT()\n"
           "MA = LIRE_MAILLAGE(FORMAT='MED')\n"
           "MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA='SURF', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))\n"
           "LN1 = FORMULE(VALE='" + ln1 + "', NOM_PARA=['X', 'Y'])\n"
           "LN2 = FORMULE(VALE='X', NOM_PARA=['X', 'Y'])\n"
           "FISS1 = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='INTERFACE', DEFI_FISS=_F(FONC_LN=LN1))\n";
}

}  // namespace

TEST(XfemCommands, CountsInTheLog) {
    const auto r = runComm(head("Y") +
                               "FISS2 = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='INTERFACE', "
                               "DEFI_FISS=_F(FONC_LN=LN2), JONCTION=_F(FISSURE=FISS1, POINT=(0, 5)))\n"
                               "FISS3 = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='INTERFACE', "
                               "DEFI_FISS=_F(FONC_LN=LN2), JONCTION=_F(FISSURE=FISS1, POINT=(0, -5)))\n"
                               "MX = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=(FISS1, FISS2, FISS3))\n"
                               "MV = POST_MAIL_XFEM(MODELE=MX)\n"
                               "FIN()\n",
                           kMesh);
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("interface (FISS1): 7 cut cells, 12 Heaviside-enriched nodes"), std::string::npos) << r.output;
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
    // FISS1 through the node row y = 1; POINT's closest node (1, 1) lies on it.
    const auto r = runComm(head("Y-1") +
                               "FISS2 = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='INTERFACE', "
                               "DEFI_FISS=_F(FONC_LN=LN2), JONCTION=_F(FISSURE=FISS1, POINT=(0.9, 1.2)))\n"
                               "FIN()\n",
                           kMesh);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("lies on the interface of the master crack FISS1"), std::string::npos) << r.output;
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
