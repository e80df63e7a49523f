// Faults of one process among several (issue 29 items 4 and 5, issue 28 item 9; docs/mpi.md,
// "Errors on several processes"): an exception on rank 1 only, between commands or inside one; a
// process that ends with os._exit; SIGTERM to mpirun while rank 0 writes; a process count the
// machine cannot hold. Every run has P time_limit 120 as a guard (a regression ends as TIME_LIMIT
// and fails the test instead of hanging the suite) and `timeout 300` around it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "parser_run.hpp"

namespace fs = std::filesystem;
using namespace ma::test;

namespace {

const std::string kSource = MINIASTER_SOURCE_DIR;
const std::string kTimeout = "timeout 300 ";
// A statement run on one rank only.
std::string onRank(int rank, const std::string& statement) {
    return "import os\nif os.environ.get('OMPI_COMM_WORLD_RANK') == '" + std::to_string(rank) + "':\n    " + statement;
}

std::string readAll(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// fe_patch_quad4.comm with `inserted` before its line `before` (whole line, first occurrence).
std::string patchWith(const std::string& before, const std::string& inserted) {
    std::string comm = readAll(kSource + "/astest/fe_patch_quad4.comm");
    const auto at = comm.find("\n" + before);
    EXPECT_NE(at, std::string::npos) << before;
    return comm.insert(at + 1, inserted + "\n");
}

// Writes t.comm and its .export (with the time-limit guard) in a fresh folder and runs it.
RunResult runOnTwo(const std::string& comm) {
    const auto dir = freshDir();
    writeText(dir / "t.comm", comm);
    writeText(dir / "t.export",
              "P time_limit 120\nF comm t.comm D 1\nF mmed " + kSource + "/astest/fe_patch_quad4.mmed D 20\n");
    return runMiniaster(dir, "t.export", "--np 2", kTimeout);
}

// The last `n` lines of `text`.
std::vector<std::string> lastLines(const std::string& text, size_t n) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    if (lines.size() > n) lines.erase(lines.begin(), lines.end() - long(n));
    return lines;
}

const std::string kRule(60, '-');

void expectEndsWith(const std::string& mess, const std::string& diagnostic) {
    EXPECT_EQ(lastLines(mess, 3), (std::vector<std::string>{kRule, "--- DIAGNOSTIC JOB : " + diagnostic, kRule}))
        << mess;
}

// A Python exception on rank 1 only, before a command: rank 0 learns it at that command's
// agreement; the run ends at once with rank 1's paragraph, exit 1.
TEST(MpiFaults, ExceptionOnOneProcessBetweenCommands) {
    const auto r = runOnTwo(patchWith("CH1 = AFFE_CHAR_MECA_F", onRank(1, "raise ValueError('boom')")));
    EXPECT_EQ(r.status, 1) << r.output;
    const std::string mess = r.file("out/t.mess");
    EXPECT_NE(mess.find("\n<F> <ERROR> (t.comm, line 37): error in the Python code of the command file: ValueError: "
                        "boom\n  (on MPI process 1 of 2)\n"),
              std::string::npos)
        << mess;
    EXPECT_EQ(mess.find("AFFE_CHAR_MECA_F("), std::string::npos) << "no command after the failure";
    expectEndsWith(mess, "<F>_ERROR");
    EXPECT_FALSE(r.exists("out/t.resu"));
}

// A formula that fails on rank 1 only, inside MECA_STATIQUE: rank 0 is then in the command's
// collectives (assembly), which stop on rank 1's announcement; the same end.
TEST(MpiFaults, ExceptionOnOneProcessInsideACommand) {
    const auto r =
        runOnTwo(patchWith("UX = lin(",
                           "import os\ndef fails(x):\n    if os.environ.get('OMPI_COMM_WORLD_RANK') == '1':\n"
                           "        raise ValueError('boom in a formula')\n    return 0.0\n"
                           "lin = lambda a, b, c: FORMULE(VALE='%r*X + %r*Y + %r + fails(X)' % (a, b, c), "
                           "NOM_PARA=['X', 'Y'], fails=fails)"));
    EXPECT_EQ(r.status, 1) << r.output;
    const std::string mess = r.file("out/t.mess");
    EXPECT_TRUE(std::regex_search(mess, std::regex("\n<F> <ERROR> MECA_STATIQUE \\(t.comm, line 4[0-9]\\): formula "
                                                   ".*ValueError: boom in a formula\n  \\(on MPI process 1 of 2\\)\n")))
        << mess;
    expectEndsWith(mess, "<F>_ERROR");
}

// os._exit(5) on rank 1: rank 0 names the process that ended (mpirun then ends the job), the
// launcher says mpirun's status; exit 1. On rank 0: rank 1 ends rank 0's .mess so.
TEST(MpiFaults, ProcessEndingWithoutAMessageIsNamed) {
    for (int rank : {1, 0}) {
        SCOPED_TRACE("os._exit on rank " + std::to_string(rank));
        const auto r = runOnTwo(patchWith("CH1 = AFFE_CHAR_MECA_F", onRank(rank, "os._exit(5)")));
        EXPECT_EQ(r.status, 1) << r.output;
        const std::string mess = r.file("out/t.mess");
        EXPECT_TRUE(std::regex_search(mess, std::regex("\n<F> <ERROR> .*: MPI process " + std::to_string(rank) +
                                                       " of 2 \\(pid [0-9]+(, exit status 5)?\\) ended before the "
                                                       "end of the run, without a message")))
            << mess;
        expectEndsWith(mess, "<F>_ERROR");
        EXPECT_NE(r.output.find("miniaster: mpirun ended with status 5"), std::string::npos) << r.output;
    }
}

// SIGTERM to mpirun itself (a scheduler's stop; mpirun started by hand) while rank 0 prints
// without end: mpirun stops reading the processes' output, so rank 0's echo blocks with the log
// held; the watchdog still writes the INTERRUPTED paragraph and the diagnostic in the .mess.
TEST(MpiFaults, SigtermToMpirunWhileRankZeroPrints) {
    const auto dir = freshDir();
    writeText(dir / "t.comm", patchWith("CH1 = AFFE_CHAR_MECA_F", "while True: print('x' * 200)"));
    writeText(dir / "t.export", "F comm t.comm D 1\nF mmed " + kSource + "/astest/fe_patch_quad4.mmed D 20\n");
    const int status =
        runThenTerminate(dir,
                         "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun --quiet -np 2 "
                         "--oversubscribe '" +
                             std::string(MINIASTER_BINARY) + "' run t.export --out-dir out",
                         2);
    EXPECT_NE(status, 0);
    const std::string mess = readAll(dir / "out/t.mess");
    const auto tail = lastLines(mess, 5);
    ASSERT_EQ(tail.size(), 5u) << mess;
    EXPECT_TRUE(std::regex_match(tail[0], std::regex("<F> <INTERRUPTED> \\(t.comm, in the Python code after the "
                                                     "command of line [0-9]+\\): the run is stopped by signal 15 .*")))
        << tail[0];
    EXPECT_EQ(tail[1], "");
    expectEndsWith(mess, "<F>_INTERRUPTED");
}

// SIGTERM to the launcher of `--np 2` 2 s after its start: forwarded to the processes, rank 0
// writes the INTERRUPTED paragraph; exit 1, and mpirun (never signalled) does not crash.
TEST(MpiFaults, SigtermToTheLauncher) {
    const auto dir = freshDir();
    writeText(dir / "t.comm", patchWith("CH1 = AFFE_CHAR_MECA_F", "while True: pass"));
    writeText(dir / "t.export", "F comm t.comm D 1\nF mmed " + kSource + "/astest/fe_patch_quad4.mmed D 20\n");
    EXPECT_EQ(runThenTerminate(dir, quotedBinary() + " run t.export --np 2 --out-dir out", 2), 1)
        << readAll(dir / "run.log");
    const std::string mess = readAll(dir / "out/t.mess");
    EXPECT_TRUE(std::regex_search(mess, std::regex("\n<F> <INTERRUPTED> .*: the run is stopped by signal 15"))) << mess;
    expectEndsWith(mess, "<F>_INTERRUPTED");
    EXPECT_EQ(readAll(dir / "run.log").find("Segmentation fault"), std::string::npos) << readAll(dir / "run.log");
}

// More processes than the machine can hold: refused before mpirun starts, nothing written.
TEST(MpiFaults, TooManyProcessesRefused) {
    const auto dir = freshDir();
    const auto r = runMiniaster(dir, kSource + "/astest/fe_patch_quad4.comm", "--np 1000", kTimeout);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_TRUE(std::regex_search(r.output, std::regex("miniaster: 1000 MPI processes asked for \\(--np or P "
                                                       "mpi_nbcpu\\): this machine has [0-9]+ core\\(s\\), and "
                                                       "miniaster starts at most 4 processes per core")))
        << r.output;
    EXPECT_NE(r.output.find("nothing was run"), std::string::npos);
    EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace
