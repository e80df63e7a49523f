// Faults and hostile input (issue 17): a full disk, a failing write, a killed or timed-out run, a
// damaged mesh, a result path that names somebody else's file, a bad .export, a material at its
// limits. Each test runs the miniaster binary the way a user would and checks what is left behind.
#include <gtest/gtest.h>
#include <sys/mount.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>

#include "parser_run.hpp"

namespace fs = std::filesystem;
using namespace ma::test;

namespace {

const std::string kSource = MINIASTER_SOURCE_DIR;
const std::string kShared = MINIASTER_SHARED_DIR;

std::string readAll(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Every file left in `folder` whose name marks a temporary of a run.
std::vector<std::string> temporaries(const fs::path& folder) {
    std::vector<std::string> out;
    std::error_code ec;
    for (const auto& e : fs::recursive_directory_iterator(folder, ec))
        if (e.path().filename().string().find(".miniaster-tmp.") != std::string::npos) out.push_back(e.path().string());
    return out;
}

// `text` with `from` replaced by `to` (once; the test fails when `from` is absent).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

// The xfem_quad4_n7 case (IMPR_RESU of the visualisation mesh) with its files in place.
std::string xfemExport() { return kSource + "/astest/xfem_quad4_n7.export"; }

// Runs fe_patch_quad4.comm changed by `edit` on its mesh.
RunResult runPatch(const std::string& from, const std::string& to) {
    auto dir = freshDir();
    writeText(dir / "t.comm", replaced(readAll(kSource + "/astest/fe_patch_quad4.comm"), from, to));
    return runMiniaster(dir, "t.comm", "--mesh '" + kSource + "/astest/fe_patch_quad4.mmed'");
}

}  // namespace

// Item 1: a full disk while IMPR_RESU writes its MED file: an error naming the cause, exit 1, no
// crash at exit, no partial result. A tmpfs of 200 kB nearly filled is a full disk.
TEST(Faults, DiskFullWhileWritingMed) {
    auto dir = freshDir();
    const fs::path full = dir / "full";
    fs::create_directories(full);
    if (::mount("tmpfs", full.c_str(), "tmpfs", 0, "size=200k") != 0)
        GTEST_SKIP() << "cannot mount a tmpfs here (needs root): the injected write failure test covers the path";
    {
        std::ofstream filler(full / "filler", std::ios::binary);
        filler << std::string(175000, '\0');
    }
    auto r = runMiniaster(dir, xfemExport(), "", "");
    // runMiniaster writes to dir/out: rerun into the full file system.
    const std::string cmd = "cd '" + dir.string() + "' && '" + std::string(MINIASTER_BINARY) + "' run '" +
                            xfemExport() + "' --out-dir full --verbose > log.txt 2>&1";
    const int raw = std::system(cmd.c_str());
    const std::string log = readAll(dir / "log.txt");
    const auto left = temporaries(full);
    const bool rmed = fs::exists(full / "xfem_quad4_n7.rmed");
    ::umount(full.c_str());
    ASSERT_TRUE(WIFEXITED(raw)) << "killed by a signal:\n" << log;
    EXPECT_EQ(WEXITSTATUS(raw), 1) << log;
    EXPECT_NE(log.find("No space left on device"), std::string::npos) << log;
    EXPECT_EQ(log.find("ABNORMAL_ABORT"), std::string::npos) << log;
    EXPECT_FALSE(rmed) << "no partial MED result";
    EXPECT_TRUE(left.empty()) << left.front();
    EXPECT_EQ(r.status, 0) << "the same case on a disk with room:\n" << r.output;
}

// Item 1, on any machine: a write failure injected with the file size limit of the shell (the
// .mess fits in 40 blocks, the MED result does not).
TEST(Faults, InjectedWriteFailure) {
    auto dir = freshDir();
    auto r = runMiniaster(dir, xfemExport(), "", "ulimit -f 40;");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("<F> <ERROR> IMPR_RESU (xfem_quad4.comm, line 52): MED file '"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("(system error: File too large)"), std::string::npos) << r.output;
    EXPECT_FALSE(r.exists("out/xfem_quad4_n7.rmed"));
    EXPECT_TRUE(temporaries(dir).empty());
    const std::string mess = r.file("out/xfem_quad4_n7.mess");
    EXPECT_NE(mess.find("--- DIAGNOSTIC JOB : <F>_ERROR"), std::string::npos) << mess;
    // The library's own lines are in the log, indented under a heading, never raw on stderr.
    EXPECT_NE(mess.find("output of the MED/HDF5 library (captured):\n      ../../../src/"), std::string::npos) << mess;
    EXPECT_EQ(r.output.find("\n../../../src/"), std::string::npos) << r.output;

    // A .mess that does not fit: the cause on stderr, and no .resu beside the incomplete log.
    dir = freshDir();
    writeText(dir / "t.comm", "DEBUT()\n" + std::string(3000, '#') + "\nFIN()\n");
    r = runMiniaster(dir, "t.comm", "", "ulimit -f 2;");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("miniaster: cannot write the message log " + (dir / "out/t.mess").string() +
                            ": File too large"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(r.exists("out/t.resu"));
}

// Item 2: a failing run never removes the file `F resu` names, and a result may not overwrite a
// data file of the run.
TEST(Faults, VictimFileIsLeftAlone) {
    auto dir = freshDir();
    writeText(dir / "victim.txt", "precious\n");
    writeText(dir / "t.comm", "DEBUT()\nx = 1/0\n");
    writeText(dir / "t.export", "F comm t.comm D 1\nF resu " + (dir / "victim.txt").string() + " R 8\n");
    auto r = runMiniaster(dir, "t.export");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_EQ(readAll(dir / "victim.txt"), "precious\n");
    EXPECT_NE(r.file("out/t.mess").find("is not from this run and is left as it was"), std::string::npos);

    fs::copy_file(kSource + "/astest/fe_patch_quad4.mmed", dir / "mesh.mmed");
    const std::string before = readAll(dir / "mesh.mmed");
    writeText(dir / "m.export", "F comm t.comm D 1\nF mmed mesh.mmed D 20\nF resu mesh.mmed R 8\n");
    r = runMiniaster(dir, "m.export", "--out-dir .");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("m.export, line 3: the result " + (dir / "mesh.mmed").string() +
                            " is the data file of line 2: the run would overwrite its own input"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(readAll(dir / "mesh.mmed"), before);
}

// Item 3: P time_limit stops an endless command file with the command it was in; the .mess and
// the TEST lines done so far are kept.
TEST(Faults, TimeLimitKeepsTheLogAndTheTestLines) {
    auto dir = freshDir();
    writeText(dir / "t.comm",
              replaced(readAll(kSource + "/astest/tables_chain.comm"), "\nFIN()", "\nwhile True: pass"));
    writeText(dir / "t.export",
              "P time_limit 2\nF comm t.comm D 1\nF mmed " + kSource + "/astest/tables_chain.mmed D 20\n");
    const auto t0 = std::chrono::steady_clock::now();
    auto r = runMiniaster(dir, "t.export");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_LT(seconds, 60.0);
    const std::string mess = r.file("out/t.mess");
    EXPECT_TRUE(std::regex_search(mess, std::regex("<F> <TIME_LIMIT> \\(t.comm, in the Python code after the command "
                                                   "of line [0-9]+\\): the time limit of 2 s")))
        << mess;
    EXPECT_NE(mess.find("--- DIAGNOSTIC JOB : <F>_TIME_LIMIT"), std::string::npos);
    const std::string resu = r.file("out/t.resu");
    EXPECT_NE(resu.find(" OK "), std::string::npos) << "the TEST lines done before the limit:\n" << resu;
    EXPECT_TRUE(temporaries(dir).empty());
}

// Item 3: SIGTERM ends the run the same way (and the .mess is there while the run goes on, issue
// 18 item 5); a temporary of a dead run is removed by the next run,
// one of a live process is not.
TEST(Faults, KilledRunAndStaleTemporaries) {
    auto dir = freshDir();
    writeText(dir / "t.comm", replaced(readAll(kSource + "/astest/tables_chain.comm"), "\nFIN()",
                                       "\nopen('started', 'w').close()\nwhile True: pass"));
    const std::string cmd =
        "cd '" + dir.string() + "' && ('" + std::string(MINIASTER_BINARY) + "' run t.comm --mesh '" + kSource +
        "/astest/tables_chain.mmed' --out-dir out --verbose > log.txt 2>&1 & p=$!; " +
        "for i in $(seq 600); do [ -e started ] && break; sleep 0.1; done; cp out/t.mess running.mess; " +
        "kill -TERM $p; wait $p; " + "echo $? > rc)";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    EXPECT_EQ(readAll(dir / "rc"), "1\n") << readAll(dir / "log.txt");
    // The .mess is a log, streamed: while the run goes on it already holds the commands done.
    EXPECT_NE(readAll(dir / "running.mess").find("TEST_TABLE"), std::string::npos) << readAll(dir / "running.mess");
    const std::string mess = readAll(dir / "out/t.mess");
    EXPECT_NE(mess.find("the run is stopped by signal 15 (Terminated)"), std::string::npos) << mess;
    EXPECT_NE(mess.find("--- DIAGNOSTIC JOB : <F>_INTERRUPTED"), std::string::npos);
    EXPECT_NE(readAll(dir / "out/t.resu").find(" OK "), std::string::npos);

    // A child that has exited: its pid is free.
    const pid_t child = fork();
    if (child == 0) _exit(0);
    waitpid(child, nullptr, 0);
    char host[256] = {};
    gethostname(host, sizeof(host) - 1);
    std::string h = host;
    h = h.substr(0, h.find('.'));
    const fs::path dead = dir / "out" / ("t.resu.miniaster-tmp." + h + "." + std::to_string(child));
    const fs::path alive = dir / "out" / ("t.resu.miniaster-tmp." + h + "." + std::to_string(getpid()));
    writeText(dead, "half");
    writeText(alive, "in progress");
    writeText(dir / "u.comm", "DEBUT()\nFIN()\n");
    auto r = runMiniaster(dir, "u.comm");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_FALSE(fs::exists(dead));
    EXPECT_TRUE(fs::exists(alive));
    EXPECT_NE(r.file("out/u.mess").find("(a temporary file of a run that no longer exists)"), std::string::npos);
}

// Item 4: one bit flipped in the object header of MAI/SE2/FAM: the mesh is damaged, not a mesh
// without groups.
TEST(Faults, BitFlipInTheFamilies) {
    auto dir = freshDir();
    std::string mesh = readAll(kSource + "/astest/fe_patch_quad4.mmed");
    ASSERT_GT(mesh.size(), 6909u);
    mesh[6909] = char(mesh[6909] ^ 0x01);
    writeText(dir / "m.mmed", mesh);
    fs::copy_file(kSource + "/astest/fe_patch_quad4.comm", dir / "t.comm");
    auto r = runMiniaster(dir, "t.comm", "--mesh m.mmed");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("<F> <ERROR> LIRE_MAILLAGE (t.comm, line 11): MED file '" + (dir / "m.mmed").string() +
                            "' is damaged"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("does not exist"), std::string::npos);
}

// Item 5: the output folder is checked before anything runs (< 1 s), and absolute: a .comm that
// changes the current folder still finds it.
TEST(Faults, OutputFolderCheckedFirst) {
    auto dir = freshDir();
    writeText(dir / "t.comm", "DEBUT()\nFIN()\n");
    writeText(dir / "afile", "");
    for (const std::string out : {"afile", "/proc/miniaster", "afile/sub"}) {
        const auto t0 = std::chrono::steady_clock::now();
        auto r = runMiniaster(dir, "t.comm", "--out-dir " + out);
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 1.0);
        EXPECT_EQ(r.status, 1) << r.output;
        EXPECT_NE(r.output.find("; nothing was run"), std::string::npos) << r.output;
        EXPECT_EQ(r.output.find("DIAGNOSTIC JOB"), std::string::npos) << r.output;
    }
    writeText(dir / "r.export", "F comm t.comm D 1\nF rmed /proc/miniaster/r.rmed R 80\n");
    auto e = runMiniaster(dir, "r.export");
    EXPECT_EQ(e.status, 1);
    EXPECT_NE(e.output.find("cannot create the folder of the result file /proc/miniaster/r.rmed,"), std::string::npos)
        << e.output;
    writeText(dir / "c.comm", "DEBUT()\nimport os\nos.chdir('/')\nFIN()\n");
    auto r = runMiniaster(dir, "c.comm");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(r.exists("out/c.mess"));
    EXPECT_TRUE(r.exists("out/c.resu"));
}

// Item 6: material at its limits and overflow: the real cause, not "a missing boundary condition".
TEST(Faults, MaterialAtItsLimits) {
    auto r = runPatch("E = 100.0E6", "E = 0.0");
    EXPECT_NE(r.output.find("<F> <ERROR> DEFI_MATERIAU (t.comm, line 19): ELAS[1]/E = 0: Young's modulus must be > 0"),
              std::string::npos)
        << r.output;
    r = runPatch("nu = 0.3", "nu = -1.0");
    EXPECT_NE(r.output.find("ELAS[1]/NU = -1: Poisson's ratio must lie in ]-1, 0.5]"), std::string::npos) << r.output;
    r = runPatch("nu = 0.3", "nu = 0.4999999999");
    EXPECT_NE(r.output.find("<A> <MATERIAL_1>"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("NU = 0.4999999999 is nearly incompressible in 3D and plane strain"), std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("Likely cause: a missing boundary condition"), std::string::npos) << r.output;
    r = runPatch("p1, p2 = 2.0E6, -0.5E6", "p1, p2 = 1e300, -0.5E6");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("the norm is not finite"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("reference zero"), std::string::npos) << r.output;
}

// Item 6: a penalty coefficient far beyond the stiffness is named as the cause (ssnv511h).
TEST(Faults, HugePenaltyIsNamed) {
    auto dir = freshDir();
    std::string comm = readAll(kShared + "/astest/ssnv511h.comm");
    for (auto at = comm.find("COEF_PENA_CONT = 1e13"); at != std::string::npos; at = comm.find("COEF_PENA_CONT = 1e13"))
        comm.replace(at, 21, "COEF_PENA_CONT = 1e40");
    writeText(dir / "t.comm", comm);
    auto r = runMiniaster(dir, "t.comm", "--mesh '" + kShared + "/astest/ssnv511h.mmed'");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("COEF_PENA_CONT up to 1.000e+40"), std::string::npos) << r.output;
}

// Item 7: sizes beyond the memory limit, a folder as the .comm, strict .export lines.
TEST(Faults, MemoryLimitAndStrictInputs) {
    auto dir = freshDir();
    writeText(dir / "t.comm",
              "DEBUT()\nL = DEFI_LIST_REEL(DEBUT=0., INTERVALLE=_F(JUSQU_A=1., NOMBRE=2**31))\nFIN()\n");
    writeText(dir / "t.export", "P memory_limit 256\nF comm t.comm D 1\n");
    const auto t0 = std::chrono::steady_clock::now();
    auto r = runMiniaster(dir, "t.export");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 10.0);
    EXPECT_NE(r.output.find("<F> <ERROR> DEFI_LIST_REEL (t.comm, line 2): INTERVALLE[1]/NOMBRE (2147483648 instants) "
                            "needs 16384 MB of memory, more than the memory_limit of 256 MB (P memory_limit in the "
                            ".export)"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("std::"), std::string::npos);

    writeText(dir / "m.comm", "DEBUT()\nx = b'x' * (600 * 2**20)\nFIN()\n");
    writeText(dir / "m.export", "P memory_limit 256\nF comm m.comm D 1\n");
    r = runMiniaster(dir, "m.export");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("<F> <MEMORY_LIMIT>"), std::string::npos) << r.output;

    fs::create_directories(dir / "d.comm");
    r = runMiniaster(dir, "d.comm");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("<F> <ERROR> the command file d.comm is a folder"), std::string::npos) << r.output;

