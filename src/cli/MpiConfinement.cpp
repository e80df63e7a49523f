#include "cli/MpiConfinement.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string_view>

#include "core/AtomicFile.hpp"
#include "core/Mpi.hpp"

namespace fs = std::filesystem;

namespace ma::cli {

namespace {

constexpr const char* kSessionStem = "miniaster-mpi";

// Adds `items` (comma-separated) to the list held by `variable`, keeping what the user gave.
void addToList(const char* variable, std::string_view items) {
    std::string list = std::getenv(variable) ? std::getenv(variable) : "";
    for (size_t start = 0; start < items.size();) {
        const size_t end = std::min(items.find(',', start), items.size());
        const std::string item(items.substr(start, end - start));
        if (("," + list + ",").find("," + item + ",") == std::string::npos) list += (list.empty() ? "" : ",") + item;
        start = end + 1;
    }
    setenv(variable, list.c_str(), 1);
}

// TMPDIR (as OpenMPI reads it), else /tmp; the reason when it cannot hold the session folder.
std::optional<std::string> temporaryBase(std::string& base) {
    const char* tmp = std::getenv("TMPDIR");
    base = tmp && *tmp ? tmp : "/tmp";
    std::error_code ec;
    if (!fs::is_directory(base, ec))
        return "the temporary folder TMPDIR=" + base + (fs::exists(base, ec) ? " is not a folder" : " does not exist");
    if (::access(base.c_str(), W_OK | X_OK) != 0)
        return "cannot write in the temporary folder TMPDIR=" + base + ": " + std::strerror(errno);
    return std::nullopt;
}

}  // namespace

std::optional<std::string> confineMpiLibraries() {
    addToList("HWLOC_PLUGINS_BLACKLIST", "hwloc_gl,hwloc_opencl");
    setenv("OMPI_MCA_shmem", "mmap", 0);
    if (mpi::launchedByMpirun()) return std::nullopt;
    std::string base;
    if (auto refused = temporaryBase(base)) return refused;
    removeStaleTemporaries(base, kSessionStem);
    // Created by MPI_Init (or mpirun), removed by MPI_Finalize (or mpirun); it has this process's
    // pid, which mpirun keeps when the launcher becomes it.
    const std::string session = temporaryPathFor((fs::path(base) / kSessionStem).string());
    setenv("OMPI_MCA_orte_top_session_dir", session.c_str(), 0);
    setenv("OMPI_MCA_btl_vader_backing_directory", session.c_str(), 0);
    setenv("OMPI_MCA_osc_sm_backing_directory", session.c_str(), 0);
    return std::nullopt;
}

void confineLaunchedJob() { setenv("OMPI_MCA_btl", "self,vader", 0); }

}  // namespace ma::cli
