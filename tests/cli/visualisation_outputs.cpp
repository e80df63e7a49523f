// Results users can look at (issue 18): IMPR_RESU FORMAT='GMSH' read back by Debian's gmsh,
// `miniaster convert` read back by VTK with the MED file's values, `miniaster plot` pictures, what
// meshio reads of our MED files; and the check of the whole command file before it runs.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "med_test_support.hpp"
#include "parser_run.hpp"

namespace fs = std::filesystem;

namespace {

using ma::test::astest;
using ma::test::readText;
using ma::test::runCommand;

int exitStatus(int raw) { return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1; }

// The original .comm with `extra` inserted before its final FIN().
std::string withBeforeFin(const std::string& original, const std::string& extra) {
    std::string text = readText(astest(original));
    const auto fin = text.rfind("\nFIN(");
    if (fin == std::string::npos) throw std::runtime_error("no FIN() in " + original);
    return text.substr(0, fin + 1) + extra + text.substr(fin + 1);
}

struct CaseRun {
    int status = -1;
    std::string dir, output;
};

CaseRun runCase(const std::string& dir, const std::string& name, const std::string& comm, const std::string& mesh) {
    std::ofstream(dir + "/" + name + ".comm") << comm;
    CaseRun r{0, dir, ""};
    int raw = 0;
    r.output = runCommand(std::string(MINIASTER_BINARY) + " run " + dir + "/" + name + ".comm --mesh " + astest(mesh) +
                              " --out-dir " + dir + " --verbose",
                          &raw);
    r.status = exitStatus(raw);
    return r;
}

std::string checkScript() {
    return "/usr/bin/python3 " + std::string(MINIASTER_SOURCE_DIR) + "/tests/visualisation_check.py";
}

// ssnv511e (2D, contact, POST_CHAM_XFEM) and ssnv511g (HEXA8) with their results printed, run once.
class Visualisation : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = ma::test::scratchDir("visualisation");
        const std::string outputs =
            "IMPR_RESU(FORMAT='GMSH', UNITE=37, RESU=(\n"
            "    _F(RESULTAT=RES_XFEM, NOM_CHAM='DEPL', TYPE_CHAM='VECT_2D', NOM_CMP=('DX', 'DY')),\n"
            "    _F(RESULTAT=RES_XFEM, NOM_CHAM='SIEF_ELGA'),\n"
            "    _F(RESULTAT=UTOT1, NOM_CHAM='DEPL', TYPE_CHAM='TENS_2D', NOM_CMP=('DX', 'DY', 'H1X', 'H1Y'))))\n"
            "IMPR_RESU(FORMAT='GMSH', VERSION=1.0, UNITE=38, RESU=_F(RESULTAT=UTOT1, NOM_CHAM='DEPL', "
            "GROUP_MA='SURF'))\n"
            "IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(RESULTAT=UTOT1))\n"
            "IMPR_RESU(FORMAT='MED', UNITE=81, RESU=_F(RESULTAT=RES_XFEM))\n"
            "IMPR_RESU(FORMAT='MED', UNITE=82, RESU=_F(RESULTAT=UTOT1, NOM_CHAM='DEPL'))\n"
            "IMPR_RESU(FORMAT='MED', UNITE=83, RESU=_F(RESULTAT=RES_XFEM, NOM_CHAM='DEPL'))\n";
        e_ = runCase(dir_, "e", withBeforeFin("ssnv511e.comm", outputs), "ssnv511a.mmed");
        fs::create_directories(dir_ + "/g");
        g_ = runCase(dir_ + "/g", "g",
                     withBeforeFin("ssnv511g.comm", "IMPR_RESU(FORMAT='MED', UNITE=81, RESU=_F(RESULTAT=RES_XFEM))\n"),
                     "ssnv511g.mmed");
    }
    static void TearDownTestSuite() { fs::remove_all(dir_); }

    static std::string dir_;
    static CaseRun e_, g_;
};
std::string Visualisation::dir_;
CaseRun Visualisation::e_, Visualisation::g_;

struct GmshRead {
    int status;
    std::string out, err;
};

