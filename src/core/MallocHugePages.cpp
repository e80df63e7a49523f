#include "core/MallocHugePages.hpp"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#include <unistd.h>

namespace ma {
namespace {

constexpr const char* kTunable = "glibc.malloc.hugetlb";
constexpr const char* kGuard = "MINIASTER_MALLOC_REEXEC";  // set for the re-executed process only

bool hugePagesAvailable() {
    std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string modes;
    std::getline(in, modes);
    return in && modes.find("[never]") == std::string::npos;
}

}  // namespace

void reexecWithMallocOnHugePages(char** argv) {
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    if (std::getenv(kGuard) || (tunables && std::strstr(tunables, kTunable)) || !hugePagesAvailable()) return;
    std::string value = std::string(kTunable) + "=1";
    if (tunables && *tunables) value = std::string(tunables) + ":" + value;
    if (setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0 || setenv(kGuard, "1", 1) != 0) return;
    execv("/proc/self/exe", argv);
    // execv failed (no /proc): go on without huge pages, as before.
    unsetenv(kGuard);
    if (tunables) setenv("GLIBC_TUNABLES", tunables, 1);
    else unsetenv("GLIBC_TUNABLES");
}

const char* mallocHugePagesState() {
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    if (tunables && std::strstr(tunables, "glibc.malloc.hugetlb=1")) return "glibc.malloc.hugetlb=1 (malloc on transparent huge pages)";
    if (tunables && std::strstr(tunables, kTunable)) return "GLIBC_TUNABLES sets glibc.malloc.hugetlb: kept as given";
    if (!hugePagesAvailable()) return "transparent huge pages off in the kernel: 4 KB pages";
    return "4 KB pages (re-execution with glibc.malloc.hugetlb=1 failed)";
}

}  // namespace ma
