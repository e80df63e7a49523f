#pragma once
// The .export file of a run (commands_spec §7.8, code_aster's run_aster/export.py), read strictly:
// every line is understood or refused with its line number.
//   P <name> <value...>                 parameters (time_limit, memory_limit, ...)
//   A <args...>                         command-line arguments of the command file (ignored)
//   F <type> <path> <D|R|C...> <unit>   a file: D data, R result, C gzip-compressed
//   R <type> <path> <D|R...> <unit>     a directory
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace ma {

// A line of the .export that cannot be honoured: "case.export, line N: cause".
struct ExportError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Largest process count accepted from P mpi_nbcpu and --np.
inline constexpr int kMaxProcesses = 4096;

struct ExportEntry {
    int line = 0;
    bool directory = false;      // an `R` line
    std::string type;            // comm, mmed, rmed, mess, resu, repe, ...
    std::filesystem::path path;  // absolute (data: relative to the .export's folder; results: see below)
    bool data = false, result = false, compressed = false;
    int unit = 0;  // 0: no logical unit
};

struct ExportFile {
    std::string name;  // file name of the .export, for messages
    std::vector<ExportEntry> entries;
    std::optional<double> timeLimitSeconds;         // P time_limit
    std::optional<double> memoryLimitMb;            // P memory_limit
    std::optional<int> mpiProcesses;                // P mpi_nbcpu (processes; --np on the command line wins)
    std::string where(const ExportEntry& e) const;  // "case.export, line N"
};

// Reads and checks `exportPath`. Relative data paths are relative to the .export's folder, relative
// result paths to `resultBase` (the --out-dir when given, else the .export's folder). Checks: the
// syntax of every line, units (integers 0..99, one line per unit, 15 is the 'code' file), flags,
// data files that exist and are regular files (not a directory, a FIFO, a device), a result that would overwrite a data file, a
// code_aster database (`base`/`bhdf`: no POURSUITE in miniaster), one command file.
ExportFile readExportFile(const std::string& exportPath, const std::optional<std::filesystem::path>& resultBase);

// Why an input must be a regular file (the end of the refusal of a FIFO, a device, a socket).
extern const char* const kNotRegular;

}  // namespace ma
