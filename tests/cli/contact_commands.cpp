// DEFI_CONTACT and STAT_NON_LINE with contact through the supervisor on ssnv511a's mesh: the model
// must come from MODI_MODELE_XFEM(CONTACT='STANDARD'), unsupported formulations and friction are
// refused, ignored code_aster settings are named in the log, ITER_CONT_MAXI reached is an error
// and the contact loop is logged.
#include <gtest/gtest.h>

#include <string>

#include "parser_run.hpp"
#include "ssnv511_scene.hpp"

using namespace ma::test;

namespace {

const std::string kMesh = std::string("--mesh '") + MINIASTER_SHARED_DIR + "/astest/ssnv511a.mmed'";

std::string scene(const std::string& contact) {
    return ssnv511Preamble() + contact;
}

const std::string kXfemContact = "MX = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=(F1, F2, F3), CONTACT='OUI')\n";

// Blocks pulled apart by their edges, ITER_CONT_MAXI given.
std::string pulled(int iterContMaxi) {
    return scene(kXfemContact +
                 "CT = DEFI_CONTACT(MODELE=MX, FORMULATION='XFEM', ITER_CONT_MAXI=" + std::to_string(iterContMaxi) +
                 ", ELIM_ARETE='ELIM', ZONE=[_F(FISS_MAIT=F, CONTACT_INIT='OUI', INTEGRATION='NOEUD', "
                 "ALGO_LAGR='VERSION2') for F in (F1, F2, F3)])\n"
                 "MAT = DEFI_MATERIAU(ELAS=_F(E=1.0e8, NU=0.3))\n"
                 "CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))\n"
                 "CH = AFFE_CHAR_MECA(MODELE=MX, DDL_IMPO=(_F(GROUP_MA='LG', DX=-0.01, H1X=0.), "
                 "_F(GROUP_MA='LD', DX=0.01, H1X=0.), _F(GROUP_MA='LB', DY=-0.01, H1Y=0.), "
                 "_F(GROUP_MA='LH', DY=0.01, H1Y=0.)))\n"
                 "LI = DEFI_LIST_REEL(DEBUT=0., INTERVALLE=_F(JUSQU_A=1., NOMBRE=1))\n"
                 "R = STAT_NON_LINE(MODELE=MX, CHAM_MATER=CM, CONTACT=CT, EXCIT=_F(CHARGE=CH), "
                 "COMPORTEMENT=_F(RELATION='ELAS'), INCREMENT=_F(LIST_INST=LI))\n"
                 "FIN()\n");
}

}  // namespace

TEST(ContactCommands, ModelWithoutContactIsRefused) {
    const auto r = runComm(scene("MX = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=(F1, F2, F3))\n"
                                 "CT = DEFI_CONTACT(MODELE=MX, FORMULATION='XFEM', ZONE=_F(FISS_MAIT=F1))\n"
                                 "FIN()\n"),
                           kMesh);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("was made without contact; use MODI_MODELE_XFEM(..., CONTACT='STANDARD')"),
              std::string::npos)
        << r.output;
    const auto c = runComm(scene("CT = DEFI_CONTACT(MODELE=MO, FORMULATION='XFEM', ZONE=_F(FISS_MAIT=F1))\nFIN()\n"),
                           kMesh);
    EXPECT_EQ(c.status, 1);
    EXPECT_NE(c.output.find("is not an X-FEM model"), std::string::npos) << c.output;
}

TEST(ContactCommands, OtherFormulationsAndFrictionAreNotSupported) {
    const auto r = runComm(scene(kXfemContact + "CT = DEFI_CONTACT(MODELE=MX, FORMULATION='CONTINUE', "
                                                "ZONE=_F(FISS_MAIT=F1))\nFIN()\n"),
                           kMesh);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("not supported by miniaster"), std::string::npos) << r.output;
    const auto f = runComm(scene(kXfemContact + "CT = DEFI_CONTACT(MODELE=MX, FORMULATION='XFEM', FROTTEMENT='COULOMB', "
                                                "ZONE=_F(FISS_MAIT=F1))\nFIN()\n"),
                           kMesh);
    EXPECT_EQ(f.status, 1);
    EXPECT_NE(f.output.find("not supported by miniaster"), std::string::npos) << f.output;
}

TEST(ContactCommands, PulledApartReleasesEveryPointAndLogsTheLoop) {
    const auto r = runComm(pulled(5), kMesh);
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("keywords accepted but ignored"), std::string::npos);
    EXPECT_NE(r.output.find("ELIM_ARETE"), std::string::npos);
    EXPECT_NE(r.output.find("ZONE[1]/ALGO_LAGR"), std::string::npos);
    // INTEGRATION='NOEUD': one point at each end of the 22 facets.
    EXPECT_NE(r.output.find("contact iteration 1: 44 status change(s), 0 active"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("contact iteration 2: 0 status change(s), 0 active"), std::string::npos);
}

TEST(ContactCommands, IterContMaxiReachedIsAnError) {
    const auto r = runComm(pulled(1), kMesh);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("contact did not converge at INST 1 in 1 contact iterations (ITER_CONT_MAXI)"),
              std::string::npos)
        << r.output;
}
