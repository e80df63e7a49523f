#include "cli/MpiLaunch.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "cli/MpiConfinement.hpp"
#include "cli/MpirunChild.hpp"
#include "core/Mpi.hpp"
#include "parser/ExportFile.hpp"

namespace ma::cli {

namespace {

// The most processes `--np` starts per core of this machine (docs/mpi.md, "Running").
constexpr int kProcessesPerCore = 4;

std::optional<int> processCount(const std::string& text) {
    try {
        size_t end = 0;
        const int k = std::stoi(text, &end);
        if (end == text.size() && k >= 1 && k <= kMaxProcesses) return k;
    } catch (const std::exception&) {}
    return std::nullopt;
}

// --np on the command line, else P mpi_nbcpu of the .export; 1 when neither (or when either is
// invalid: the supervisor reports it, in one process).
int requestedProcesses(int argc, char** argv) {
    std::string exportPath;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--np") return i + 1 < argc ? processCount(argv[i + 1]).value_or(1) : 1;
        if (exportPath.empty() && a.size() > 7 && a.ends_with(".export")) exportPath = a;
    }
    if (exportPath.empty()) return 1;
    try {
        return readExportFile(exportPath, std::nullopt).mpiProcesses.value_or(1);
    } catch (const std::exception&) { return 1; }
}

}  // namespace

int launchProcessesIfAsked(int argc, char** argv) {
    const int k = requestedProcesses(argc, argv);
    if (k <= 1 || mpi::launchedByMpirun()) return -1;
    // Per process: one OpenBLAS thread, and the element loops' threads share the cores.
    const int cores = std::max(1, int(std::thread::hardware_concurrency()));
    if (k > kProcessesPerCore * cores) {
        std::fprintf(stderr,
                     "miniaster: %d MPI processes asked for (--np or P mpi_nbcpu): this machine has %d core(s), and "
                     "miniaster starts at most %d processes per core on it (%d here): beyond that the processes "
                     "mostly wait for their turn on a core at every collective operation, and each holds a whole "
                     "copy of the mesh; nothing was run. On several machines, start mpirun yourself with a hostfile "
                     "(docs/mpi.md)\n",
                     k, cores, kProcessesPerCore, kProcessesPerCore * cores);
        return 1;
    }
    setenv("OPENBLAS_NUM_THREADS", "1", 0);
    setenv("OMP_NUM_THREADS", std::to_string(std::max(1, cores / k)).c_str(), 0);
    // A process waiting in a collective yields its core (on a shared machine the others' jobs
    // otherwise stall the K processes' lock-step; no cost measured on a quiet one).
    setenv("OMPI_MCA_mpi_yield_when_idle", "1", 0);
    if (geteuid() == 0) {  // OpenMPI refuses root without these
        setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 0);
        setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 0);
    }
    confineLaunchedJob();
    std::error_code ec;
    const std::string self = std::filesystem::read_symlink("/proc/self/exe", ec).string();
    std::vector<std::string> args = {"mpirun",    "--quiet",
                                     "-np",       std::to_string(k),
                                     "--bind-to", "none",
                                     "--stdin",   "none",  // mpirun runs in its own process group
                                     "-x",        "OPENBLAS_NUM_THREADS",
                                     "-x",        "OMP_NUM_THREADS"};
    if (k > cores) args.push_back("--oversubscribe");
    args.push_back(ec ? std::string(argv[0]) : self);
    for (int i = 1; i < argc; ++i) args.emplace_back(argv[i]);
    std::vector<char*> c;
    for (auto& a : args) c.push_back(a.data());
    c.push_back(nullptr);
    return runMpirun(c);
}

}  // namespace ma::cli
