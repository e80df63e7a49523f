// Outputs that are inputs, links or special files, and two runs of one case in one folder (issue 28
// items 5 and 6). Each refusal comes before the first command, on stderr with exit 1, and leaves
// every file it names as it was.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <thread>

#include "parser_run.hpp"

namespace fs = std::filesystem;
using namespace ma::test;

namespace {

const std::string kSource = MINIASTER_SOURCE_DIR;
const std::string kMesh = kSource + "/astest/fe_patch_quad4.mmed";
const std::string kComm = "DEBUT()\nL = DEFI_LIST_REEL(VALE=(1.0, 2.0))\nFIN()\n";

std::string readAll(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Refused before anything ran: exit 1, the cause and "nothing was run" on stderr, no command echoed.
void expectRefused(const RunResult& r, const std::string& cause) {
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_TRUE(contains(r.output, cause)) << "expected: " << cause << "\ngot:\n" << r.output;
    EXPECT_TRUE(contains(r.output, "; nothing was run")) << r.output;
    EXPECT_FALSE(contains(r.output, "DEFI_LIST_REEL(")) << r.output;
}

// A file that must come out of the run as it went in.
struct Victim {
    fs::path path;
    std::string text;
    Victim(const fs::path& p, std::string t) : path(p), text(std::move(t)) { writeText(path, text); }
    void expectUntouched() const { EXPECT_EQ(readAll(path), text) << path; }
};

}  // namespace

// An out-dir .mess or .resu that is a link to a file elsewhere: never followed, on a run that
// would succeed and on one that would fail; the link stays a link.
TEST(OutputFaults, ResultThatIsALinkIsNotFollowed) {
    for (const std::string name : {"t.mess", "t.resu"})
        for (const std::string& comm : {kComm, std::string("DEBUT()\nsyntax error here\n")}) {
            SCOPED_TRACE(name + " / " + comm);
            const auto dir = freshDir();
            writeText(dir / "t.comm", comm);
            const Victim victim(dir / "victim.txt", "somebody's file\n");
            fs::create_directories(dir / "out");
            fs::create_symlink(dir / "victim.txt", dir / "out" / name);
            const auto r = runMiniaster(dir, "t.comm");
            expectRefused(r, "out/" + name + " is a symbolic link (to " + (dir / "victim.txt").string() +
                                 "): the run does not write through a link it did not create");
            victim.expectUntouched();
            EXPECT_TRUE(fs::is_symlink(dir / "out" / name));
        }
}

// The command file or the mesh named like an output: refused, left as they were.
TEST(OutputFaults, InputNamedLikeAnOutput) {
    {
        const auto dir = freshDir();
        fs::create_directories(dir / "out");
        const Victim comm(dir / "out" / "x.mess", kComm);
        const auto r = runMiniaster(dir, "out/x.mess");
        expectRefused(r, "the message log " + (dir / "out" / "x.mess").string() + " is the command file");
        comm.expectUntouched();
    }
    {
        const auto dir = freshDir();
        writeText(dir / "t.comm", kComm);
        fs::create_directories(dir / "out");
        fs::copy_file(kMesh, dir / "out" / "t.mess");
        const std::string mesh = readAll(dir / "out" / "t.mess");
        const auto r = runMiniaster(dir, "t.comm", "--mesh out/t.mess");
        expectRefused(r, "is the data file of unit 20");
        EXPECT_EQ(readAll(dir / "out" / "t.mess"), mesh);
    }
}

// .export lines whose results collide: F mess and F resu on one file, two units on one .rmed, an
// F rmed that is the input mesh reached through a linked folder (and through a hard link).
TEST(OutputFaults, ExportResultsThatCollide) {
    struct Case {
        std::string lines, cause;
    };
    const std::vector<Case> cases = {
        {"F mess r.txt R 6\nF resu r.txt R 8\n",
         "the message log OUT/r.txt and the result file OUT/r.txt are the same file"},
        {"F rmed a.rmed R 80\nF rmed DIR/outlink/a.rmed R 81\n",
         "the result file of unit 80 OUT/a.rmed and the result file of unit 81 DIR/outlink/a.rmed are the same file"},
        {"F mmed in/m.mmed D 20\nF rmed DIR/link/m.mmed R 80\n",
         "result file of unit 80 DIR/link/m.mmed is the data file of unit 20"},
        {"F mmed in/m.mmed D 20\nF rmed DIR/hard.mmed R 80\n",
         "result file of unit 80 DIR/hard.mmed is the data file of unit 20"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.lines);
        const auto dir = freshDir();
        writeText(dir / "t.comm", kComm);
        fs::create_directories(dir / "in");
        fs::create_directories(dir / "out");
        fs::copy_file(kMesh, dir / "in" / "m.mmed");
        fs::create_directory_symlink(dir / "in", dir / "link");
        fs::create_directory_symlink(dir / "out", dir / "outlink");
        fs::create_hard_link(dir / "in" / "m.mmed", dir / "hard.mmed");
        const std::string mesh = readAll(dir / "in" / "m.mmed");
        std::string lines = c.lines, cause = c.cause;
        for (auto* s : {&lines, &cause}) {
            *s = std::regex_replace(*s, std::regex("DIR/"), dir.string() + "/");
            *s = std::regex_replace(*s, std::regex("OUT/"), (dir / "out").string() + "/");
        }
        writeText(dir / "t.export", "F comm t.comm D 1\n" + lines);
        const auto r = runMiniaster(dir, "t.export");
        expectRefused(r, cause);
        EXPECT_EQ(readAll(dir / "in" / "m.mmed"), mesh);
    }
}

// Result paths that are a FIFO or a character device: refused at once (no open, no wait).
TEST(OutputFaults, ResultThatIsAFifoOrADevice) {
    const auto dir = freshDir();
    writeText(dir / "t.comm", kComm);
    fs::create_directories(dir / "out");
    ASSERT_EQ(::mkfifo((dir / "out" / "f.rmed").c_str(), 0600), 0);
    writeText(dir / "t.export", "F comm t.comm D 1\nF rmed f.rmed R 80\n");
    auto r = runMiniaster(dir, "t.export");
    expectRefused(r, "the result file of unit 80 " + (dir / "out" / "f.rmed").string() +
                         " exists and is not a regular file (a FIFO)");
    writeText(dir / "t.export", "F comm t.comm D 1\nF rmed /dev/null R 80\n");
    r = runMiniaster(dir, "t.export");
    expectRefused(r, "the result file of unit 80 /dev/null exists and is not a regular file (a device)");
    fs::remove(dir / "out" / "f.rmed");
    // A unit without an F line (fort.38 of the output folder) is known when a command writes it.
    const Victim victim(dir / "victim.txt", "somebody's file\n");
    fs::create_symlink(dir / "victim.txt", dir / "out" / "fort.38");
    writeText(dir / "t.comm",
              "DEBUT()\nMA = LIRE_MAILLAGE(FORMAT='MED')\n"
              "IMPR_RESU(FORMAT='MED', UNITE=38, RESU=_F(MAILLAGE=MA))\nFIN()\n");
    r = runMiniaster(dir, "t.comm", "--mesh '" + kMesh + "'");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_TRUE(contains(r.file("out/t.mess"), "fort.38 of logical unit 38 is a symbolic link")) << r.output;
    victim.expectUntouched();
    EXPECT_TRUE(fs::is_symlink(dir / "out" / "fort.38"));
}

// Item 6: a second run of the case in the same folder is refused while the first runs (its pid
// named, its .mess intact); once the first is killed (SIGKILL: no clean-up of its own), the lock
// is gone with it and the next run works.
TEST(OutputFaults, SecondRunOfTheCaseInTheSameFolder) {
    const auto dir = freshDir();
    writeText(dir / "t.comm", "DEBUT()\nimport time\ntime.sleep(60)\nFIN()\n");
    writeText(dir / "start.sh",
              "cd '" + dir.string() + "' && exec " + quotedBinary() + " run t.comm --out-dir out > first.log 2>&1\n");
    const pid_t first = ::fork();
    ASSERT_GE(first, 0);
    if (first == 0) {
        ::execl("/bin/sh", "sh", (dir / "start.sh").c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    // The end of DEBUT is the first run's last line before its sleep: its .mess is stable from then on.
    while (!contains(readAll(dir / "out" / "t.mess"), "end of DEBUT") && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    const std::string firstMess = readAll(dir / "out" / "t.mess");
    ASSERT_TRUE(contains(firstMess, "end of DEBUT")) << readAll(dir / "first.log");

    writeText(dir / "t.comm", kComm);  // the first run has read its own
    auto second = runMiniaster(dir, "t.comm");
    expectRefused(second, "another run of this case is writing in this output folder (process " +
                              std::to_string(first) + ", still running): its message log " +
                              (dir / "out" / "t.mess").string() + " is locked");
    EXPECT_EQ(readAll(dir / "out" / "t.mess"), firstMess);

    ::kill(first, SIGKILL);
    int status = 0;
    ::waitpid(first, &status, 0);
    second = runMiniaster(dir, "t.comm");
    EXPECT_EQ(second.status, 0) << second.output;
    EXPECT_TRUE(contains(second.file("out/t.mess"), "--- DIAGNOSTIC JOB : OK"));
}