// gmsh -0 on a .geo that merges `pos` and prints every view's name, steps, min and max.
GmshRead readWithGmsh(const std::string& dir, const std::string& pos) {
    std::ofstream(dir + "/check.geo")
        << "Merge \"" << pos << "\";\n"
        << "Printf(\"views=%g\", PostProcessing.NbViews);\n"
           "For i In {0:PostProcessing.NbViews-1}\n"
           "  Printf(StrCat(\"name=\", View[i].Name));\n"
           "  Printf(\"steps=%g min=%.9g max=%.9g\", View[i].NbTimeStep, View[i].Min, View[i].Max);\n"
           "EndFor\n";
    const int raw = std::system(("cd " + dir + " && gmsh -0 check.geo >gmsh.out 2>gmsh.err").c_str());
    return {exitStatus(raw), readText(dir + "/gmsh.out"), readText(dir + "/gmsh.err")};
}

std::vector<std::string> viewNames(const std::string& gmshOut) {
    std::vector<std::string> names;
    std::regex name("name=(\\S+)");
    for (std::sregex_iterator it(gmshOut.begin(), gmshOut.end(), name), end; it != end; ++it) names.push_back((*it)[1]);
    return names;
}

TEST_F(Visualisation, GmshViewsOfSsnv511eAreReadByGmsh) {
    ASSERT_EQ(e_.status, 2) << e_.output;  // ssnv511e: code_aster's inexact NON_REGRESSION values (README)
    auto r = readWithGmsh(dir_, "fort.37");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_NE(r.out.find("views=6\n"), std::string::npos) << r.out;
    EXPECT_EQ(viewNames(r.out),
              (std::vector<std::string>{"RES_XFEM_DEPL_VECTEUR", "RES_XFEM_SIEF_ELGA_SIXX", "RES_XFEM_SIEF_ELGA_SIYY",
                                        "RES_XFEM_SIEF_ELGA_SIZZ", "RES_XFEM_SIEF_ELGA_SIXY", "UTOT1_DEPL_TENSEUR"}));
    // Two steps (INST 0 and 1); SIXX = -p in the blocks: p = 1e6 below the horizontal interface, 2e6 above.
    EXPECT_NE(r.out.find("name=RES_XFEM_SIEF_ELGA_SIXX\nsteps=2 min=-2000000 max=0"), std::string::npos) << r.out;

    r = readWithGmsh(dir_, "fort.38");  // VERSION=1.0: DEPL as a vector and one scalar view per component
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(viewNames(r.out), (std::vector<std::string>{"UTOT1_DEPL_VECTEUR", "UTOT1_DEPL_DX", "UTOT1_DEPL_DY",
                                                          "UTOT1_DEPL_H1X", "UTOT1_DEPL_H1Y", "UTOT1_DEPL_H2X",
                                                          "UTOT1_DEPL_H2Y", "UTOT1_DEPL_H3X", "UTOT1_DEPL_H3Y"}))
        << r.out;
    const std::string pos = readText(dir_ + "/fort.38");
    EXPECT_EQ(pos.rfind("$PostFormat\n 1.0 0 8\n$EndPostFormat\n$View\nUTOT1_DEPL_VECTEUR     2\n", 0), 0u)
        << pos.substr(0, 200);
}

TEST_F(Visualisation, VtuOfThePostChamXfemResultHoldsTheMedValues) {
    ASSERT_EQ(e_.status, 2) << e_.output;
    int raw = 0;
    std::string out =
        runCommand(std::string(MINIASTER_BINARY) + " convert " + dir_ + "/fort.81 " + dir_ + "/xfem.vtu", &raw);
    ASSERT_EQ(exitStatus(raw), 0) << out;
    EXPECT_NE(out.find("mesh MA_XFEM (180 nodes, 100 cells"), std::string::npos) << out;
    out = runCommand(checkScript() + " vtu " + dir_ + "/xfem.vtu " + dir_ + "/fort.81 DX DY LAGS_C", &raw);
    EXPECT_EQ(exitStatus(raw), 0) << out;
    // DEPL at 2 steps on 180 nodes: the vector (DX, DY, DZ = 0), LAGS_C and LAGS_F1 apart
    // (docs/visualisation.md): 2 x 180 x 5 values.
    EXPECT_NE(out.find("vtu: OK 2 nodal fields, 1800 values equal"), std::string::npos) << out;
    EXPECT_NE(out.find("GROUP_MA:SURF"), std::string::npos) << out;
    EXPECT_NE(out.find("RES_XFEMSIEF_ELGA@1"), std::string::npos) << out;

    // The X-FEM result on the parent mesh (Heaviside components, profiled Gauss-point fields).
    out = runCommand(std::string(MINIASTER_BINARY) + " convert " + dir_ + "/fort.80 " + dir_ + "/utot1.vtu", &raw);
    ASSERT_EQ(exitStatus(raw), 0) << out;
    out = runCommand(checkScript() + " vtu " + dir_ + "/utot1.vtu " + dir_ + "/fort.80 DX DY H1X H3Y", &raw);
    EXPECT_EQ(exitStatus(raw), 0) << out;
}

