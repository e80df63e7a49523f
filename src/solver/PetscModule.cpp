// SOLVEUR METHODE='PETSC' / 'GCPC' live in a module (libminiaster_petsc.so, built beside the program
// from PetscSolver.cpp and KrylovSettings.cpp), loaded at the first solver that asks for it: a run
// that does not use PETSc does not load its libraries (15 MB resident, docs/solver.md).
#include <dlfcn.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "solver/LinearSolverImpl.hpp"

namespace ma {

namespace {

using Factory = LinearSolver* (*)(const SolverOptions&);

// Beside the executable first (the program in build/), then where the build put it (the test
// programs in build/tests).
std::vector<std::string> moduleCandidates() {
    std::vector<std::string> paths;
    std::error_code error;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    const std::string name = std::filesystem::path(MINIASTER_PETSC_MODULE).filename().string();
    if (!error) paths.push_back((self.parent_path() / name).string());
    paths.emplace_back(MINIASTER_PETSC_MODULE);
    return paths;
}

Factory loadFactory() {
    std::string reasons;
    for (const std::string& path : moduleCandidates()) {
        if (access(path.c_str(), R_OK) != 0) continue;
        void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            reasons += std::string(reasons.empty() ? "" : "; ") + dlerror();
            continue;
        }
        if (void* symbol = dlsym(handle, "miniaster_make_petsc_solver")) return reinterpret_cast<Factory>(symbol);
        reasons += "; " + path + " has no entry point miniaster_make_petsc_solver";
    }
    throw NotImplemented("SOLVEUR/METHODE='PETSC' and 'GCPC' need miniaster's PETSc module " +
                         std::filesystem::path(MINIASTER_PETSC_MODULE).filename().string() + ", which " +
                         (reasons.empty()
                              ? "is neither beside the program nor in " + std::string(MINIASTER_PETSC_MODULE)
                              : "could not be loaded: " + reasons) +
                         " (./miniaster build builds it)");
}

}  // namespace

std::unique_ptr<LinearSolver> makePetscSolver(const SolverOptions& options) {
    static const Factory factory = loadFactory();
    return std::unique_ptr<LinearSolver>(factory(options));
}

}  // namespace ma
