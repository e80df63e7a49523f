// The supervisor end to end: .export runs, outputs, naming of concepts, reuse, FIN, alarms.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "parser_run.hpp"
#include "xfem/SubcellQuadrature.hpp"

using namespace ma::test;

TEST(ParserSupervisor, ExportRunWritesMessAndResu) {
    auto dir = freshDir();
    std::filesystem::create_directories(dir / "data");
    writeText(dir / "data" / "case.comm", R"(
DEBUT(CODE=_F(NIV_PUB_WEB='INTERNET'))
L_INST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1, NOMBRE=4))
VAR1 = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 2.0), PROL_DROITE='CONSTANT')
F = FORMULE(VALE='2*INST', NOM_PARA='INST')
print('VAR1', VAR1(0.25), VAR1(3.0), 'F', F(0.25))
FIN()
print('after FIN')
)");
    writeText(dir / "data" / "case.export",
              "P time_limit 30\nP testlist submit verification\nF comm case.comm D 1\nF mess case.mess R 6\n");
    auto r = runMiniaster(dir, "data/case.export");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("L_INST = DEFI_LIST_REEL("), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("VAR1 0.5 2.0 F 0.5"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("after FIN"), std::string::npos) << "nothing runs after FIN";
    EXPECT_NE(r.output.find("TIMING SUMMARY"), std::string::npos);
    EXPECT_NE(r.output.find("<I> <FIN> ARRET NORMAL"), std::string::npos);
    EXPECT_NE(r.output.find("--- DIAGNOSTIC JOB : OK\n"), std::string::npos);
    // R paths of the .export are relative to --out-dir when given; the .resu takes the default name.
    EXPECT_TRUE(r.exists("out/case.mess"));
    EXPECT_TRUE(r.exists("out/case.resu"));
    EXPECT_NE(r.file("out/case.mess").find("--- DIAGNOSTIC JOB : OK"), std::string::npos);
}

TEST(ParserSupervisor, ConceptNaming) {
    auto r = runComm(R"(
DEBUT()
A = FORMULE(VALE='X', NOM_PARA='X')
T = [None] * 5
T[1] = FORMULE(VALE='X', NOM_PARA='X')
for i in [2, 3]:
    T[i] = FORMULE(VALE='X', NOM_PARA='X')
def make():
    B = FORMULE(VALE='X', NOM_PARA='X')
    return B
C = make()
D = {}
D['k'] = FORMULE(VALE='X', NOM_PARA='X')
print(A.getName(), T[1].getName(), T[2].getName(), T[3].getName(), C.getName(), D['k'].getName(), A.getType())
FIN()
)");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("\nA T_1 T_2 T_3 B D_k formule\n"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("T_2 = FORMULE("), std::string::npos);
}

TEST(ParserSupervisor, ReuseIsHonouredForReentrantCommands) {
    // Validation only: CALC_TABLE is reentrant; the result must be assigned to the reused object.
    auto ok = runComm(
        "DEBUT()\nL = DEFI_LIST_REEL(VALE=(0., 1.))\n"
        "R = STAT_NON_LINE(MODELE=None, CHAM_MATER=None, INCREMENT=_F(LIST_INST=L))\n",
        "--check-syntax");
    EXPECT_EQ(ok.status, 1);  // MODELE=None is an absent mandatory keyword
    EXPECT_NE(ok.output.find("mandatory keyword MODELE is missing"), std::string::npos) << ok.output;

    auto mismatch = runComm(R"(
DEBUT()
F = FORMULE(VALE='X', NOM_PARA='X')
L = DEFI_LIST_REEL(VALE=(0., 1.))
M = LIRE_MAILLAGE()
M2 = DEFI_GROUP(reuse=M, MAILLAGE=M, CREA_GROUP_NO=_F(GROUP_MA='A'))
)",
                            "--check-syntax");
    expectError(mismatch,
                "<F> <ERROR> DEFI_GROUP (t.comm, line 6): reuse=M but the result is assigned to M2: a "
                "reentrant command modifies the object given by reuse=, assign the result to it");

    auto noReuse =
        runComm("DEBUT()\nM = LIRE_MAILLAGE()\nM2 = DEFI_GROUP(MAILLAGE=M, CREA_GROUP_NO=_F(GROUP_MA='A'))\n",
                "--check-syntax");
    expectError(noReuse,
                "<F> <ERROR> DEFI_GROUP (t.comm, line 3): DEFI_GROUP modifies its input in place: reuse= is "
                "mandatory (write X = DEFI_GROUP(reuse=X, ...) with the object it modifies)");

    auto good = runComm(
        "DEBUT()\nM = LIRE_MAILLAGE()\nM = DEFI_GROUP(reuse=M, MAILLAGE=M, "
        "CREA_GROUP_NO=_F(GROUP_MA='A'))\nFIN()\n",
        "--check-syntax");
    EXPECT_EQ(good.status, 0) << good.output;
    EXPECT_NE(good.output.find("M = DEFI_GROUP("), std::string::npos);
}

