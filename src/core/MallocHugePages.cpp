#include "core/MallocHugePages.hpp"

#include <cstdlib>
#include <cstring>

namespace ma {

const char* mallocPagesState() {
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    if (tunables && std::strstr(tunables, "glibc.malloc.hugetlb=1"))
        return "glibc.malloc.hugetlb=1 from GLIBC_TUNABLES (malloc on transparent huge pages)";
    if (tunables && std::strstr(tunables, "glibc.malloc.hugetlb=2"))
        return "glibc.malloc.hugetlb=2 from GLIBC_TUNABLES (malloc on reserved huge pages)";
    return "4 KB pages (glibc's default)";
}

}  // namespace ma