    const std::vector<std::pair<std::string, std::string>> cases = {
        {"F mmed m.mmed D 80abc", "line 2: the unit '80abc' is not a logical unit (an integer 0..99)"},
        {"F rmed r.rmed R -80", "line 2: the unit '-80' is not a logical unit"},
        {"F rmed r.rmed RX 80", "line 2: unknown flag 'X' in 'RX'"},
        {"F rmed a.rmed R 80\nF rmed b.rmed R 80", "line 3: unit 80 is already given on line 2"},
        {"F base glob.1 D 0",
         "line 2: 'base' is a code_aster database: miniaster neither reads nor writes one (there "
         "is no POURSUITE)"},
        {"P time_limit 10s", "line 2: 'time_limit' must be a positive number (seconds), got '10s'"},
        {"Q what", "line 2: unknown line type 'Q'"},
    };
    writeText(dir / "t.comm", "DEBUT()\nFIN()\n");
    for (size_t k = 0; k < cases.size(); ++k) {
        writeText(dir / "e.export", "F comm t.comm D 1\n" + cases[k].first + "\n");
        r = runMiniaster(dir, "e.export");
        EXPECT_EQ(r.status, 1) << cases[k].first;
        EXPECT_NE(r.output.find("<F> <ERROR> e.export, " + cases[k].second), std::string::npos)
            << cases[k].first << "\n"
            << r.output;
    }
}