TEST_F(Visualisation, ConvertRefusesWhatItCannotDo) {
    int raw = 0;
    auto out = runCommand(std::string(MINIASTER_BINARY) + " convert " + dir_ + "/fort.81 " + dir_ + "/x.txt", &raw);
    EXPECT_EQ(exitStatus(raw), 1);
    EXPECT_NE(out.find("miniaster convert: the output file must end in .vtu (one file) or .pvd (a time series): "),
              std::string::npos)
        << out;
    out = runCommand(std::string(MINIASTER_BINARY) + " convert " + dir_ + "/absent.rmed " + dir_ + "/x.vtu", &raw);
    EXPECT_EQ(exitStatus(raw), 1);
    EXPECT_NE(out.find("absent.rmed"), std::string::npos) << out;
    EXPECT_FALSE(fs::exists(dir_ + "/x.vtu"));
}

TEST_F(Visualisation, PlotDrawsThe2DAnd3DResults) {
    ASSERT_EQ(e_.status, 2) << e_.output;
    ASSERT_EQ(g_.status, 2) << g_.output;
    int raw = 0;
    for (const auto& [med, png, extra] :
         {std::tuple{dir_ + "/fort.81", dir_ + "/e.png", " --deformed 20 --field SIEF_ELGA --component SIXX"},
          std::tuple{dir_ + "/g/fort.81", dir_ + "/g.png", " --deformed 20"}}) {
        auto out = runCommand(std::string(MINIASTER_BINARY) + " plot " + med + " -o " + png + extra, &raw);
        ASSERT_EQ(exitStatus(raw), 0) << out;
        out = runCommand(checkScript() + " png " + png + " 800 650", &raw);
        EXPECT_EQ(exitStatus(raw), 0) << out;
    }
    auto out =
        runCommand(std::string(MINIASTER_BINARY) + " plot " + dir_ + "/fort.81 -o " + dir_ + "/x.png --field NOPE",
                   &raw);
    EXPECT_EQ(exitStatus(raw), 1);
    EXPECT_NE(out.find("miniaster plot: no field NOPE"), std::string::npos) << out;
    // A usage error exits with 1, as the other errors, and leaves no temporary VTU behind.
    const std::string tmp = dir_ + "/tmp";
    fs::create_directories(tmp);
    out = runCommand("TMPDIR=" + tmp + " " + std::string(MINIASTER_BINARY) + " plot " + dir_ + "/fort.81 -o " + dir_ +
                         "/x.png --deformed abc",
                     &raw);
    EXPECT_EQ(exitStatus(raw), 1) << out;
    EXPECT_NE(out.find("miniaster plot: error: argument --deformed: invalid float value: 'abc'"), std::string::npos)
        << out;
    EXPECT_TRUE(fs::is_empty(tmp)) << fs::directory_iterator(tmp)->path();
    EXPECT_FALSE(fs::exists(dir_ + "/x.png"));
}

// meshio reads the mesh and the nodal fields of both results as they are (values compared with
// h5py's); their Gauss-point fields it cannot read (docs/med.md, "meshio"), but it reads all of them
// in the VTU files of `miniaster convert`.
TEST_F(Visualisation, MeshioReadsBothResults) {
    ASSERT_EQ(e_.status, 2) << e_.output;
    int raw = 0;
    auto out = runCommand(checkScript() + " meshio " + dir_ + "/fort.82", &raw);
    EXPECT_EQ(exitStatus(raw), 0) << out;
    EXPECT_NE(out.find("meshio: OK 36 points, 45 cells, 576 nodal values equal to h5py's"), std::string::npos) << out;
    out = runCommand(checkScript() + " meshio " + dir_ + "/fort.83", &raw);
    EXPECT_EQ(exitStatus(raw), 0) << out;
    EXPECT_NE(out.find("meshio: OK 180 points, 100 cells, 1440 nodal values equal to h5py's"), std::string::npos)
        << out;
    for (const char* med : {"fort.80", "fort.81"}) {
        const std::string vtu = dir_ + "/meshio_" + med + ".vtu";
        out = runCommand(std::string(MINIASTER_BINARY) + " convert " + dir_ + "/" + med + " " + vtu, &raw);
        ASSERT_EQ(exitStatus(raw), 0) << out;
        out = runCommand(checkScript() + " meshio " + vtu, &raw);
        EXPECT_EQ(exitStatus(raw), 0) << out;
        EXPECT_NE(out.find("SIEF_ELGA@1"), std::string::npos) << out;
    }
}

