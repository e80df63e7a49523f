// Interpreter crashes and what the command file's own Python can do to the process (issue 28
// item 7): values without end, a segfault, signals, a timer it arms, a sleep past the time limit,
// os.fork(), the .mess's descriptor closed. Each ends with its paragraph in the .mess and exit 1
// (or, for a fork and a closed descriptor, the run goes on and completes).
#include <gtest/gtest.h>
#include <signal.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "parser_run.hpp"

namespace fs = std::filesystem;
using namespace ma::test;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

size_t count(const std::string& text, const std::string& part) {
    size_t n = 0;
    for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
}

// The run ended with exit 1, `paragraph` in its .mess and the diagnostic `diagnostic` at its end.
void expectStopped(const RunResult& r, const std::string& paragraph, const std::string& diagnostic) {
    EXPECT_EQ(r.status, 1) << r.output;
    const std::string mess = r.file("out/t.mess");
    EXPECT_TRUE(contains(mess, paragraph)) << "expected: " << paragraph << "\ngot:\n" << mess;
    EXPECT_TRUE(contains(mess, "--- DIAGNOSTIC JOB : " + diagnostic + "\n")) << mess;
    EXPECT_FALSE(contains(r.output, "Traceback")) << r.output;
}

}  // namespace

// A value nested 1e5 deep, a list and an _F that contain themselves: the command's error, naming
// the keyword, instead of a stack overflow or a run without end.
TEST(InterpreterFaults, ValuesWithoutEnd) {
    auto r = runComm("DEBUT()\nv = 1.0\nfor i in range(100000):\n    v = [v]\nL = DEFI_LIST_REEL(VALE=v)\nFIN()\n");
    expectError(r,
                "<F> <ERROR> DEFI_LIST_REEL (t.comm, line 5): the value of VALE is nested more than 32 levels deep "
                "(lists, tuples or _F inside each other); a keyword takes a value, a list of values or _F occurrences");
    r = runComm("DEBUT()\nv = [1.0]\nv.append(v)\nL = DEFI_LIST_REEL(VALE=v)\nFIN()\n");
    expectError(r,
                "<F> <ERROR> DEFI_LIST_REEL (t.comm, line 4): the value of VALE contains itself (a list, tuple or "
                "_F that holds itself): it has no end");
    r = runComm(
        "DEBUT()\nf = _F(JUSQU_A=1.0, NOMBRE=2)\nf['PAS'] = [f]\nL = DEFI_LIST_REEL(DEBUT=0., INTERVALLE=f)\nFIN()\n");
    expectError(r,
                "<F> <ERROR> DEFI_LIST_REEL (t.comm, line 4): the value of INTERVALLE contains itself (a list, "
                "tuple or _F that holds itself): it has no end");
}

// A segfault in the command file's own code (ctypes), and one from a stack overflow: the
// paragraph (written from the signal handler, on its own stack), exit 1, no .resu.
TEST(InterpreterFaults, SegfaultInTheCommandFilesCode) {
    auto r = runComm("DEBUT()\nimport ctypes\nctypes.string_at(0)\nFIN()\n");
    expectStopped(r,
                  "<F> <ABNORMAL_ABORT> (t.comm, in the Python code after the command of line 1): the process "
                  "received signal 11 (SIGSEGV, segmentation fault: an invalid memory access); the run is stopped",
                  "<F>_ABNORMAL_ABORT");
    EXPECT_FALSE(r.exists("out/t.resu"));
    // Recursion through C (each level a few C frames) with the interpreter's guard lifted.
    r = runComm(
        "DEBUT()\nimport sys, functools\nsys.setrecursionlimit(10**8)\n"
        "def f(n):\n    return functools.reduce(lambda a, b: f(n + 1), [0, 1], 0)\nf(0)\nFIN()\n");
    expectStopped(r, "the process received signal 11 (SIGSEGV", "<F>_ABNORMAL_ABORT");
}

