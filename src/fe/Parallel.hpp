#pragma once
// Threads for the element and pattern loops. Work is split into contiguous ranges in a fixed way and
// every floating-point sum keeps its serial order (see batchedElementLoop, fe/ElementLoop.hpp), so the
// results do not depend on the number of threads.
//
// Number of threads: OMP_NUM_THREADS when set (the variable OpenBLAS and code_aster's OpenMP parts
// read too), else the hardware's, at most 8.
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace ma {

int workerCount();
// Forces the number of threads (tests compare 1 and 2 threads); 0 restores the default.
void setWorkerCount(int n);

// Calls f(begin, end, worker) on `parts` contiguous ranges covering [0, n) (worker 0 on the calling
// thread). The first exception thrown by any range is rethrown after every range has finished.
template <class F>
void parallelRanges(size_t n, int parts, F&& f) {
    if (parts <= 1 || n < 2) {
        f(size_t(0), n, 0);
        return;
    }
    std::vector<std::exception_ptr> errors(parts);
    auto run = [&](int t) {
        try {
            f(n * t / parts, n * (t + 1) / parts, t);
        } catch (...) { errors[t] = std::current_exception(); }
    };
    {
        std::vector<std::jthread> threads;
        for (int t = 1; t < parts; ++t) threads.emplace_back(run, t);
        run(0);
    }
    for (auto& e : errors)
        if (e) std::rethrow_exception(e);
}

}  // namespace ma
