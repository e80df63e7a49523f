// The run's environment (issue 29 items 6-8): what a run touches outside its outputs (traced with
// strace), the embedded Python against a venv or a wrong PYTHONHOME, the process's own limits
// (ulimit -v, ulimit -t) named as such, and inputs that are not what they seem (a file name that
// is not UTF-8, an unreadable command file, a byte order mark, a FIFO, a 5 MB value, TMPDIR a file).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <thread>

#include "parser_run.hpp"

namespace fs = std::filesystem;
using namespace ma::test;

namespace {

const std::string kSource = MINIASTER_SOURCE_DIR;
const std::string kPatch = kSource + "/astest/fe_patch_quad4";

std::string readAll(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The run ended well (exit 0) with `part` in its .mess `out/<messName>`.
void expectSucceededWith(const RunResult& r, const std::string& messName, const std::string& part) {
    EXPECT_EQ(r.status, 0) << r.output.substr(0, 4000);
    EXPECT_TRUE(contains(r.file("out/" + messName), part)) << r.file("out/" + messName).substr(0, 4000);
}

// The run failed (exit 1) with `part` in its .mess `out/<messName>`; that .mess.
std::string expectFailedWith(const RunResult& r, const std::string& messName, const std::string& part) {
    EXPECT_EQ(r.status, 1) << r.output.substr(0, 4000);
    const std::string mess = r.file("out/" + messName);
    EXPECT_TRUE(contains(mess, part)) << mess.substr(0, 4000);
    return mess;
}

// One system call of an strace -ff file: name, quoted paths, result, the process's program.
struct Call {
    std::string name, args, program;
    std::vector<std::string> paths;
    long result = -1;
};

// Every call of the traces `<prefix>.<pid>`; `program` is the last execve of that process.
std::vector<Call> readTraces(const fs::path& folder) {
    static const std::regex line(R"(^([a-z0-9_]+)\((.*)\)\s+= (-?[0-9]+))");
    static const std::regex quoted(R"re("((?:[^"\\]|\\.)*)")re");
    std::vector<Call> calls;
    for (const auto& file : fs::directory_iterator(folder)) {
        std::ifstream in(file.path());
        std::string program;
        for (std::string text; std::getline(in, text);) {
            std::smatch m;
            if (!std::regex_search(text, m, line)) continue;
            Call c{m[1], m[2], program, {}, std::stol(m[3])};
            for (std::sregex_iterator q(c.args.begin(), c.args.end(), quoted), end; q != end; ++q)
                c.paths.push_back((*q)[1]);
            if (c.name == "execve" && c.result == 0 && !c.paths.empty()) program = c.paths[0];
            c.program = program;
            calls.push_back(c);
        }
    }
    return calls;
}

// The path a successful call creates ("" for none).
std::string createdPath(const Call& c) {
    if (c.result < 0) return "";
    if ((c.name == "open" || c.name == "openat" || c.name == "creat") && !c.paths.empty() &&
        (c.name == "creat" || contains(c.args, "O_CREAT")))
        return c.paths[0];
    if ((c.name == "mkdir" || c.name == "mkdirat" || c.name == "mknod" || c.name == "mknodat") && !c.paths.empty())
        return c.paths[0];
    if ((c.name.starts_with("rename") || c.name.starts_with("link") || c.name.starts_with("symlink")) &&
        c.paths.size() >= 2)
        return c.paths[1];
    return "";
}

const char* kTraced =
    "execve,connect,bind,listen,sendto,sendmsg,open,openat,creat,mkdir,mkdirat,mknod,mknodat,rename,renameat,renameat2,"
    "link,linkat,"
    "symlink,symlinkat";

// Runs `miniaster run <args>` under strace -ff in `dir` with TMPDIR=dir/tmp; the calls.
std::vector<Call> tracedRun(const fs::path& dir, const std::string& args, int& status) {
    fs::create_directories(dir / "trace");
    fs::create_directories(dir / "tmp");
    const std::string cmd = "cd '" + dir.string() + "' && TMPDIR='" + (dir / "tmp").string() +
                            "' strace -qq -ff -o trace/t -e trace=" + kTraced + " '" + MINIASTER_BINARY + "' run " +
                            args + " --out-dir out --verbose > log.txt 2>&1";
    status = WEXITSTATUS(std::system(cmd.c_str()));
    return readTraces(dir / "trace");
}

bool under(const std::string& path, const fs::path& folder) {
    const std::string f = folder.string() + "/";
    return path.starts_with(f) || path + "/" == f;
}

// Every file or folder the run created is in its output folder or its OpenMPI session folder
// ($TMPDIR/miniaster-mpi.miniaster-tmp.<host>.<pid>), or is a write to /proc (the peak memory's
// reset); the session folder is gone after the run.
void expectNothingCreatedElsewhere(const std::vector<Call>& calls, const fs::path& dir) {
    size_t inSession = 0;
    for (const auto& c : calls) {
        const std::string p = createdPath(c);
        if (p.empty() || p.starts_with("/proc/")) continue;
        const bool session = under(p, dir / "tmp") && contains(p, "/miniaster-mpi.miniaster-tmp.");
        inSession += session;
        EXPECT_TRUE(under(p, dir / "out") || p.starts_with("out/") || p == "out" || session)
            << c.name << " creates " << p << " (program " << c.program << ")";
    }
    EXPECT_GT(inSession, 0u) << "OpenMPI's session folder is in the run's temporary folder";
    EXPECT_TRUE(fs::is_empty(dir / "tmp")) << "the session folder is removed at the end";
}

// A command file that runs until it is killed, once `started` exists.
std::string endlessComm() { return "DEBUT()\nopen('started', 'w').close()\nwhile True: pass\n"; }

}  // namespace

// Item 6: one process connects, binds and sends nothing (hwloc's GL plugin probed the X servers on
// 127.0.0.1:6000-6009 and /tmp/.X11-unix) and creates nothing outside its outputs and its session
// folder (OpenMPI's, in /tmp/ompi.<host>.<uid> and /dev/shm before).
TEST(Environment, OneProcessOpensNoConnectionAndWritesOnlyItsFolders) {
    auto dir = freshDir();
    int status = -1;
    const auto calls = tracedRun(dir, "'" + kPatch + ".export'", status);
    ASSERT_EQ(status, 0) << readAll(dir / "log.txt");
    ASSERT_GT(calls.size(), 100u) << "strace (Debian package strace) traced the run";
    for (const auto& c : calls)  // OpenMPI's interface list is an ioctl on a socket: nothing connects or sends
        EXPECT_TRUE(c.name != "connect" && c.name != "bind" && c.name != "listen" && !c.name.starts_with("send"))
            << c.name << "(" << c.args << ")";
    expectNothingCreatedElsewhere(calls, dir);
    EXPECT_TRUE(fs::exists(dir / "out/fe_patch_quad4.mess"));
}

// Item 6 on two processes (--np 2: the binary becomes mpirun). What is legitimate: each process
// connects to its mpirun on 127.0.0.1 (PMIx); mpirun listens on 127.0.0.1 (PMIx) and, for the
// daemons of other nodes, on every interface (OpenMPI 4.1's out-of-band channel has no way to
// bind to the loopback only: README "Security"); the processes bind nothing (shared memory, no
// TCP transport). Nothing else connects, and nothing is created outside the two folders.
TEST(Environment, TwoProcessesTalkOnlyToTheirMpirun) {
    auto dir = freshDir();
    int status = -1;
    const auto calls = tracedRun(dir, "--np 2 '" + kPatch + ".export'", status);
    ASSERT_EQ(status, 0) << readAll(dir / "log.txt");
    size_t connects = 0;
    for (const auto& c : calls) {
        const bool mpirun = c.program.ends_with("mpirun") || c.program.ends_with("orterun");
        if (c.name == "connect") {
            ++connects;
            EXPECT_TRUE(contains(c.args, "AF_INET,") && contains(c.args, "inet_addr(\"127.0.0.1\")"))
                << c.program << ": connect(" << c.args << ")";
        }
        if (c.name == "bind") {
            EXPECT_TRUE(mpirun || contains(c.args, "inet_addr(\"127.0.0.1\")"))
                << c.program << ": bind(" << c.args << ")";
        }
    }
    EXPECT_GE(connects, 2u) << "each process connects to mpirun";
    expectNothingCreatedElsewhere(calls, dir);
}

// Item 6: a --np run killed by SIGKILL (mpirun and its processes) leaves its session folder; the
// next run removes it.
TEST(Environment, SessionFolderOfAKilledRunIsRemovedByTheNextRun) {
    auto dir = freshDir();
    fs::create_directories(dir / "tmp");
    writeText(dir / "t.comm", endlessComm());
    const pid_t child = fork();
    if (child == 0) {
        setsid();
        const std::string cmd = "cd '" + dir.string() + "' && exec env TMPDIR='" + (dir / "tmp").string() + "' '" +
                                MINIASTER_BINARY + "' run --np 2 t.comm --out-dir out > log.txt 2>&1";
        execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    for (int i = 0; i < 600 && !fs::exists(dir / "started"); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    ASSERT_TRUE(fs::exists(dir / "started")) << readAll(dir / "log.txt");
    kill(-child, SIGKILL);
    waitpid(child, nullptr, 0);
    // mpirun (its own process group) goes with the launcher, the processes with mpirun (their
    // SIGTERM: INTERRUPTED); none may run on (they used to spin for ever).
    auto running = [&] {
        int n = 0;
        for (const auto& e : fs::directory_iterator("/proc")) {
            std::error_code ec;
            n += fs::read_symlink(e.path() / "cwd", ec) == dir;
        }
        return n;
    };
    for (int i = 0; i < 100 && running() > 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    EXPECT_EQ(running(), 0);
    std::vector<std::string> left;
    for (const auto& e : fs::directory_iterator(dir / "tmp")) left.push_back(e.path().filename().string());
    ASSERT_EQ(left.size(), 1u);
    EXPECT_TRUE(left[0].starts_with("miniaster-mpi.miniaster-tmp.")) << left[0];

    writeText(dir / "u.comm", "DEBUT()\nFIN()\n");
    auto r = runMiniaster(dir, "u.comm", "", "TMPDIR='" + (dir / "tmp").string() + "'");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(fs::is_empty(dir / "tmp"));
}

// Item 6 / issue 28: TMPDIR naming a file is refused at once, with its name.
TEST(Environment, TemporaryFolderThatIsAFile) {
    auto dir = freshDir();
    writeText(dir / "afile", "");
    writeText(dir / "t.comm", "DEBUT()\nFIN()\n");
    for (const std::string np : {"", "--np 2"}) {
        auto r = runMiniaster(dir, "t.comm", np, "TMPDIR='" + (dir / "afile").string() + "'");
        EXPECT_EQ(r.status, 1) << r.output;
        EXPECT_TRUE(contains(r.output, "miniaster: the temporary folder TMPDIR=" + (dir / "afile").string() +
                                           " is not a folder; nothing was run"))
            << r.output;
        EXPECT_FALSE(contains(r.output, "orte_init")) << r.output;
    }
}

// Item 7: a venv first on PATH (its python3 without numpy) does not change the interpreter; a
// wrong PYTHONHOME is ignored and said; PYTHONPATH is honoured; one holding a broken standard
// library is an error with a .mess, not an abort.
TEST(Environment, EmbeddedPythonIsTheBuildOne) {
    auto dir = freshDir();
    fs::create_directories(dir / "venv/bin");
    fs::create_symlink("/usr/bin/python3", dir / "venv/bin/python3");
    writeText(dir / "venv/pyvenv.cfg", "home = /usr/bin\ninclude-system-site-packages = false\n");
    writeText(dir / "t.comm", "DEBUT()\nimport numpy\nprint('numpy', numpy.__name__)\nFIN()\n");
    expectSucceededWith(runMiniaster(dir, "t.comm", "", "PATH='" + (dir / "venv/bin").string() + "':\"$PATH\""),
                        "t.mess", "numpy numpy");
    fs::create_directories(dir / "fake");  // a python3 that is a script (pyenv's shims are)
    writeText(dir / "fake/python3", "#!/bin/sh\nexit 1\n");
    fs::permissions(dir / "fake/python3", fs::perms::owner_all);
    expectSucceededWith(runMiniaster(dir, "t.comm", "", "PATH='" + (dir / "fake").string() + "':\"$PATH\""), "t.mess",
                        "numpy numpy");

    expectSucceededWith(runMiniaster(dir, "t.comm", "", "PYTHONHOME=/nonexistent"), "t.mess",
                        "PYTHONHOME=/nonexistent is ignored");

    fs::create_directories(dir / "mods");  // PYTHONPATH for the user's own modules is honoured
    writeText(dir / "mods/mymod.py", "X = 3\n");
    writeText(dir / "m.comm", "DEBUT()\nimport mymod\nprint('mymod', mymod.X)\nFIN()\n");
    expectSucceededWith(runMiniaster(dir, "m.comm", "", "PYTHONPATH='" + (dir / "mods").string() + "'"), "m.mess",
                        "mymod 3");
    EXPECT_FALSE(fs::exists(dir / "mods/__pycache__")) << "nothing written beside the module";

    fs::create_directories(dir / "lib/encodings");
    writeText(dir / "lib/encodings/__init__.py", "raise ImportError('not a standard library')\n");
    auto path = runMiniaster(dir, "t.comm", "", "PYTHONPATH='" + (dir / "lib").string() + "'");
    const std::string mess = expectFailedWith(path, "t.mess", "<F> <ERROR> (t.comm): the embedded Python (home ");
    EXPECT_TRUE(contains(mess, "cannot start")) << mess;
    EXPECT_TRUE(contains(mess, "--- DIAGNOSTIC JOB : <F>_ERROR"));
}

// Item 8: ulimit -v is named as the limit, not the machine's memory (checked size and failed
// allocation alike).
TEST(Environment, VirtualMemoryLimitIsNamed) {
    for (const std::string n : {"300000000", "240000000"}) {
        auto r = runComm("DEBUT()\nL = DEFI_LIST_REEL(DEBUT=0., INTERVALLE=_F(JUSQU_A=1., NOMBRE=" + n + "))\nFIN()\n",
                         "", "ulimit -v 2000000;");
        const std::string mess = expectFailedWith(r, "t.mess", "<F> <ERROR> DEFI_LIST_REEL (t.comm, line 2): ");
        EXPECT_TRUE(contains(mess, "the 1953 MB limit of the process's virtual memory (ulimit -v, RLIMIT_AS)")) << mess;
        EXPECT_FALSE(contains(mess, "of memory available on this machine")) << mess;
    }
}

// Item 8: a hard ulimit -t (soft = hard: the kernel sends SIGKILL) stops the run just before it,
// with the TIME_LIMIT paragraph.
TEST(Environment, CpuTimeLimitOfTheProcessStopsTheRun) {
    auto r = runComm("DEBUT()\nwhile True: pass\n", "", "ulimit -t 3;");
    const std::string mess =
        expectFailedWith(r, "t.mess",
                         "<F> <TIME_LIMIT> (t.comm, in the Python code after the command of line 1): the CPU "
                         "time limit of the process (3 s: ulimit -t, RLIMIT_CPU) is about to be reached");
    EXPECT_TRUE(contains(mess, "--- DIAGNOSTIC JOB : <F>_TIME_LIMIT"));
}

// Item 8: a command file whose name is not UTF-8 runs (an error in it names its line).
TEST(Environment, CommandFileNameNotUtf8) {
    auto dir = freshDir();
    writeText(dir / "t\xe9.comm", "DEBUT()\nx = 1\nFIN()\n");
    writeText(dir / "u\xe9.comm", "DEBUT()\nx = 1 / 0\nFIN()\n");
    expectSucceededWith(runMiniaster(dir, "t\xe9.comm"), "t\xe9.mess", "--- DIAGNOSTIC JOB : OK");
    expectFailedWith(runMiniaster(dir, "u\xe9.comm"), "u\xe9.mess",
                     "<F> <ERROR> (u\xe9.comm, line 2): error in the Python code of the command file: "
                     "ZeroDivisionError");
}

// Item 8: an unreadable command file says so (as root: run as nobody, who cannot read it).
TEST(Environment, UnreadableCommandFile) {
    auto dir = freshDir();
    writeText(dir / "t.comm", "DEBUT()\nFIN()\n");
    fs::permissions(dir, fs::perms::all);
    fs::permissions(dir / "t.comm", fs::perms::owner_read | fs::perms::owner_write);
    const std::string asOther = geteuid() == 0 ? "exec setpriv --reuid=nobody --regid=nogroup --clear-groups" : "";
    if (geteuid() != 0) fs::permissions(dir / "t.comm", fs::perms::none);
    const std::string mess = expectFailedWith(runMiniaster(dir, "t.comm", "", asOther), "t.mess",
                                              "<F> <ERROR> (t.comm): cannot read the command file " +
                                                  (dir / "t.comm").string() + ": Permission denied");
    EXPECT_FALSE(contains(mess, "internal error"));
}

// Item 8: a UTF-8 byte order mark at the top of the .export (Windows editors write one).
TEST(Environment, ByteOrderMarkInTheExport) {
    auto dir = freshDir();
    writeText(dir / "t.comm", "DEBUT()\nFIN()\n");
    writeText(dir / "t.export", "\xEF\xBB\xBFP time_limit 60\nF comm t.comm D 1\n");
    expectSucceededWith(runMiniaster(dir, "t.export"), "t.mess", "limits      : time 60 s (CPU)");
}

// Item 8: the .mess echoes a bounded prefix of huge values, with their count; an error quoting a
// huge value is bounded too (a 50 MB GROUP_MA made a 100 MB .mess).
TEST(Environment, HugeValuesAreEchoedBounded) {
    auto r = runComm(
        "DEBUT()\nL = DEFI_LIST_REEL(VALE=[float(i) for i in range(1000000)])\n"
        "M = DEFI_LIST_REEL(VALE=1., TITRE='x' * 5000000)\nN = DEFI_LIST_REEL(VALE=1., INFO='y' * 5000000)\nFIN()\n");
    EXPECT_EQ(r.status, 1) << r.output.substr(0, 2000);
    const std::string mess = r.file("out/t.mess");
    EXPECT_LT(mess.size(), 40000u);
    EXPECT_TRUE(contains(mess, ", 98, 99, ... (1000000 values))")) << mess.substr(0, 4000);
    EXPECT_TRUE(contains(mess, "xxx... (5000000 characters)'"));
    EXPECT_TRUE(contains(mess, "<F> <ERROR> DEFI_LIST_REEL (t.comm, line 4): keyword INFO: 'yyy"));
    EXPECT_TRUE(contains(mess, "... (5000039 characters)")) << "the paragraph, cut";
}

// Issue 28: a FIFO as the command file (or a data file of the .export) is refused at once; an
// empty --out-dir is a usage error (it aborted).
TEST(Environment, FifoAndEmptyOutDir) {
    auto dir = freshDir();
    ASSERT_EQ(mkfifo((dir / "f.comm").c_str(), 0600), 0);
    writeText(dir / "g.export", "F comm f.comm D 1\n");
    const auto t0 = std::chrono::steady_clock::now();
    auto direct = runMiniaster(dir, "f.comm");
    auto exported = runMiniaster(dir, "g.export");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 30.0);
    expectFailedWith(direct, "f.mess",
                     "<F> <ERROR> the command file f.comm is not a regular file (a FIFO, a device or a socket");
    expectFailedWith(exported, "g.mess", "g.export, line 1: " + (dir / "f.comm").string() + " is not a regular file");

    writeText(dir / "t.comm", "DEBUT()\nFIN()\n");
    const std::string cmd =
        "cd '" + dir.string() + "' && '" + MINIASTER_BINARY + "' run t.comm --out-dir '' 2> err.txt";
    const int raw = std::system(cmd.c_str());
    EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 1) << raw;
    EXPECT_TRUE(contains(readAll(dir / "err.txt"), "miniaster: --out-dir needs a value, got an empty one"));
}
