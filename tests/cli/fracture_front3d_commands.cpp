// CALC_G on a 3D front through the supervisor (ssnv185c's mesh and faces-pressure case, the solve of
// astest/g3d_ssnv185c_faces.comm): a LISSAGE pair that code_aster refuses for a fiss_xfem is a user
// error naming the keyword and code_aster's message, after the solve, with no table written. The
// values are checked by unit/fracture_front3d.cpp and astest/g3d_ssnv185c_faces.
#include <gtest/gtest.h>

#include "med_test_support.hpp"
#include "parser_run.hpp"

namespace {

TEST(FractureFront3DCommands, LegendreThetaWithLagrangeGIsRefused) {
    const auto dir = ma::test::freshDir();
    const std::string comm = ma::test::readText(std::string(MINIASTER_SOURCE_DIR) + "/astest/g3d_ssnv185c_faces.comm");
    const auto cut = comm.find("# The edge-cracked strip");
    ASSERT_NE(cut, std::string::npos);
    ma::test::writeText(dir / "t.comm",
                        comm.substr(0, cut) +
                            "T = CALC_G(RESULTAT=U, OPTION='CALC_K_G', THETA=_F(FISSURE=FISS, R_INF=1., R_SUP=2.),\n"
                            "           LISSAGE=_F(LISSAGE_THETA='LEGENDRE', LISSAGE_G='LAGRANGE'))\nFIN()\n");
    const auto r = ma::test::runMiniaster(dir, "t.comm", "--mesh '" + ma::test::astest("ssnv185c.mmed") + "'");
    EXPECT_EQ(r.status, 1) << r.output;
    const std::string mess = r.file("out/t.mess");
    EXPECT_NE(mess.find("LISSAGE[1]/LISSAGE_G: LISSAGE_THETA='LEGENDRE' with LISSAGE_G='LAGRANGE' is not a smoothing "
                        "of CALC_G on an X-FEM crack (code_aster's RUPTURE0_86)"),
              std::string::npos)
        << mess;
    EXPECT_NE(mess.find("# end of MECA_STATIQUE"), std::string::npos);  // refused at CALC_G, after the solve
}

}  // namespace
