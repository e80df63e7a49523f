// CALC_G and POST_K1_K2_K3 through the supervisor before crack-tip enrichment is merged: what is not
// implemented is refused by the static check before the first command (CHAM_THETA,
// TYPE_MAILLAGE), and a crack without front (ssnv511e's interfaces) is a
// user error naming the crack. The values are checked by tests/unit/fracture_*.cpp on exact fields.
#include <gtest/gtest.h>

#include "med_test_support.hpp"
#include "parser_run.hpp"

namespace {

ma::test::RunResult runOnSsnv511e(const std::string& extra) {
    const auto dir = ma::test::freshDir();
    const std::string comm = ma::test::readText(ma::test::astest("ssnv511e.comm"));
    ma::test::writeText(dir / "t.comm", ma::test::beforeFin(comm, extra));
    return ma::test::runMiniaster(dir, "t.comm", "--mesh '" + ma::test::astest("ssnv511a.mmed") + "'");
}

TEST(FractureCommandsStatic, UnimplementedKeywordsAreRefusedBeforeTheSolve) {
    const auto r = runOnSsnv511e(
        "G = CALC_G(RESULTAT=UTOT1, THETA=_F(FISSURE=FISS1), CHAM_THETA=CO('TH'))\n"
        "K = POST_K1_K2_K3(FISSURE=FISS1, RESULTAT=UTOT1, TYPE_MAILLAGE='LIBRE')\n");
    EXPECT_EQ(r.status, 1) << r.output;
    const std::string mess = r.file("out/t.mess");
    EXPECT_NE(mess.find("problems found in the command file before its first command (none was run)"),
              std::string::npos)
        << mess;
    EXPECT_NE(mess.find("CALC_G: keyword CHAM_THETA is not supported by miniaster"), std::string::npos) << mess;
    EXPECT_NE(mess.find("POST_K1_K2_K3: keyword TYPE_MAILLAGE is not supported by miniaster"), std::string::npos)
        << mess;
    EXPECT_EQ(mess.find("STAT_NON_LINE("), std::string::npos);  // nothing ran
}

TEST(FractureCommands, InterfaceHasNoFront) {
    for (const std::string call : {"G = CALC_G(RESULTAT=UTOT1, OPTION='CALC_K_G', THETA=_F(FISSURE=FISS2))\n",
                                   "K = POST_K1_K2_K3(FISSURE=FISS2, RESULTAT=UTOT1)\n"}) {
        const auto r = runOnSsnv511e(call);
        EXPECT_EQ(r.status, 1) << r.output;
        const std::string mess = r.file("out/t.mess");
        EXPECT_NE(mess.find("FISS2 has no front in the mesh: there is no stress intensity to compute"),
                  std::string::npos)
            << mess;
    }
}

// The theta method takes the lip pressure's term (astest/glip_griffith_pressure checks its values)
// but not the volume forces': a result loaded by FORCE_INTERNE is refused at CALC_G, after the
// solves. The force is on every cell, classical cells following crack-tip cells in the load loop
// (which once kept the previous cell's crack-tip terms: an internal error at MECA_STATIQUE).
TEST(FractureCommands, VolumeForcesAreRefusedByTheThetaMethod) {
    const auto dir = ma::test::freshDir();
    const std::string comm =
        ma::test::readText(std::string(MINIASTER_SOURCE_DIR) + "/astest/glip_griffith_pressure.comm");
    const auto cut = comm.find("lam = A / 1.");
    ASSERT_NE(cut, std::string::npos);
    ma::test::writeText(dir / "t.comm",
                        comm.substr(0, cut) +
                            "FV = AFFE_CHAR_MECA(MODELE=MX, FORCE_INTERNE=_F(TOUT='OUI', FY=1.))\n"
                            "RV = MECA_STATIQUE(MODELE=MX, CHAM_MATER=CM, EXCIT=(_F(CHARGE=BC), _F(CHARGE=FV)))\n"
                            "T = CALC_G(RESULTAT=RV, THETA=_F(FISSURE=FISS))\nFIN()\n");
    const auto r =
        ma::test::runMiniaster(dir, "t.comm",
                               "--mesh '" + std::string(MINIASTER_SOURCE_DIR) + "/astest/glip_griffith_n40.mmed'");
    EXPECT_EQ(r.status, 1) << r.output;
    const std::string mess = r.file("out/t.mess");
    EXPECT_NE(mess.find("CALC_G with the load FV of result RV: volume forces enter the theta method's right-hand "
                        "side, which miniaster does not compute yet"),
              std::string::npos)
        << mess;
    EXPECT_NE(mess.find("# end of MECA_STATIQUE"), std::string::npos);
}

}  // namespace
