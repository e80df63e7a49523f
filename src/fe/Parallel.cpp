#include "fe/Parallel.hpp"

#include <algorithm>
#include <atomic>
#include <cstdlib>

namespace ma {

namespace {
std::atomic<int> forced{0};
}

int workerCount() {
    if (const int n = forced.load()) return n;
    static const int count = [] {
        if (const char* env = std::getenv("OMP_NUM_THREADS")) {
            const int n = std::atoi(env);
            if (n >= 1) return std::min(n, 8);
        }
        return std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, 8);
    }();
    return count;
}

void setWorkerCount(int n) { forced.store(std::clamp(n, 0, 8)); }

}  // namespace ma
