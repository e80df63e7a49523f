#pragma once
// OpenBLAS's worker threads spin between calls: a Krylov iteration calls level-1 BLAS (PETSc's
// VecDot, VecAXPY, VecNorm) on vectors large enough for OpenBLAS to wake its pool each time, so the
// pool never sleeps through a solve and its spinning takes a core's cycles (39 % of the samples of
// a 3D CG + ML solve). A single-threaded section asks OpenBLAS for one thread and gives the count
// back after; the factorisations, whose BLAS 3 uses the pool, keep it. No-op when the BLAS in the
// process is not OpenBLAS (no openblas_set_num_threads to find).
#include <dlfcn.h>

namespace ma {

class OneBlasThread {
public:
    OneBlasThread() {
        set_ = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
        auto get = reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
        if (!set_ || !get) {
            set_ = nullptr;
            return;
        }
        previous_ = get();
        if (previous_ > 1) set_(1);
    }
    ~OneBlasThread() {
        if (set_ && previous_ > 1) set_(previous_);
    }
    OneBlasThread(const OneBlasThread&) = delete;
    OneBlasThread& operator=(const OneBlasThread&) = delete;

private:
    void (*set_)(int) = nullptr;
    int previous_ = 1;
};

}  // namespace ma