// Signals whose default action ends the process: sent to it by the command file itself (as
// another process would), a timer it arms (signal.alarm), each ends the run with its paragraph.
TEST(InterpreterFaults, SignalsEndTheRunWithAParagraph) {
    for (int sig : {SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGVTALRM, SIGPROF, SIGPWR, SIGIO}) {
        SCOPED_TRACE(sig);
        const auto r = runComm("DEBUT()\nimport os, time\nos.kill(os.getpid(), " + std::to_string(sig) +
                               ")\ntime.sleep(30)\nFIN()\n");
        expectStopped(r,
                      "<F> <INTERRUPTED> (t.comm, in the Python code after the command of line 1): the run is "
                      "stopped by signal " +
                          std::to_string(sig) + " (" + strsignal(sig) + ")",
                      "<F>_INTERRUPTED");
    }
    for (int sig : {SIGTRAP, SIGSYS}) {
        SCOPED_TRACE(sig);
        const auto r = runComm("DEBUT()\nimport os, time\nos.kill(os.getpid(), " + std::to_string(sig) +
                               ")\ntime.sleep(30)\nFIN()\n");
        expectStopped(r, "the process received signal " + std::to_string(sig) + " (SIG", "<F>_ABNORMAL_ABORT");
    }
    const auto r = runComm("DEBUT()\nimport signal, time\nsignal.alarm(1)\ntime.sleep(30)\nFIN()\n");
    expectStopped(r, "the run is stopped by signal 14 (Alarm clock)", "<F>_INTERRUPTED");
}

// P time_limit counts elapsed time too: a run asleep (no CPU used) is stopped all the same.
TEST(InterpreterFaults, SleepPastTheTimeLimit) {
    auto dir = freshDir();
    writeText(dir / "t.comm", "DEBUT()\nimport time\ntime.sleep(60)\nFIN()\n");
    writeText(dir / "t.export", "P time_limit 2\nF comm t.comm D 1\n");
    const auto r = runMiniaster(dir, "t.export");
    expectStopped(r,
                  "<F> <TIME_LIMIT> (t.comm, in the Python code after the command of line 1): the time limit of "
                  "2 s (P time_limit: CPU time of the process or elapsed time, whichever comes first) is reached",
                  "<F>_TIME_LIMIT");
    const std::string mess = r.file("out/t.mess");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(mess, m, std::regex(R"(is reached \(([0-9.]+) s elapsed, ([0-9.]+) s of CPU\))")));
    EXPECT_GE(std::stod(m[1]), 2.0);  // stopped by the elapsed time: never before it, with CPU to spare
    EXPECT_LT(std::stod(m[2]), 2.0);
}

// os.fork() (Python's) and fork() through ctypes: the child runs nothing of the rest of the file
// and writes nothing; the parent completes the run, once.
TEST(InterpreterFaults, ForkedChildRunsNothing) {
    for (const std::string fork : {"os.fork()", "ctypes.CDLL(None).fork()"}) {
        SCOPED_TRACE(fork);
        const auto r = runComm("DEBUT()\nimport os, ctypes\npid = " + fork +
                               "\nif pid == 0:\n    print('CHILD RAN')\nelse:\n    os.waitpid(pid, 0)\n"
                               "L = DEFI_LIST_REEL(VALE=(1.0, 2.0))\nFIN()\n");
        EXPECT_EQ(r.status, 0) << r.output;
        const std::string mess = r.file("out/t.mess");
        EXPECT_EQ(count(mess, "DEFI_LIST_REEL("), 1u) << mess;
        EXPECT_EQ(count(mess, "--- DIAGNOSTIC JOB : OK"), 1u) << mess;
        if (fork == "os.fork()") {
            EXPECT_FALSE(contains(mess, "CHILD RAN")) << mess;
            EXPECT_TRUE(contains(mess, " <I> os.fork() (line 3): the child process ended at once")) << mess;
        }
        EXPECT_EQ(r.files().size(), 2u);  // t.mess, t.resu
    }
}

// The command file closes the .mess's descriptor and opens a file of its own (which gets that
// number): the log is reopened, nothing of it is lost, the user's file holds only its text.
TEST(InterpreterFaults, MessDescriptorClosedByTheCommandFile) {
    const auto r = runComm(
        "DEBUT()\nimport os\nfor fd in os.listdir('/proc/self/fd'):\n"
        "    try:\n        target = os.readlink('/proc/self/fd/' + fd)\n    except OSError:\n        continue\n"
        "    if target.endswith('t.mess'):\n        os.close(int(fd))\n"
        "mine = open('mine.txt', 'w')\nL = DEFI_LIST_REEL(VALE=(1.0, 2.0))\nmine.write('mine')\nmine.close()\n"
        "FIN()\n");
    EXPECT_EQ(r.status, 0) << r.output;
    const std::string mess = r.file("out/t.mess");
    EXPECT_TRUE(contains(mess, "the descriptor of the message log was closed by the command file")) << mess;
    EXPECT_TRUE(contains(mess, "L = DEFI_LIST_REEL(")) << mess;
    EXPECT_TRUE(contains(mess, "--- DIAGNOSTIC JOB : OK")) << mess;
    EXPECT_TRUE(contains(mess, "  command file: ")) << "the head of the log is kept";
    EXPECT_EQ(r.file("mine.txt"), "mine");
}
