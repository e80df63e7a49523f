#pragma once
// What `miniaster run` prints on the terminal (docs/supervisor.md, "The terminal"): one line per
// command as it ends, then the TEST SUMMARY, the alarms raised, the failure, the diagnostic and the
// files written. The .mess keeps everything; `--verbose` echoes the whole .mess instead.
#include <filesystem>
#include <string>
#include <vector>

#include "core/TestReport.hpp"

namespace ma {

class RunState;

// "  LIRE_MAILLAGE             line    12         0.013 s" on stdout (rank 0, summary mode);
// consecutive calls of one command on one line ("  TEST_TABLE x4   lines 447-468   0.001 s").
void printCommandEnd(const std::string& command, int line, double seconds);

// The end of the run on stdout: `diagnostic` is the block of the .mess ("---...--- DIAGNOSTIC JOB :
// ...---..."), `files` the outputs to list when they exist and were modified since `start` (the run's).
void printRunSummary(const RunState& run, const std::string& diagnostic, const std::vector<std::string>& files,
                     std::filesystem::file_time_type start);

// The .mess line saying why NON_REGRESSION values of a case differ from code_aster's by design and
// where the doc lists them; "" when the case is not one of those or nothing differs.
std::string knownDifferenceNote(const std::string& commBaseName, const TestReport& tests);

}  // namespace ma