// The whole command file is checked before its first command: an unknown command near the end of
// ssnv511e stops the run at once, with its line, and no command has run.
TEST(StaticCheck, UnknownCommandNearTheEndStopsTheRunBeforeAnyWork) {
    const auto dir = ma::test::scratchDir("static_check");
    std::string comm = withBeforeFin("ssnv511e.comm", "FOO_BAR(RESULTAT=RES_XFEM)\n");
    const int line = int(std::count(comm.begin(), comm.begin() + comm.find("FOO_BAR("), '\n')) + 1;
    auto r = runCase(dir, "t", comm, "ssnv511a.mmed");
    EXPECT_EQ(r.status, 1) << r.output;
    const std::string mess = readText(dir + "/t.mess");
    EXPECT_NE(mess.find("<F> <ERROR> FOO_BAR (t.comm, line " + std::to_string(line) +
                        "): unknown command FOO_BAR (not a code_aster command known to miniaster)"),
              std::string::npos)
        << mess;
    EXPECT_EQ(mess.find("# Command #"), std::string::npos) << "a command ran before the check";
    EXPECT_FALSE(fs::exists(dir + "/t.resu"));

    // Every problem at once, in line order; calls the tree cannot see (**kwargs, commands through
    // variables, the file's own functions in capitals) are left to the run.
    comm =
        "DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='MED', BOGUS=1)\n"
        "def MY_MACRO(**kw):\n    return DEFI_GROUP(**kw)\ncmd = DEFI_GROUP\n"
        "MA = DEFI_GROUP(reuse=MA, MAILLAGE=MA, CREA_GROUP_NO=(_F(GROUP_MA='LH'), _F(GROUP_MA='LD', NOPE=2)))\n"
        "for i in range(2):\n    PROPA_FISS(RESULTAT=MA)\nFIN()\n";
    r = runCase(dir, "t", comm, "ssnv511a.mmed");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(readText(dir + "/t.mess")
                  .find("<F> <ERROR> (t.comm): 3 problems found in the command file before its first command (none "
                        "was run):\n"
                        "    line 2: LIRE_MAILLAGE: unknown keyword BOGUS for LIRE_MAILLAGE (known keywords: FORMAT, "
                        "INFO, INFO_MED, NOM_MED, UNITE, VERI_MAIL)\n"
                        "    line 6: DEFI_GROUP: unknown keyword CREA_GROUP_NO[2]/NOPE for DEFI_GROUP (known keywords "
                        "in CREA_GROUP_NO[2]: "),
              std::string::npos)
        << readText(dir + "/t.mess");
    EXPECT_NE(
        readText(dir + "/t.mess").find("    line 8: PROPA_FISS: command PROPA_FISS is not supported by miniaster\n"),
        std::string::npos);

    comm =
        "DEBUT()\nargs = dict(FORMAT='MED')\nMA = LIRE_MAILLAGE(**args)\n"
        "def GROUPS(**kw):\n    return DEFI_GROUP(**kw)\nmake = DEFI_GROUP\n"
        "MA = make(reuse=MA, MAILLAGE=MA, CREA_GROUP_NO=_F(GROUP_MA='LH'))\n"
        "for g in ('LD', 'LB'):\n    MA = GROUPS(reuse=MA, MAILLAGE=MA, CREA_GROUP_NO=_F(GROUP_MA=g))\nFIN()\n";
    r = runCase(dir, "t", comm, "ssnv511a.mmed");
    EXPECT_EQ(r.status, 0) << readText(dir + "/t.mess");
    fs::remove_all(dir);
}

}  // namespace
