#pragma once
// The run guard: what stops a run from outside the command file, and how it ends.
// - `P time_limit` (CPU seconds of the process or elapsed seconds, whichever comes first),
//   `P memory_limit` (megabytes of resident memory), and every signal that would end the process
//   from outside (SIGTERM, SIGINT, SIGHUP, SIGXCPU, SIGQUIT, SIGUSR1/2, SIGALRM, SIGVTALRM, SIGPROF,
//   SIGPWR, SIGIO; also a timer the command file arms): a watchdog thread ends the run through the
//   stop handler (an <F> paragraph naming the running command, the .mess and the TEST lines so far
//   kept, temporaries removed, exit 1), whatever the main thread is doing.
// - Faults of an instruction (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP, SIGSYS): the crash
//   handler (async-signal-safe, on its own stack: a stack overflow too) appends an
//   <F>_ABNORMAL_ABORT paragraph and diagnostic to the streamed .mess and exits 1.
// - SIGXFSZ and SIGPIPE are ignored: a write beyond the file size limit or to a closed pipe fails
//   (and is reported) instead of killing the run.
#include <optional>
#include <string>

namespace ma {

struct RunLimits {
    std::optional<double> timeLimitSeconds;
    std::optional<double> memoryLimitMb;
};

// Called on the watchdog thread; never returns. `kind` is TIME_LIMIT, MEMORY_LIMIT or INTERRUPTED.
using StopHandler = void (*)(const std::string& kind, const std::string& cause);

// The stop signals are caught from here on (at the start of the run): one that arrives before the
// watchdog starts is handled by it as soon as it does, instead of killing the run mid-header.
void armStopSignals();
// Starts the watchdog (after the interpreter, whose own SIGINT handler it replaces).
void startRunGuard(const RunLimits& limits, StopHandler stop);
// The run is ending normally: the watchdog stops, and a stop signal from then on is ignored (the
// run completes its .mess and ends with its own status: a completed run is not turned into an
// interrupted one, nor cut in the middle of its summary).
void stopRunGuard();

// Crash handler (see above); `messFd` is the streamed .mess, -1 when it is not open.
void installCrashHandler(int messFd);

// Whether this process is a child the command file forked (os.fork, ctypes' fork): it must not run
// the rest of the file nor touch the outputs.
bool isForkedChild();

}  // namespace ma
