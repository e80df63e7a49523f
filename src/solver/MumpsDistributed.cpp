#include "solver/MumpsDistributed.hpp"

#include <fmt/format.h>

#include <string>
#include <vector>

#include "core/Messages.hpp"
#include "core/Mpi.hpp"

namespace ma::mumps {

int communicator(const SolverOptions& options) {
    return options.distributed ? mpi::fortranWorld() : mpi::fortranSelf();
}

bool passes(const SolverOptions& options, int i, int j, double v) {
    return !options.distributed || v != 0.0 || (i == j && mpi::isRoot());
}

double totalEntries(const SolverOptions& options, MUMPS_INT8 local) {
    double n = double(local);
    if (options.distributed) mpi::sum(std::span<double>(&n, 1));
    return n;
}

void shareSolution(const SolverOptions& options, std::span<double> x) {
    if (options.distributed) mpi::broadcast(x);
}

void logProcesses(const SolverOptions& options, int largestMb, int totalMb, double peakMb) {
    if (!options.distributed) return;
    std::vector<double> peaks(size_t(mpi::size()), 0.0);
    peaks[size_t(mpi::rank())] = peakMb;
    mpi::sum(peaks);
    std::string list;
    for (double p : peaks) list += fmt::format(" {:.0f}", p);
    msg().infof(
        "    MUMPS on {} processes: {} MB on the largest (INFOG(21)), {} MB in all (INFOG(22)); resident peak "
        "per process (MB):{}",
        mpi::size(), largestMb, totalMb, list);
}

}  // namespace ma::mumps
