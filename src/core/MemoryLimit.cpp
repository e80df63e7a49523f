#include "core/MemoryLimit.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <fstream>
#include <limits>

#include "core/Error.hpp"

namespace ma {

namespace {
std::size_t gLimitBytes = 0;  // 0: not set

// MemAvailable of /proc/meminfo: what can be allocated without swapping (physical memory when
// the kernel does not say).
std::size_t availableMemoryBytes() {
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    for (std::size_t kb = 0; meminfo >> key >> kb;) {
        if (key == "MemAvailable:") return kb * 1024;
        meminfo.ignore(64, '\n');
    }
    const long pages = ::sysconf(_SC_PHYS_PAGES), size = ::sysconf(_SC_PAGE_SIZE);
    return pages > 0 && size > 0 ? std::size_t(pages) * std::size_t(size) : std::size_t(-1);
}

std::string origin() {
    return gLimitBytes ? fmt::format("the memory_limit of {:.0f} MB (P memory_limit in the .export)",
                                     double(gLimitBytes) / (1024.0 * 1024.0))
                       : fmt::format("the {:.0f} MB of memory available on this machine",
                                     double(availableMemoryBytes()) / (1024.0 * 1024.0));
}
}  // namespace

void setMemoryLimit(double megabytes) {
    // A limit beyond what size_t counts is no limit (and converting it would be undefined).
    const double bytes = megabytes * 1024.0 * 1024.0;
    gLimitBytes = bytes < double(std::numeric_limits<std::size_t>::max()) ? std::size_t(bytes)
                                                                          : std::numeric_limits<std::size_t>::max();
}

std::size_t memoryLimitBytes() { return gLimitBytes ? gLimitBytes : availableMemoryBytes(); }

bool memoryLimitIsSet() { return gLimitBytes != 0; }

void checkAllocation(double bytes, const std::string& what) {
    if (bytes <= double(memoryLimitBytes())) return;
    throw UserError(
        fmt::format("{} needs {:.0f} MB of memory, more than {}", what, bytes / (1024.0 * 1024.0), origin()));
}

std::string outOfMemoryCause() {
    return fmt::format(
        "out of memory: the command needed more memory than {}; raise the limit or reduce the "
        "problem",
        origin());
}

}  // namespace ma
