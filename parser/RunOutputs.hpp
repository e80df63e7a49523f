#pragma once
// The files of a run: where they go, checked before the first command runs, and how they end.
// - Every path is absolute (a .comm that calls os.chdir cannot lose an output).
// - The output folder and every result path (R) are checked writable up front (< 1 s): a folder
//   that cannot be created, a file in the way, a read-only place, /proc...
// - The .mess is a log, streamed as the run goes; results are atomic (core/AtomicFile.hpp).
// - The .resu is written at the end, also after a failure when it holds lines (TEST lines done
//   so far, as code_aster keeps them); a failure never removes or replaces a file the run did not
//   write, and never a previous result by an empty one.
// - .export extras: DC data are decompressed into a scratch folder of the run, RC results are
//   written there and gzip-compressed to their path at the end; an R directory is created and
//   receives the units without an F line (fort.N).
#include <string>
#include <vector>

#include "parser/ExportFile.hpp"

namespace ma {

class RunState;

struct RunOutputs {
    std::string outDir;  // absolute
    std::string mess, resu;
    bool resuCompressed = false;
    std::string scratch;  // "" until a DC/RC line needs it
    struct Compressed {
        std::string plain, final;
    };
    std::vector<Compressed> compressedResults;
    std::vector<std::string> resultFolders;  // R directories (created)
    std::vector<std::string> resultFiles;    // F ... R files (their folder is checked)
    int messFd = -1;
};

// Units, .mess/.resu paths, R directories and DC/RC files of the .export. UserError on a file
// that cannot be decompressed.
void applyExport(const ExportFile& exportFile, RunState& run, RunOutputs& out);
// Checks that no output is a link, a special file, an input of the run (`exportFile` "" for a
// .comm run) or another output (parser/OutputGuard.hpp); creates and checks the output folder and
// every result path; removes stale temporaries of dead runs there. UserError naming the path and
// the reason.
void prepareOutputs(RunOutputs& out, const RunState& run, const std::string& exportFile);
// Opens the .mess locked against another run of the case and streams the log into it (UserError
// when it cannot be created or another run holds it).
void openMessageLog(RunOutputs& out);
// End of run: the .resu (see above), the compressed results, the .mess synced and closed, the
// scratch folder removed. False when an output could not be written (reported on stderr).
bool finishOutputs(RunOutputs& out, bool failed, bool checkOnly);
// Emergency end from the watchdog thread: `paragraph` and the diagnostic appended to the log,
// the .resu with the lines so far, temporaries removed, _exit(1).
[[noreturn]] void stopRunNow(RunOutputs& out, const std::string& paragraph, const std::string& diagnostic);

}  // namespace ma
