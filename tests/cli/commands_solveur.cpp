// SOLVEUR PRETRAITEMENTS / POSTTRAITEMENTS (MUMPS keywords, code_aster's meaning; docs/fe.md):
// each setting is logged, reaches the solver (its own scaling and refinement lines change) and
// leaves the answer unchanged (ssnv511a's rigid block translations, exact to round-off).
#include <gtest/gtest.h>

#include <cstdlib>
#include <regex>
#include <sstream>
#include <string>

#include "parser_run.hpp"
#include "ssnv511_scene.hpp"

using namespace ma::test;

namespace {

const std::string kMesh = std::string("--mesh '") + MINIASTER_SHARED_DIR + "/astest/ssnv511a.mmed'";

// ssnv511a's rigid scene with the given SOLVEUR keywords; POST_ERREUR against the exact field.
std::string rigid(const std::string& solveur) {
    return ssnv511Preamble() +
           "MX = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=(F1, F2, F3))\n"
           "MAT = DEFI_MATERIAU(ELAS=_F(E=1.0e8, NU=0.3))\n"
           "CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))\n"
           "def depx(x, y):\n"
           "    if y >= 0 and x < 0: return -0.25\n"
           "    if y < 0 and x < 0: return -0.5\n"
           "    if y >= 0 and x >= 0: return 0.75\n"
           "    return 1.0\n"
           "DX = FORMULE(VALE='depx(X, Y)', depx=depx, NOM_PARA=['X', 'Y'])\n"
           "ZERO = FORMULE(VALE='0.0 * X', NOM_PARA=['X', 'Y'])\n"
           "CH = AFFE_CHAR_MECA_F(MODELE=MX, DDL_IMPO=_F(GROUP_MA=('LD', 'LG'), DX=DX, DY=ZERO))\n"
           "R = MECA_STATIQUE(MODELE=MX, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH), SOLVEUR=_F(" +
           solveur +
           "))\n"
           "U = CREA_CHAMP(OPERATION='EXTR', TYPE_CHAM='NOEU_DEPL_R', RESULTAT=R, NOM_CHAM='DEPL', NUME_ORDRE=1)\n"
           "T = POST_ERREUR(OPTION='DEPL_RELA', CHAM_GD=U, MODELE=MX, GROUP_MA='SURF', DX=DX, DY=ZERO)\n"
           "IMPR_TABLE(TABLE=T, FORMAT_R='E24.16')\n"
           "FIN()\n";
}

struct Solved {
    std::string log;
    double l2 = -1.0;      // relative L2 error of the rigid answer (TOTAL row)
    int refinements = -1;  // steps reported by the solve line (0 when none)
    bool scaled = false;   // the solver's scaling line is present
};

Solved solve(const std::string& solveur) {
    const auto r = runComm(rigid(solveur), kMesh);
    EXPECT_EQ(r.status, 0) << r.output;
    Solved s;
    s.log = r.output;
    std::smatch m;
    // TOTAL  DIFFERENCE  REFERENCE  ERREUR RELATIVE
    if (std::regex_search(s.log, m, std::regex(R"(\n\s*TOTAL\s+(\S+)\s+(\S+)\s+(\S+))"))) s.l2 = std::stod(m[3]);
    if (std::regex_search(s.log, m, std::regex(R"(solve [0-9.]+ s, relative residual[^\n]*)"))) {
        const std::string line = m[0];
        std::smatch k;
        s.refinements = std::regex_search(line, k, std::regex(R"(after (\d+) refinement step)")) ? std::stoi(k[1]) : 0;
    }
    s.scaled = s.log.find("diagonal scaling D^-1/2 K D^-1/2: |K_ii|") != std::string::npos;
    return s;
}

}  // namespace

TEST(CommandsSolveur, DefaultsScaleAndRefineAtMostFourSteps) {
    const Solved s = solve("METHODE='MUMPS'");
    EXPECT_NE(s.log.find("SOLVEUR: PRETRAITEMENTS='AUTO' -> diagonal scaling D^-1/2 K D^-1/2; "
                         "POSTTRAITEMENTS='AUTO' -> iterative refinement, at most 4 step(s)"),
              std::string::npos)
        << s.log;
    EXPECT_TRUE(s.scaled);
    EXPECT_GE(s.refinements, 0);
    EXPECT_LE(s.refinements, 4);
    EXPECT_GE(s.l2, 0.0);
    EXPECT_LT(s.l2, 1e-12);
}

TEST(CommandsSolveur, PretraitementsSansTurnsTheScalingOff) {
    const Solved s = solve("METHODE='MUMPS', PRETRAITEMENTS='SANS'");
    EXPECT_NE(s.log.find("SOLVEUR: PRETRAITEMENTS='SANS' -> no scaling"), std::string::npos) << s.log;
    EXPECT_FALSE(s.scaled) << s.log;
    EXPECT_GE(s.l2, 0.0);
    EXPECT_LT(s.l2, 1e-12);
}

TEST(CommandsSolveur, PosttraitementsSansMiniForce) {
    const Solved none = solve("METHODE='MUMPS', POSTTRAITEMENTS='SANS'");
    EXPECT_NE(none.log.find("POSTTRAITEMENTS='SANS' -> no iterative refinement"), std::string::npos) << none.log;
    EXPECT_NE(none.log.find("(no refinement)"), std::string::npos) << none.log;
    EXPECT_EQ(none.refinements, 0);
    const Solved mini = solve("METHODE='MUMPS', POSTTRAITEMENTS='MINI'");
    EXPECT_NE(mini.log.find("POSTTRAITEMENTS='MINI' -> iterative refinement, at most 1 step(s)"), std::string::npos);
    EXPECT_GE(mini.refinements, 0);
    EXPECT_LE(mini.refinements, 1);
    const Solved force = solve("METHODE='MUMPS', POSTTRAITEMENTS='FORCE', PRETRAITEMENTS='SANS'");
    EXPECT_NE(force.log.find("POSTTRAITEMENTS='FORCE' -> iterative refinement, at most 10 step(s)"), std::string::npos);
    EXPECT_FALSE(force.scaled);
    for (const Solved* s : {&none, &mini, &force}) {
        EXPECT_GE(s->l2, 0.0);
        EXPECT_LT(s->l2, 1e-12);
    }
}

TEST(CommandsSolveur, UnknownPosttraitementsIsRefusedByTheCatalog) {
    const auto r = runComm(rigid("METHODE='MUMPS', POSTTRAITEMENTS='TOUJOURS'"), kMesh);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("POSTTRAITEMENTS"), std::string::npos) << r.output;
}
