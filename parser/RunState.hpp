#pragma once
// State of one run of a command file, shared by the supervisor (command line, outputs,
// diagnostic) and the Python bridge (command calls).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/Units.hpp"

namespace ma {

struct CommandTiming {
    std::string command;
    int calls = 0;
    double seconds = 0.0;
    long peakKb = 0;  // peak resident memory of the process after the command
};

struct RunFailure {
    std::string kind;       // "ERROR" or "SYNTAX_ERROR" (diagnostic <F>_<kind>)
    std::string paragraph;  // "<F> <ERROR> COMMAND (file.comm, line N): cause"
};

class RunState {
public:
    static RunState& current();

    Units units;
    std::string commFile;                           // path of the command file
    std::string commBaseName;                       // for messages: "ssnv511a.comm"
    bool checkOnly = false;                         // --check-syntax: validate every call, execute none
    bool consoleSummary = false;                    // the terminal gets a summary, not the log (parser/RunSummary)
    std::map<std::string, std::string> runOptions;  // expert options given (parser/RunOptions.hpp)
    bool debutSeen = false;
    bool finSeen = false;
    bool missingDebutReported = false;
    int commandCount = 0;
    // The command being executed, for the crash report and the run guard (parser/RunGuard.hpp).
    char runningCommand[64] = {};
    int runningLine = 0;
    std::optional<RunFailure> failure;
    std::vector<CommandTiming> timings;  // in order of first call

    // Records the first failure (later ones are consequences) and logs its paragraph.
    // `who` is the command name (may be empty), `line` the .comm line (0 when unknown).
    void fail(const std::string& kind, const std::string& who, int line, const std::string& cause);
    void recordTiming(const std::string& command, double seconds);
};

// The processes' agreement on the run's failure (docs/mpi.md), before and after every command
// and at the end of the command file: every process calls it at the same point, with its
// failure if any; afterwards all of them hold the lowest failing rank's paragraph (naming that
// process), rank 0 has logged it, and none calls it again. Nothing on one process.
void agreeWithOtherProcesses(RunState& run);

// Peak resident memory of the process in kB: max of getrusage ru_maxrss and /proc VmHWM.
long peakMemoryKb();

// The cause of an exception no command expected (a defect of miniaster), in words a user can act
// on: never a bare C++ library message.
std::string unexpectedErrorCause(const std::exception& e);

// Installs the `_miniaster` module, the builtins (every catalogued command, _F...) and the
// stdout/stderr redirection into the message log. Needs a running interpreter.
void installPythonBuiltins();

}  // namespace ma
