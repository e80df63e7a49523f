#include "core/MemoryLimit.hpp"

#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <utility>

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

double megabytes(std::size_t bytes) { return double(bytes) / (1024.0 * 1024.0); }

// The soft limit of the process's address space (ulimit -v) or data segment (ulimit -d), the
// smaller; 0 when neither is set. Allocations beyond it fail whatever the machine has.
struct ProcessLimit {
    std::size_t bytes = 0;
    const char* name = "";
};
ProcessLimit processLimit() {
    ProcessLimit smallest;
    for (const auto& [resource, name] : {std::pair{RLIMIT_AS, "virtual memory (ulimit -v, RLIMIT_AS)"},
                                         std::pair{RLIMIT_DATA, "data segment (ulimit -d, RLIMIT_DATA)"}}) {
        rlimit limit{};
        if (::getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) continue;
        if (smallest.bytes == 0 || limit.rlim_cur < smallest.bytes) smallest = {std::size_t(limit.rlim_cur), name};
    }
    return smallest;
}

// The limit that binds first, named: P memory_limit, the process's limit, the machine's memory.
std::string origin() {
    const ProcessLimit process = processLimit();
    const std::size_t available = availableMemoryBytes();
    if (gLimitBytes && (!process.bytes || gLimitBytes <= process.bytes))
        return fmt::format("the memory_limit of {:.0f} MB (P memory_limit in the .export)", megabytes(gLimitBytes));
    if (process.bytes && process.bytes < available)
        return fmt::format("the {:.0f} MB limit of the process's {} (the machine has {:.0f} MB available)",
                           megabytes(process.bytes), process.name, megabytes(available));
    return fmt::format("the {:.0f} MB of memory available on this machine", megabytes(available));
}
}  // namespace

void setMemoryLimit(double megabytes) {
    // A limit beyond what size_t counts is no limit (and converting it would be undefined).
    const double bytes = megabytes * 1024.0 * 1024.0;
    gLimitBytes = bytes < double(std::numeric_limits<std::size_t>::max()) ? std::size_t(bytes)
                                                                          : std::numeric_limits<std::size_t>::max();
}

std::size_t memoryLimitBytes() {
    const std::size_t process = processLimit().bytes;
    const std::size_t limit = gLimitBytes ? gLimitBytes : availableMemoryBytes();
    return process ? std::min(limit, process) : limit;
}

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
