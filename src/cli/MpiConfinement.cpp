#include "cli/MpiConfinement.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string_view>

#include "core/AtomicFile.hpp"

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

std::string temporaryBase() {
    const char* tmp = std::getenv("TMPDIR");
    return tmp && *tmp ? tmp : "/tmp";
}

}  // namespace

void confineMpiLibraries() {
    addToList("HWLOC_PLUGINS_BLACKLIST", "hwloc_gl,hwloc_opencl");
    setenv("OMPI_MCA_shmem", "mmap", 0);
    // The session folders of --np runs killed before mpirun could remove them (SIGKILL).
    std::error_code ec;
    if (fs::is_directory(temporaryBase(), ec)) removeStaleTemporaries(temporaryBase(), kSessionStem);
}

std::optional<std::string> confineLaunchedJob() {
    const std::string base = temporaryBase();
    std::error_code ec;
    if (!fs::is_directory(base, ec))
        return "the temporary folder TMPDIR=" + base + " is not a folder" +
               (fs::exists(base, ec) ? "" : " (it does not exist)");
    if (::access(base.c_str(), W_OK | X_OK) != 0)
        return "cannot write in the temporary folder TMPDIR=" + base + ": " + std::strerror(errno);
    // mpirun creates the folder and removes it when the job ends; it has this process's pid.
    const std::string session = temporaryPathFor((fs::path(base) / kSessionStem).string());
    setenv("OMPI_MCA_orte_top_session_dir", session.c_str(), 0);
    setenv("OMPI_MCA_btl_vader_backing_directory", session.c_str(), 0);
    setenv("OMPI_MCA_osc_sm_backing_directory", session.c_str(), 0);
    setenv("OMPI_MCA_btl", "self,vader", 0);  // one machine: no TCP transport listening on every interface
    return std::nullopt;
}

}  // namespace ma::cli
