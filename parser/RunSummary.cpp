#include "parser/RunSummary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>

#include "core/Messages.hpp"
#include "parser/RunState.hpp"

namespace fs = std::filesystem;

namespace ma {

namespace {

// code_aster's originals whose NON_REGRESSION values (VALE_CALC) are its own inexact contact
// results: ours differ by design, every line documented.
const std::map<std::string, const char*>& knownDifferences() {
    static const std::map<std::string, const char*> cases = {
        {"ssnv511e", "docs/contact.md, appendix \"NON_REGRESSION NOOK lines of ssnv511e-h\""},
        {"ssnv511f", "docs/contact.md, appendix \"NON_REGRESSION NOOK lines of ssnv511e-h\""},
        {"ssnv511g", "docs/contact.md, appendix \"NON_REGRESSION NOOK lines of ssnv511e-h\""},
        {"ssnv511h", "docs/contact.md, appendix \"NON_REGRESSION NOOK lines of ssnv511e-h\""},
        {"ssnv512f", "docs/family.md, \"Results\""},
        {"ssnv513e", "docs/family.md, \"Results\""},
        {"ssnv513g", "docs/family.md, \"Results\""},
    };
    return cases;
}

}  // namespace

namespace {

// Consecutive calls of one command (a loop of TEST_TABLE) make one line, printed when another
// command ends or the run does.
struct PendingCommands {
    std::string command;
    int calls = 0, firstLine = 0, lastLine = 0;
    double seconds = 0;
} gPending;

void flushPending() {
    if (gPending.calls == 0) return;
    const std::string name =
        gPending.calls > 1 ? fmt::format("{} x{}", gPending.command, gPending.calls) : gPending.command;
    const std::string lines = gPending.firstLine == gPending.lastLine
                                  ? fmt::format("line {:5d}", gPending.firstLine)
                                  : fmt::format("lines {}-{}", gPending.firstLine, gPending.lastLine);
    std::fputs(fmt::format("  {:<24} {:<14} {:9.3f} s\n", name, lines, gPending.seconds).c_str(), stdout);
    std::fflush(stdout);
    gPending = {};
}

}  // namespace

void printCommandEnd(const std::string& command, int line, double seconds) {
    if (gPending.calls > 0 && gPending.command != command) flushPending();
    if (gPending.calls == 0) gPending = {command, 0, line, line, 0.0};
    ++gPending.calls;
    gPending.firstLine = std::min(gPending.firstLine, line);
    gPending.lastLine = std::max(gPending.lastLine, line);
    gPending.seconds += seconds;
}

void printRunSummary(const RunState& run, const std::string& diagnostic, const std::vector<std::string>& files,
                     fs::file_time_type start) {
    flushPending();
    std::string out;
    const auto& tests = testReport();
    // Appended piece by piece: gcc 12's -Wrestrict misfires on "\n" + string.
    if (!tests.empty()) out.append("\n").append(tests.summary());
    if (const std::string note = knownDifferenceNote(run.commBaseName, tests); !note.empty())
        out.append(note).append("\n");
    if (!msg().raisedAlarms().empty()) {
        out += "\n  alarms:";
        for (const auto& [id, count] : msg().raisedAlarms()) out += fmt::format(" <{}> x{}", id, count);
        out += " (their text is in the .mess; docs/messages.md says what to do)\n";
    }
    if (run.failure) out.append("\n").append(run.failure->paragraph).append("\n");
    out.append(diagnostic).append("\n");
    std::string written;
    for (const auto& f : files)
        if (std::error_code ec; fs::is_regular_file(f, ec) && fs::last_write_time(f, ec) >= start && !ec)
            written.append("\n    ").append(f);
    if (!written.empty()) out.append("  files:").append(written).append("\n");
    std::fputs(out.c_str(), stdout);
    std::fflush(stdout);
}

std::string knownDifferenceNote(const std::string& commBaseName, const TestReport& tests) {
    const auto it = knownDifferences().find(fs::path(commBaseName).stem().string());
    const int differing = tests.count(TestLine::Status::Nook, true);
    if (it == knownDifferences().end() || differing == 0) return "";
    return fmt::format(
        "  <I> the {} NOOK NON_REGRESSION value{} of {} differ{} by design: VALE_CALC there is code_aster's own "
        "inexact contact result, not a reference (every line: {}; README, \"Running code_aster's originals\")",
        differing, differing > 1 ? "s" : "", it->first, differing > 1 ? "" : "s", it->second);
}

}  // namespace ma
