#include "parser/RunGuard.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
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

// Every signal whose default action ends the process: the run ends with its paragraph instead.
// Those that come from outside (kill, a timer the command file armed: signal.alarm) stop it from
// the watchdog; the faults of an instruction are the crash handler's (below).
constexpr int kStopSignals[] = {SIGTERM, SIGINT,  SIGHUP,    SIGXCPU, SIGQUIT, SIGUSR1,
                                SIGUSR2, SIGALRM, SIGVTALRM, SIGPROF, SIGPWR,  SIGIO};
constexpr int kFatalSignals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP, SIGSYS};
constexpr int kTickMs = 50;  // how often the limits are looked at

int gWakePipe[2] = {-1, -1};
std::atomic<bool> gStopping{false};
std::thread* gWatchdog = nullptr;
pid_t gRunPid = 0;                                // the process of the run (not a child it forked)
std::chrono::steady_clock::time_point gRunStart;  // wall time of the run's start

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

// P time_limit: CPU time of the process, and elapsed time as code_aster's own limit counts it (a
// run waiting in time.sleep or on a lock uses no CPU).
void checkTimeLimit(const std::optional<double>& limit, StopHandler stop) {
    if (!limit) return;
    const double cpu = cpuSeconds();
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - gRunStart).count();
    if (cpu > *limit || elapsed > *limit)
        stop("TIME_LIMIT", fmt::format("the time limit of {:g} s (P time_limit: CPU time of the process or elapsed "
                                       "time, whichever comes first) is reached ({:.1f} s elapsed, {:.1f} s of CPU); "
                                       "the run is stopped",
                                       *limit, elapsed, cpu));
}

#if defined(__SANITIZE_ADDRESS__)
// AddressSanitizer's shadow memory and quarantine count in the resident memory (2 to 3 times the
// program's own, its documentation says): the .export's limit, meant for the program, is tripled
// for the resident-memory watch (CONTRIBUTING.md, "Sanitizers").
constexpr double kResidentFactor = 3.0;
#else
constexpr double kResidentFactor = 1.0;
#endif

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
        checkTimeLimit(limits.timeLimitSeconds, stop);
        checkProcessCpuLimit(processLimit, stop);
        if (const double resident = limits.memoryLimitMb ? residentMemoryMb() : 0.0;
            limits.memoryLimitMb && resident > kResidentFactor * *limits.memoryLimitMb)
            stop("MEMORY_LIMIT", fmt::format("the resident memory of the process ({:.0f} MB) exceeds the "
                                             "memory_limit of {:g} MB (P memory_limit{}); the run is stopped",
                                             resident, *limits.memoryLimitMb,
                                             kResidentFactor != 1.0 ? ", x3 under AddressSanitizer" : ""));
    }
}

// ---- crash handler (async-signal-safe: write() of text assembled by hand, no allocation)

int gCrashFd = -1;
char gAltStack[1 << 16];  // a stack overflow (deep recursion) still gets its paragraph

struct Text {
    char data[2048];
    size_t size = 0;
    Text& operator<<(const char* s) {
        while (*s && size < sizeof(data)) data[size++] = *s++;
        return *this;
    }
    Text& operator<<(long n) {
        char digits[24];
        int k = 0;
        const bool negative = n < 0;
        unsigned long u = negative ? 0UL - static_cast<unsigned long>(n) : static_cast<unsigned long>(n);
        do digits[k++] = static_cast<char>('0' + u % 10);
        while ((u /= 10) > 0 && k < 22);
        if (negative) digits[k++] = '-';
        while (k > 0 && size < sizeof(data)) data[size++] = digits[--k];
        return *this;
    }
};

void writeAll(int fd, const char* data, size_t size) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n <= 0) return;
        data += n;
        size -= size_t(n);
    }
}

const char* signalName(int sig) {
    switch (sig) {
        case SIGSEGV: return "SIGSEGV, segmentation fault: an invalid memory access";
        case SIGBUS: return "SIGBUS, bus error: an invalid memory access";
        case SIGFPE: return "SIGFPE, arithmetic exception";
        case SIGILL: return "SIGILL, illegal instruction";
        case SIGABRT: return "SIGABRT, aborted";
        case SIGTRAP: return "SIGTRAP, trace or breakpoint trap";
        case SIGSYS: return "SIGSYS, bad system call";
        default: return "a fatal signal";
    }
}

extern "C" void onFatalSignal(int sig) {
    if (::getpid() != gRunPid) ::_exit(1);  // a child forked by the command file: quietly
    const auto& run = RunState::current();
    Text text;
    text << "\n<F> <ABNORMAL_ABORT> ";
    const char* file = run.commBaseName.c_str();
    const long line = run.runningLine;
    if (run.runningCommand[0]) text << run.runningCommand << " (" << file << ", line " << line << ")";
    else if (line) text << "(" << file << ", in the Python code after the command of line " << line << ")";
    else text << "(" << file << ")";
    text << ": the process received signal " << long(sig) << " (" << signalName(sig)
         << "); the run is stopped. Its cause is in native code: the command file's own (ctypes, a C extension "
            "it imports), a Python recursion deeper than the stack (sys.setrecursionlimit), or a defect of "
            "miniaster (then please report it with the command file)\n\n"
            "------------------------------------------------------------\n"
            "--- DIAGNOSTIC JOB : <F>_ABNORMAL_ABORT\n"
            "------------------------------------------------------------\n";
    writeAll(STDOUT_FILENO, text.data, text.size);
    if (gCrashFd >= 0 && msg().streamFd() >= 0) writeAll(msg().streamFd(), text.data, text.size);
    ::_exit(1);
}

}  // namespace

void armStopSignals() {
    if (!gRunPid) {
        gRunPid = ::getpid();
        gRunStart = std::chrono::steady_clock::now();
    }
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
    if (!gRunPid) gRunPid = ::getpid();
    stack_t stack{};
    stack.ss_sp = gAltStack;
    stack.ss_size = sizeof(gAltStack);
    ::sigaltstack(&stack, nullptr);  // this thread's (the main thread: the command file's)
    struct sigaction action {};
    action.sa_handler = onFatalSignal;
    action.sa_flags = SA_ONSTACK;
    sigemptyset(&action.sa_mask);
    for (int sig : kFatalSignals) ::sigaction(sig, &action, nullptr);
}

bool isForkedChild() { return gRunPid != 0 && ::getpid() != gRunPid; }

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