TEST(ParserSupervisor, MissingFinAndDebutAreAlarms) {
    auto r = runComm("L = DEFI_LIST_REEL(VALE=(0., 1.))\n");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("<A> <SUPERVIS_1>"), std::string::npos);
    EXPECT_NE(r.output.find("<A> <SUPERVIS_2>"), std::string::npos);
    EXPECT_NE(r.output.find("--- DIAGNOSTIC JOB : <A>_ALARM\n"), std::string::npos);
    EXPECT_TRUE(r.exists("out/t.resu"));
}

TEST(ParserSupervisor, MallocPagesAreGlibcsUnlessTheUserSetsThem) {
    // glibc's default pages (src/core/MallocHugePages.hpp says why); the binary does not re-execute
    // itself with a tunable of its own, and a user's GLIBC_TUNABLES reaches the run as given.
    const auto r = runComm("import os\nprint('TUNABLES=' + os.environ.get('GLIBC_TUNABLES', ''))\nDEBUT()\nFIN()\n", "",
                           "GLIBC_TUNABLES=");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("  memory      : 4 KB pages (glibc's default)\n"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("TUNABLES=\n"), std::string::npos) << r.output;
    const auto on = runComm("import os\nprint('TUNABLES=' + os.environ['GLIBC_TUNABLES'])\nDEBUT()\nFIN()\n", "",
                            "GLIBC_TUNABLES=glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1");
    EXPECT_NE(on.output.find("  memory      : glibc.malloc.hugetlb=1 from GLIBC_TUNABLES"), std::string::npos)
        << on.output;
    EXPECT_NE(on.output.find("TUNABLES=glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1\n"), std::string::npos)
        << on.output;
}

TEST(ParserSupervisor, CommWithMissingMesh) {
    auto r = runComm("DEBUT()\nFIN()\n", "--mesh nowhere.med");
    expectError(r, "<F> <ERROR> the mesh file nowhere.med (--mesh) does not exist");
}

TEST(ParserSupervisor, MeshOptionSetsUnit20) {
    auto dir = freshDir();
    writeText(dir / "t.comm", "DEBUT()\nFIN()\n");
    writeText(dir / "m.med", "");
    auto r = runMiniaster(dir, "t.comm", "--mesh m.med");
    EXPECT_EQ(r.status, 0) << r.output;
}

TEST(ParserSupervisor, BadCommandLine) {
    auto dir = freshDir();
    auto r = runMiniaster(dir, "t.comm", "--frobnicate");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("miniaster: unknown option --frobnicate"), std::string::npos) << r.output;
}

TEST(ParserSupervisor, CodeAsterCommandsModule) {
    auto r = runComm("from code_aster.Commands import *\nDEBUT()\nL = DEFI_LIST_REEL(VALE=(0., 1.))\nFIN()\n");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("--- DIAGNOSTIC JOB : OK"), std::string::npos);
}