// .export flag C and R directories (issue 18, item 8): a gzip-compressed command file and mesh
// are read, a compressed result is written compressed, the units without F line go into the R
// directory.
TEST(Faults, CompressedFilesAndResultDirectories) {
    auto dir = freshDir();
    fs::copy_file(kSource + "/astest/tables_chain.comm", dir / "t.comm");
    fs::copy_file(kSource + "/astest/tables_chain.mmed", dir / "t.mmed");
    std::string comm = readAll(dir / "t.comm");
    comm = replaced(comm, "\nFIN()",
                    "\nIMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(MAILLAGE=MA))\n"
                    "IMPR_RESU(FORMAT='MED', UNITE=81, RESU=_F(MAILLAGE=MA))\nFIN()");
    writeText(dir / "t.comm", comm);
    ASSERT_EQ(std::system(("cd '" + dir.string() + "' && gzip t.comm t.mmed").c_str()), 0);
    writeText(dir / "t.export",
              "F comm t.comm.gz DC 1\nF mmed t.mmed.gz DC 20\nF rmed r.rmed.gz RC 80\n"
              "R repe results R 0\n");
    auto r = runMiniaster(dir, "t.export");
    EXPECT_EQ(r.status, 0) << r.output;
    ASSERT_TRUE(r.exists("out/r.rmed.gz")) << r.output;
    EXPECT_EQ(std::system(("cd '" + dir.string() + "/out' && gzip -t r.rmed.gz").c_str()), 0);
    EXPECT_TRUE(r.exists("out/results/fort.81")) << r.output;
    EXPECT_TRUE(temporaries(dir).empty());
    for (const auto& f : r.files())
        EXPECT_TRUE(f == "t.mess" || f == "t.resu" || f == "r.rmed.gz" || f == "results") << f;

    writeText(dir / "bad.export", "F comm t.export DC 1\n");
    r = runMiniaster(dir, "bad.export");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("(flag C) is not gzip-compressed"), std::string::npos) << r.output;
}

