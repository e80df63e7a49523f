#include "fe/ElementLoop.hpp"

#include <ctime>

#include "fe/Parallel.hpp"

namespace ma {

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double threadCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

int elementWorkers(size_t nElements) {
    return static_cast<int>(std::min<size_t>(workerCount(), std::max<size_t>(1, nElements / kElementBatch)));
}

}  // namespace ma
