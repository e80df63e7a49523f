#include "parser/RunGuard.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/MemoryLimit.hpp"
#include "core/MemoryUsage.hpp"
#include "core/Messages.hpp"
#include "parser/PeerWatch.hpp"
#include "parser/RunState.hpp"

namespace ma {

namespace {

constexpr int kStopSignals[] = {SIGTERM, SIGINT, SIGHUP, SIGXCPU};
constexpr int kTickMs = 50;  // how often the limits are looked at

int gWakePipe[2] = {-1, -1};
std::atomic<bool> gStopping{false};
std::thread* gWatchdog = nullptr;

extern "C" void onStopSignal(int sig) {
    const unsigned char byte = static_cast<unsigned char>(sig);
    [[maybe_unused]] const ssize_t n = ::write(gWakePipe[1], &byte, 1);
}

double cpuSeconds() {
    timespec t{};
    ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// The soft RLIMIT_CPU (ulimit -t), when set. At a hard limit equal to it (what `ulimit -t` sets)
// the kernel sends SIGKILL, not SIGXCPU: the run stops a little before, with its paragraph.
std::optional<double> processCpuLimit() {
    rlimit limit{};
    if (::getrlimit(RLIMIT_CPU, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
    return double(limit.rlim_cur);
}

void checkProcessCpuLimit(const std::optional<double>& seconds, StopHandler stop) {
    if (!seconds) return;
    const double margin = std::min(1.0, 0.2 * *seconds);  // CPU seconds; ticks of 50 ms, several threads
    if (const double used = cpuSeconds(); used > *seconds - margin)
        stop("TIME_LIMIT", fmt::format("the CPU time limit of the process ({:g} s: ulimit -t, RLIMIT_CPU) is about to "
                                       "be reached ({:.1f} s used); the run is stopped before the system kills it",
                                       *seconds, used));
}

// Another process of the run that ended first (mpirun then ends the job with SIGTERM): named.
void stopIfPeerEnded(StopHandler stop, const PeerWatch& peers) {
    if (const auto peer = peers.endedPeer(); peer && !gStopping)
        stop("ERROR", fmt::format("{} ended before the end of the run, without a message of its own (os._exit, a "
                                  "crash or a kill); the run is stopped",
                                  *peer));
}

void stopOnSignal(StopHandler stop, const PeerWatch& peers) {
    unsigned char sig = 0;
    if (::read(gWakePipe[0], &sig, 1) != 1 || gStopping) return;
    stopIfPeerEnded(stop, peers);
    stop("INTERRUPTED", fmt::format("the run is stopped by signal {} ({})", int(sig), strsignal(sig)));
}

void watch(RunLimits limits, StopHandler stop) {
    const std::optional<double> processLimit = processCpuLimit();
    const PeerWatch peers;
    std::vector<pollfd> fds = {{gWakePipe[0], POLLIN, 0}};
    peers.addTo(fds);
    while (!gStopping) {
        if (::poll(fds.data(), fds.size(), kTickMs) > 0) {
            if (fds.size() > 1) stopIfPeerEnded(stop, peers);
            if (fds[0].revents & POLLIN) stopOnSignal(stop, peers);
        }
        if (gStopping) return;
        if (limits.timeLimitSeconds && cpuSeconds() > *limits.timeLimitSeconds)
            stop("TIME_LIMIT", fmt::format("the time limit of {:g} s (P time_limit, CPU time of the process) is "
                                           "reached; the run is stopped",
                                           *limits.timeLimitSeconds));
        checkProcessCpuLimit(processLimit, stop);
        if (const double resident = limits.memoryLimitMb ? residentMemoryMb() : 0.0;
            limits.memoryLimitMb && resident > *limits.memoryLimitMb)
            stop("MEMORY_LIMIT", fmt::format("the resident memory of the process ({:.0f} MB) exceeds the "
                                             "memory_limit of {:g} MB (P memory_limit); the run is stopped",
                                             resident, *limits.memoryLimitMb));
    }
}

// ---- crash handler

int gCrashFd = -1;

void writeAll(int fd, const char* data, size_t size) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n <= 0) return;
        data += n;
        size -= size_t(n);
    }
}

extern "C" void onFatalSignal(int sig) {
    // Best effort: the process is already broken; only write() on prepared data.
    const auto& run = RunState::current();
    char where[160];
    if (run.runningCommand[0])
        std::snprintf(where, sizeof(where), "%s (%s, line %d)", run.runningCommand, run.commBaseName.c_str(),
                      run.runningLine);
    else std::snprintf(where, sizeof(where), "(%s)", run.commBaseName.c_str());
    char paragraph[640];
    const int len = std::snprintf(paragraph, sizeof(paragraph),
                                  "\n<F> <ABNORMAL_ABORT> %s: the process received signal %d (%s); this is a defect "
                                  "of miniaster, please report it\n\n"
                                  "------------------------------------------------------------\n"
                                  "--- DIAGNOSTIC JOB : <F>_ABNORMAL_ABORT\n"
                                  "------------------------------------------------------------\n",
                                  where, sig, strsignal(sig));
    const size_t size = len > 0 ? size_t(std::min<int>(len, sizeof(paragraph) - 1)) : 0;
    writeAll(STDOUT_FILENO, paragraph, size);
    if (gCrashFd >= 0) writeAll(gCrashFd, paragraph, size);
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

}  // namespace

void armStopSignals() {
    if (gWakePipe[0] < 0 && ::pipe2(gWakePipe, O_CLOEXEC) != 0) return;
    struct sigaction action {};
    action.sa_handler = onStopSignal;
    sigemptyset(&action.sa_mask);
    for (int sig : kStopSignals) ::sigaction(sig, &action, nullptr);
    std::signal(SIGXFSZ, SIG_IGN);
    std::signal(SIGPIPE, SIG_IGN);
}

void startRunGuard(const RunLimits& limits, StopHandler stop) {
    if (gWatchdog) return;
    armStopSignals();  // again: the interpreter took SIGINT
    if (gWakePipe[0] < 0) return;
    if (limits.memoryLimitMb) setMemoryLimit(*limits.memoryLimitMb);
    gWatchdog = new std::thread(watch, limits, stop);
}

void stopRunGuard() {
    if (!gWatchdog) return;
    gStopping = true;
    gWatchdog->join();
    delete gWatchdog;
    gWatchdog = nullptr;
    for (int sig : kStopSignals) std::signal(sig, SIG_IGN);
}

void installCrashHandler(int messFd) {
    gCrashFd = messFd;
    for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(sig, onFatalSignal);
}

}  // namespace ma

namespace ma {

std::string unexpectedErrorCause(const std::exception& e) {
    std::string what = e.what();
    for (auto at = what.find("std::"); at != std::string::npos; at = what.find("std::")) what.erase(at, 5);
    if (dynamic_cast<const std::length_error*>(&e))
        return "a size too large to be allocated was requested (" + what +
               "); check the sizes given in the command file";
    return "internal error of miniaster (" + what + "); please report it with the command file";
}

}  // namespace ma
