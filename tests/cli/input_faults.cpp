// Inputs that mislead (issue 28 item 8, what tests/cli/environment_faults.cpp and input_checks.cpp
// do not cover): a case name at the file system's limit, a level set FORMULE that returns a text,
// the same interface twice in one model.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "parser_run.hpp"

namespace fs = std::filesystem;
using namespace ma::test;

namespace {

const std::string kSource = MINIASTER_SOURCE_DIR;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// An X-FEM model of the xfem_quad4_n7 mesh with the interfaces `cracks` defined before it.
RunResult runXfem(const std::string& cracks, const std::string& fissure) {
    return runComm(
        "DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='MED', UNITE=20)\n"
        "MO_SAIN = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA='SURF', PHENOMENE='MECANIQUE', "
        "MODELISATION='D_PLAN'))\n" +
            cracks + "MO = MODI_MODELE_XFEM(MODELE_IN=MO_SAIN, FISSURE=" + fissure + ")\nFIN()\n",
        "--mesh '" + kSource + "/astest/xfem_quad4_n7.mmed'");
}

const std::string kHorizontal =
    "LSN = FORMULE(VALE='Y', NOM_PARA=['X', 'Y'])\n"
    "F1 = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='INTERFACE', DEFI_FISS=_F(FONC_LN=LSN))\n";

}  // namespace

// A case whose .mess name is 255 bytes (the file system's limit): its temporaries' names are
// shortened (a hash of the name), the run completes and leaves no temporary.
TEST(InputFaults, CaseNameAtTheFileSystemLimit) {
    const auto dir = freshDir();
    const std::string name(250, 'x');
    writeText(dir / (name + ".comm"), "DEBUT()\nL = DEFI_LIST_REEL(VALE=(1.0, 2.0))\nFIN()\n");
    const auto r = runMiniaster(dir, name + ".comm");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(r.exists("out/" + name + ".mess"));
    EXPECT_TRUE(r.exists("out/" + name + ".resu")) << r.output;
    for (const auto& f : r.files()) EXPECT_EQ(f.find(".miniaster-tmp."), std::string::npos) << f;
}

// A level set that returns a text ('0.5' would be read as a number by float()): an error naming
// the formula, the point and the text.
TEST(InputFaults, LevelSetFormulaReturningAText) {
    const auto r = runXfem(
        "LSN = FORMULE(VALE='str(Y)', NOM_PARA=['X', 'Y'])\n"
        "F1 = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='INTERFACE', DEFI_FISS=_F(FONC_LN=LSN))\n",
        "F1");
    EXPECT_EQ(r.status, 1) << r.output;
    const std::string mess = r.file("out/t.mess");
    EXPECT_TRUE(contains(mess, "<F> <ERROR> DEFI_FISS_XFEM (t.comm, line 5)")) << mess;
    EXPECT_TRUE(contains(mess, "formula LSN = 'str(Y)' (FORMULE defined in t.comm, line 4) failed for X=")) << mess;
    EXPECT_TRUE(contains(mess, "TypeError: the formula returns a text ('")) << mess;
}

// The same interface twice: one concept listed twice (refused before this issue), or two concepts
// with proportional level sets (the same zero set). Their enrichments would coincide (a singular
// system): refused. A different interface (shifted) is accepted.
TEST(InputFaults, SameInterfaceTwiceInOneModel) {
    auto r = runXfem(kHorizontal, "(F1, F1)");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_TRUE(contains(r.file("out/t.mess"),
                         "<F> <ERROR> MODI_MODELE_XFEM (t.comm, line 6): FISSURE: crack F1 is "
                         "listed twice"))
        << r.file("out/t.mess");
    r = runXfem(kHorizontal +
                    "LSN2 = FORMULE(VALE='-2.0 * Y', NOM_PARA=['X', 'Y'])\n"
                    "F2 = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='INTERFACE', "
                    "DEFI_FISS=_F(FONC_LN=LSN2))\n",
                "(F1, F2)");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_TRUE(contains(r.file("out/t.mess"),
                         "<F> <ERROR> MODI_MODELE_XFEM (t.comm, line 8): FISSURE: F1 and F2 are "
                         "the same interface (the same cut elements, normal level sets "
                         "proportional at their nodes)"))
        << r.file("out/t.mess");
    r = runXfem(kHorizontal +
                    "LSN2 = FORMULE(VALE='Y - 0.01', NOM_PARA=['X', 'Y'])\n"
                    "F2 = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='INTERFACE', "
                    "DEFI_FISS=_F(FONC_LN=LSN2))\n",
                "(F1, F2)");
    EXPECT_FALSE(contains(r.file("out/t.mess"), "the same interface")) << r.file("out/t.mess");
}
