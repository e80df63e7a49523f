#include "cli/MpirunChild.hpp"

#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>

#include "core/ProcessStat.hpp"

namespace ma::cli {

namespace {

constexpr int kStopSignals[] = {SIGTERM, SIGINT, SIGHUP};
// After a forwarded signal, how long the processes have to end before mpirun itself is stopped
// (SIGTERM), then killed with its group (SIGKILL): a process stuck where no signal reaches it.
constexpr double kGraceSeconds = 20.0, kKillSeconds = 5.0;

// The processes whose parent is `parent` (the MPI processes mpirun started on this machine).
std::vector<pid_t> childrenOf(pid_t parent) {
    std::vector<pid_t> out;
    std::error_code ec;
    for (std::filesystem::directory_iterator e("/proc", ec), end; !ec && e != end; e.increment(ec)) {
        const std::string name = e->path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        const auto fields = processStatFields(std::atoi(name.c_str()));
        char state = 0;
        int ppid = 0;
        if (fields && std::sscanf(fields->c_str(), "%c %d", &state, &ppid) == 2 && ppid == parent && state != 'Z')
            out.push_back(std::atoi(name.c_str()));
    }
    return out;
}

int statusOf(int raw) {
    if (WIFEXITED(raw)) {
        const int status = WEXITSTATUS(raw);
        if (status == 0 || status == 1 || status == 2) return status;
        std::fprintf(stderr,
                     "miniaster: mpirun ended with status %d: an MPI process ended with that status before the end "
                     "of the run (the .mess names it)\n",
                     status);
    } else if (WIFSIGNALED(raw)) {
        std::fprintf(stderr, "miniaster: mpirun ended by signal %d (%s)\n", WTERMSIG(raw), strsignal(WTERMSIG(raw)));
    }
    return 1;
}

}  // namespace

int runMpirun(std::vector<char*>& argv) {
    sigset_t stops, previous;
    sigemptyset(&stops);
    for (int sig : kStopSignals) sigaddset(&stops, sig);
    sigaddset(&stops, SIGCHLD);
    sigprocmask(SIG_BLOCK, &stops, &previous);
    std::fflush(stdout);
    const pid_t launcher = ::getpid();
    const pid_t child = ::fork();
    if (child == 0) {
        sigprocmask(SIG_SETMASK, &previous, nullptr);
        // In its own process group, mpirun outlived a launcher killed with its group (SIGKILL):
        // it and the processes ran on for ever. It goes with the launcher now.
        ::prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (::getppid() != launcher) ::_exit(1);
        ::setpgid(0, 0);  // Ctrl-C on the terminal reaches the launcher only, which forwards it
        execvp(argv[0], argv.data());
        std::fprintf(stderr, "miniaster: cannot start mpirun: %s (Debian package openmpi-bin)\n", std::strerror(errno));
        ::_exit(1);
    }
    if (child < 0) {
        std::fprintf(stderr, "miniaster: cannot start mpirun: %s\n", std::strerror(errno));
        return 1;
    }
    using Clock = std::chrono::steady_clock;
    int pending = 0;  // a stop signal not yet delivered to the processes (they were starting)
    std::optional<Clock::time_point> forwarded;
    bool terminated = false;
    for (;;) {
        int raw = 0;
        if (::waitpid(child, &raw, WNOHANG) == child) return statusOf(raw);
        const timespec tick{0, 100'000'000};
        siginfo_t info{};
        const int sig = sigtimedwait(&stops, &info, &tick);
        if (sig == SIGTERM || sig == SIGINT || sig == SIGHUP) pending = sig;
        if (pending) {
            const auto ranks = childrenOf(child);
            for (pid_t p : ranks) ::kill(p, pending);
            if (!ranks.empty()) {
                pending = 0;
                forwarded = Clock::now();
            }
        }
        const double waited = forwarded ? std::chrono::duration<double>(Clock::now() - *forwarded).count() : 0.0;
        if (forwarded && waited > kGraceSeconds && !terminated) {
            ::kill(child, SIGTERM);
            terminated = true;
        }
        if (forwarded && waited > kGraceSeconds + kKillSeconds) ::kill(-child, SIGKILL);
    }
}

void stopWithMpirun() {
    const pid_t parent = ::getppid();
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) ::raise(SIGTERM);  // it ended before the call
}

}  // namespace ma::cli