// A failure late in a run keeps the .resu with the TEST lines done so far (code_aster's
// behaviour, issue 18 item 4), and os._exit in the command file leaves the log so far.
TEST(Faults, LateFailureKeepsTheTestLines) {
    auto dir = freshDir();
    writeText(dir / "t.comm", replaced(readAll(kSource + "/astest/tables_chain.comm"), "\nFIN()", "\nx = 1/0\nFIN()"));
    auto r = runMiniaster(dir, "t.comm", "--mesh '" + kSource + "/astest/tables_chain.mmed'");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.file("out/t.resu").find(" OK "), std::string::npos) << r.file("out/t.resu");
    EXPECT_NE(r.file("out/t.mess").find("ZeroDivisionError"), std::string::npos);

    writeText(dir / "t.comm",
              replaced(readAll(kSource + "/astest/tables_chain.comm"), "\nFIN()", "\nimport os\nos._exit(3)"));
    r = runMiniaster(dir, "t.comm", "--mesh '" + kSource + "/astest/tables_chain.mmed'");
    EXPECT_EQ(r.status, 3);
    const std::string mess = r.file("out/t.mess");
    EXPECT_NE(mess.find("TEST_TABLE"), std::string::npos) << "the log of the commands run before os._exit";
    EXPECT_EQ(mess.find("DIAGNOSTIC JOB : OK"), std::string::npos) << "not the .mess of the earlier run";
}
