// DEFI_CONTACT and STAT_NON_LINE with contact through the supervisor on ssnv511a's mesh: the model
// must come from MODI_MODELE_XFEM(CONTACT='STANDARD'), unsupported formulations and friction are
// refused, ignored code_aster settings are named in the log, ITER_CONT_MAXI reached is an error
// and the contact loop is logged.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "parser_run.hpp"
#include "ssnv511_scene.hpp"

using namespace ma::test;

namespace {

const std::string kMesh = std::string("--mesh '") + MINIASTER_SHARED_DIR + "/astest/ssnv511a.mmed'";

std::string scene(const std::string& contact) { return ssnv511Preamble() + contact; }

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
    const auto c =
        runComm(scene("CT = DEFI_CONTACT(MODELE=MO, FORMULATION='XFEM', ZONE=_F(FISS_MAIT=F1))\nFIN()\n"), kMesh);
    EXPECT_EQ(c.status, 1);
    EXPECT_NE(c.output.find("is not an X-FEM model"), std::string::npos) << c.output;
}

TEST(ContactCommands, OtherFormulationsAndFrictionAreNotSupported) {
    const auto r = runComm(scene(kXfemContact + "CT = DEFI_CONTACT(MODELE=MX, FORMULATION='CONTINUE', "
                                                "ZONE=_F(FISS_MAIT=F1))\nFIN()\n"),
                           kMesh);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("not supported by miniaster"), std::string::npos) << r.output;
    const auto f =
        runComm(scene(kXfemContact + "CT = DEFI_CONTACT(MODELE=MX, FORMULATION='XFEM', FROTTEMENT='COULOMB', "
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
    EXPECT_NE(r.output.find("contact iteration 1: 44 status change(s) (0 activated, 44 released), 0 active"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("contact iteration 2: 0 status change(s) (0 activated, 0 released), 0 active"),
              std::string::npos);
}

TEST(ContactCommands, IterContMaxiReachedIsAnError) {
    const auto r = runComm(pulled(1), kMesh);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("contact did not converge at INST 1 in 1 contact iterations (ITER_CONT_MAXI)"),
              std::string::npos)
        << r.output;
}

TEST(ContactCommands, AContactLoopThatCannotConvergeNamesThePointsThatKeepChanging) {
    // ssnv513g (3D HEXA8, the inclined interface of the F junction) stopped after 2 contact iterations:
    // its active set is still settling (537 -> 516 -> 510 points on code_aster's mesh, whose
    // left-handed cells are cut into other sub-cells than a right-handed numbering would give), the
    // error names the points that changed, where they are and their gap and contact function.
    std::ifstream in(std::string(MINIASTER_SHARED_DIR) + "/astest/ssnv513g.comm");
    std::stringstream text;
    text << in.rdbuf();
    std::string comm = text.str();
    const auto at = comm.find("ITER_CONT_MAXI = 10");
    ASSERT_NE(at, std::string::npos);
    comm.replace(at, std::string("ITER_CONT_MAXI = 10").size(), "ITER_CONT_MAXI = 2");
    const auto r = runComm(comm, std::string("--mesh '") + MINIASTER_SHARED_DIR + "/astest/ssnv511g.mmed'");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("contact did not converge at INST 1 in 2 contact iterations (ITER_CONT_MAXI): 6 status "
                            "change(s) at the last one, 510 active points"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("Points whose status changed at the last update:\n  FISS1 point at ("), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("facet in cell M"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("1 status change(s), now inactive, gap "), std::string::npos) << r.output;
}

namespace {

// The pressed scene of the 2013 syntax: the contact CT given as the load CHC
// (AFFE_CHAR_MECA(LIAISON_XFEM='OUI', CONTACT_XFEM=CT)); `solve` completes the STAT_NON_LINE call.
std::string legacy(const std::string& extra, const std::string& solve) {
    return scene(
        "MX = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=(F1, F2, F3), CONTACT='P1P1')\n"
        "CT = DEFI_CONTACT(MODELE=MX, FORMULATION='XFEM', "
        "ZONE=[_F(FISS_MAIT=F, CONTACT_INIT='OUI', INTEGRATION='NOEUD') for F in (F1, F2, F3)])\n"
        "MAT = DEFI_MATERIAU(ELAS=_F(E=1.0e8, NU=0.3))\n"
        "CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))\n"
        "CH = AFFE_CHAR_MECA(MODELE=MX, DDL_IMPO=(_F(GROUP_MA='LG', DX=0., H1X=0.), "
        "_F(GROUP_MA='LB', DY=0., H1Y=0.), _F(GROUP_MA='LD', DX=-0.01, H1X=0.), "
        "_F(GROUP_MA='LH', DY=-0.01, H1Y=0.)))\n"
        "CHC = AFFE_CHAR_MECA(MODELE=MX, LIAISON_XFEM='OUI', CONTACT_XFEM=CT)\n"
        "LI = DEFI_LIST_REEL(DEBUT=0., INTERVALLE=_F(JUSQU_A=1., NOMBRE=1))\n" +
        extra + "R = STAT_NON_LINE(MODELE=MX, CHAM_MATER=CM, COMP_ELAS=_F(RELATION='ELAS'), " + solve +
        "INCREMENT=_F(LIST_INST=LI))\nFIN()\n");
}

// legacy(extra, solve) stops with exit 1 and an error containing `message`.
void expectLegacyRefused(const std::string& extra, const std::string& solve, const std::string& message) {
    const auto r = runComm(legacy(extra, solve), kMesh);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
}

}  // namespace

TEST(ContactCommands, TheContactLoadOf2013IsTheContactOfTheSolve) {
    const auto r = runComm(legacy("", "EXCIT=(_F(CHARGE=CH), _F(CHARGE=CHC)), "), kMesh);
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find(
                  "MODI_MODELE_XFEM: CONTACT='P1P1' (an older code_aster syntax) is read as CONTACT='STANDARD'"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("LIAISON_XFEM='OUI' (code_aster <= 2013): the X-FEM relations it added were those between "
                            "the contact multipliers"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("EXCIT[2]/CHARGE=CHC (CONTACT_XFEM=CT): the contact of this solve, as with CONTACT=CT"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("contact iteration 1: 0 status change(s)"), std::string::npos) << r.output;
    // Given both ways, it is the same contact.
    const auto both = runComm(legacy("", "CONTACT=CT, EXCIT=(_F(CHARGE=CH), _F(CHARGE=CHC)), "), kMesh);
    EXPECT_EQ(both.status, 0) << both.output;
    EXPECT_NE(both.output.find("EXCIT[2]/CHARGE=CHC (CONTACT_XFEM=CT): the same contact as CONTACT"), std::string::npos)
        << both.output;
}

TEST(ContactCommands, TheContactLoadOf2013IsRefusedOnlyWhereItConflicts) {
    expectLegacyRefused("CT2 = DEFI_CONTACT(MODELE=MX, FORMULATION='XFEM', ZONE=_F(FISS_MAIT=F1))\n",
                        "CONTACT=CT2, EXCIT=(_F(CHARGE=CH), _F(CHARGE=CHC)), ",
                        "STAT_NON_LINE (t.comm, line 17): two contact definitions for one solve: CONTACT gives CT2, "
                        "EXCIT[2]/CHARGE=CHC (CONTACT_XFEM=CT) gives CT.");
    // The contact of another model.
    expectLegacyRefused(
        "MX2 = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=(F1, F2, F3), CONTACT='STANDARD')\n"
        "CH2 = AFFE_CHAR_MECA(MODELE=MX2, LIAISON_XFEM='OUI', CONTACT_XFEM=CT)\n",
        "EXCIT=_F(CHARGE=CH), ",
        "CONTACT_XFEM: CT was defined on the model MX, this load on MODELE MX2 (code_aster XFEM2_11");
    // LIAISON_XFEM on a model without X-FEM.
    expectLegacyRefused("CH3 = AFFE_CHAR_MECA(MODELE=MO, LIAISON_XFEM='OUI')\n", "EXCIT=_F(CHARGE=CH), ",
                        "LIAISON_XFEM='OUI': the model MO is not an X-FEM model");
    // MECA_STATIQUE solves no contact.
    expectLegacyRefused("RL = MECA_STATIQUE(MODELE=MX, CHAM_MATER=CM, EXCIT=(_F(CHARGE=CH), _F(CHARGE=CHC)))\n",
                        "EXCIT=_F(CHARGE=CH), ",
                        "): EXCIT[2]/CHARGE=CHC carries the X-FEM contact CT (AFFE_CHAR_MECA/CONTACT_XFEM); "
                        "MECA_STATIQUE solves no contact: use STAT_NON_LINE");
}