// A failed run without result lines leaves the .resu of an earlier run as it was (the run cannot
// tell it from somebody else's file) and says so in its .mess.
TEST(ParserSupervisor, ErrorLeavesTheResultOfAnEarlierRunAsItWas) {
    auto dir = freshDir();
    writeText(dir / "t.comm", "DEBUT()\nFIN()\n");
    auto first = runMiniaster(dir, "t.comm");
    ASSERT_EQ(first.status, 0) << first.output;
    ASSERT_TRUE(first.exists("out/t.resu"));
    const std::string earlier = first.file("out/t.resu");
    writeText(dir / "t.comm", "DEBUT()\nx = 1/0\n");
    auto second = runMiniaster(dir, "t.comm");
    EXPECT_EQ(second.status, 1);
    const std::string paragraph =
        "<F> <ERROR> (t.comm, line 2): error in the Python code of the command file: "
        "ZeroDivisionError: division by zero";
    EXPECT_NE(second.file("out/t.mess").find(paragraph), std::string::npos) << second.output;
    EXPECT_EQ(second.file("out/t.resu"), earlier);
    EXPECT_NE(second.file("out/t.mess").find("is not from this run and is left as it was"), std::string::npos);
}

TEST(ParserSupervisor, Latin1CommandFileIsRead) {
    auto r = runComm(
        "DEBUT()\n# d\xe9placement impos\xe9\nL = DEFI_LIST_REEL(VALE=(0., 1.), TITRE='d\xe9"
        "but')\nFIN()\n");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("<A> <SUPERVIS_3>"), std::string::npos) << r.output;
}

TEST(ParserSupervisor, CrashLeavesADiagnosisAndNoResult) {
    auto r = runComm("DEBUT()\nimport ctypes\nctypes.string_at(0)\nFIN()\n");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("--- DIAGNOSTIC JOB : <F>_ABNORMAL_ABORT"), std::string::npos) << r.output;
    EXPECT_NE(r.file("out/t.mess")
                  .find("<F> <ABNORMAL_ABORT> (t.comm, in the Python code after the command of line "
                        "1): the process received signal 11"),
              std::string::npos)
        << r.file("out/t.mess");
    EXPECT_FALSE(r.exists("out/t.resu"));
}

TEST(ParserSupervisor, ExportUnitsReachTheCommands) {
    // D 20 is what LIRE_MAILLAGE reads, R 80 is where IMPR_RESU writes (relative to --out-dir).
    auto dir = freshDir();
    const std::string mesh = std::string(MINIASTER_SHARED_DIR) + "/astest/ssnv511a.mmed";
    writeText(dir / "u.comm",
              "DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='MED')\nIMPR_RESU(FORMAT='MED', UNITE=80, "
              "RESU=_F(MAILLAGE=MA))\nFIN()\n");
    writeText(dir / "u.export", "F comm u.comm D 1\nF mmed " + mesh + " D 20\nF rmed u.rmed R 80\n");
    auto r = runMiniaster(dir, "u.export");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(r.exists("out/u.rmed")) << r.output;
    EXPECT_TRUE(r.exists("out/u.mess"));
    EXPECT_TRUE(r.exists("out/u.resu"));
}

