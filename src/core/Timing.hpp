#pragma once
// Clocks of the per-phase figures in the .mess: wall time since a start and the CPU time of the
// calling thread (a phase cost that does not depend on the machine's load), in seconds.
#include <chrono>
#include <ctime>

namespace ma {

inline double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

inline double threadCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

}  // namespace ma
