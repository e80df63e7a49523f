#pragma once
// Helpers for the supervisor tests: write a command file in a fresh temporary folder, run the
// miniaster binary on it, and collect exit status, stdout and the files left behind.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace ma::test {

struct RunResult {
    int status = -1;
    std::string output;  // stdout + stderr
    std::filesystem::path dir;
    std::string file(const std::string& name) const {
        std::ifstream in(dir / name);
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
    }
    bool exists(const std::string& name) const { return std::filesystem::exists(dir / name); }
    // Every file of the output folder (to check that nothing else is left behind).
    std::vector<std::string> files() const {
        std::vector<std::string> out;
        for (const auto& e : std::filesystem::directory_iterator(dir / "out"))
            out.push_back(e.path().filename().string());
        return out;
    }
};

inline std::filesystem::path freshDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    auto dir = std::filesystem::temp_directory_path() / "miniaster-parser-tests" /
               (std::string(info->test_suite_name()) + "." + info->name() + "." + std::to_string(getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline void writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path);
    out << text;
}

inline std::string readText(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// `comm` with `extra` inserted before its last FIN() (a test's commands appended to a case).
inline std::string beforeFin(const std::string& comm, const std::string& extra) {
    const auto fin = comm.rfind("\nFIN(");
    EXPECT_NE(fin, std::string::npos) << "no FIN( in the command file";
    if (fin == std::string::npos) return comm + extra;
    return comm.substr(0, fin + 1) + extra + comm.substr(fin + 1);
}

// Runs `miniaster run <input> --out-dir <dir>/out <extra>` in `dir`.
inline RunResult runMiniaster(const std::filesystem::path& dir, const std::string& input, const std::string& extra = "",
                              const std::string& env = "") {
    RunResult r;
    r.dir = dir;
    const std::string cmd = "cd '" + dir.string() + "' && " + env + " '" + std::string(MINIASTER_BINARY) + "' run '" +
                            input + "' --out-dir out " + extra + " 2>&1";
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buffer{};
    size_t n;
    while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) r.output.append(buffer.data(), n);
    const int raw = pclose(pipe);
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    return r;
}

// Starts `command` (a shell command line) in `dir` in the background, its output in dir/run.log,
// sends it SIGTERM after `seconds` and waits for it (all within `timeout 300`): its exit status,
// -1 when it did not exit.
// The miniaster binary, quoted for a shell command line.
inline std::string quotedBinary() {
    std::string q = "'";
    return q.append(MINIASTER_BINARY).append("'");
}

inline int runThenTerminate(const std::filesystem::path& dir, const std::string& command, int seconds) {
    // Appended piece by piece: gcc 12's -Wrestrict misfires on a chain of operator+ here.
    std::string script = "cd '";
    script.append(dir.string()).append("'\n").append(command).append(" > run.log 2>&1 &\npid=$!\nsleep ");
    script.append(std::to_string(seconds)).append("\nkill -TERM $pid\nwait $pid\n");
    writeText(dir / "kill.sh", script);
    const int raw = std::system(("timeout 300 sh '" + (dir / "kill.sh").string() + "'").c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

// Writes `comm` as t.comm in a fresh folder and runs it.
inline RunResult runComm(const std::string& comm, const std::string& extra = "", const std::string& env = "") {
    auto dir = freshDir();
    writeText(dir / "t.comm", comm);
    return runMiniaster(dir, "t.comm", extra, env);
}

// The run failed with exactly this error paragraph: exit 1, diagnostic in the .mess, no .resu.
inline void expectError(const RunResult& r, const std::string& paragraph, const std::string& diag = "<F>_ERROR") {
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("\n" + paragraph + "\n"), std::string::npos) << "expected:\n"
                                                                         << paragraph << "\ngot:\n"
                                                                         << r.output;
    EXPECT_NE(r.output.find("--- DIAGNOSTIC JOB : " + diag + "\n"), std::string::npos) << r.output;
    EXPECT_FALSE(r.exists("out/t.resu")) << "no result file after an error";
    const std::string mess = r.file("out/t.mess");
    EXPECT_NE(mess.find(paragraph), std::string::npos) << "the .mess keeps the diagnosis";
    for (const auto& f : r.files()) EXPECT_EQ(f, "t.mess") << "unexpected output file " << f;
}

}  // namespace ma::test