// --subcell-quadrature RULE (expert run option, not a .comm keyword): catalogue or 1..6, anything
// else is a usage error (exit 1) before the command file starts.
TEST(ParserSupervisor, SubcellQuadratureOption) {
    const std::string comm = "DEBUT()\nFIN()\n";
    auto r = runComm(comm, "--subcell-quadrature catalogue");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output.find("--subcell-quadrature"), std::string::npos) << "the default is not announced";
    for (int d : {1, 3, ma::xfem::kMaxSubcellDegree}) {
        r = runComm(comm, "--subcell-quadrature " + std::to_string(d));
        EXPECT_EQ(r.status, 0) << r.output;
        const std::string line = "  X-FEM       : --subcell-quadrature " + std::to_string(d) +
                                 " (volume sub-cells integrated to degree " + std::to_string(d) +
                                 ", not code_aster's catalogue rules)\n";
        EXPECT_NE(r.file("out/t.mess").find(line), std::string::npos) << r.output;
    }
    const std::vector<std::string> bads{"0",         std::to_string(ma::xfem::kMaxSubcellDegree + 1),
                                        "seven",     "2.5",
                                        "02",        "-1",
                                        "CATALOGUE", "''"};
    for (const std::string& bad : bads) {
        r = runComm(comm, "--subcell-quadrature " + bad);
        EXPECT_EQ(r.status, 1) << bad << "\n" << r.output;
        const std::string shown = bad == "''" ? "" : bad;
        EXPECT_NE(r.output.find("miniaster: --subcell-quadrature: '" + shown +
                                "' is not a rule (catalogue, or a polynomial degree 1..6)\nusage: miniaster run"),
                  std::string::npos)
            << r.output;
        EXPECT_FALSE(r.exists("out/t.mess")) << "nothing runs";
    }
    auto dir = freshDir();
    writeText(dir / "t.comm", comm);
    r = runMiniaster(dir, "t.comm", "--subcell-quadrature");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("miniaster: --subcell-quadrature needs a value"), std::string::npos) << r.output;
}

// DEBUT(IGNORE_ALARM=...): ssnv511a's three TEST0_12 alarms (VALE_CALC 0 skipped) are neither
// printed nor counted: the diagnostic is OK, their number is given at the end.
TEST(ParserSupervisor, IgnoredAlarmsAreCountedNotPrinted) {
    std::ifstream in(std::string(MINIASTER_SHARED_DIR) + "/astest/ssnv511a.comm");
    std::string comm((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string debut = "DEBUT(CODE=_F(NIV_PUB_WEB='INTERNET',),";
    ASSERT_NE(comm.find(debut), std::string::npos);
    comm.replace(comm.find(debut), debut.size(),
                 "DEBUT(CODE=_F(NIV_PUB_WEB='INTERNET',), IGNORE_ALARM=('TEST0_12', 'XFEM_22'),");
    auto r = runComm(comm, std::string("--mesh '") + MINIASTER_SHARED_DIR + "/astest/ssnv511a.mmed'");
    EXPECT_EQ(r.status, 0) << r.output;
    const std::string mess = r.file("out/t.mess");
    EXPECT_EQ(mess.find("<A> <TEST0_12>"), std::string::npos) << mess;
    EXPECT_NE(mess.find("<I> alarm TEST0_12 raised 3 time(s), not printed (DEBUT/IGNORE_ALARM)"), std::string::npos);
    EXPECT_NE(mess.find("<I> alarm XFEM_22 raised 0 time(s)"), std::string::npos);
    EXPECT_NE(mess.find("--- DIAGNOSTIC JOB : OK\n"), std::string::npos) << mess;
}

// DETRUIRE: the name leaves the command file (a later use is a NameError, the name can be given
// again); a concept another one uses lives on (a model on a destroyed mesh keeps working).
TEST(ParserSupervisor, DestroyedConceptsLeaveTheNamespace) {
    auto r = runComm(R"(
DEBUT()
MA = LIRE_MAILLAGE(FORMAT='MED')
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
C = DEFI_CONSTANTE(VALE=1.0)
DETRUIRE(CONCEPT=(_F(NOM=C), _F(NOM=(MA,))))
for name in ('C', 'MA'):
    try:
        eval(name)
        print('still there:', name)
    except NameError:
        print('gone:', name)
C = DEFI_CONSTANTE(VALE=2.0)
print('C again', C(0.0))
CH = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='LG', DX=0.0))
FIN()
)",
                     std::string("--mesh '") + MINIASTER_SHARED_DIR + "/astest/ssnv511a.mmed'");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("gone: C\n"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("gone: MA\n"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("C again 2.0"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("    MA, C removed from the command file's names"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("CH = AFFE_CHAR_MECA("), std::string::npos);  // MO's mesh lives on
}
