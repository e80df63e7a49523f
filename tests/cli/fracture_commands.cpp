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

}  // namespace
