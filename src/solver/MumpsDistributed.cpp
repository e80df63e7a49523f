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

void setInputFormat(DMUMPS_STRUC_C& id, const SolverOptions& options) {
    id.icntl[4] = 0;                             // ICNTL(5): assembled
    id.icntl[17] = options.distributed ? 3 : 0;  // ICNTL(18): distributed triplets, or on the host
    id.icntl[19] = 0;                            // ICNTL(20): dense right-hand side on the host
    id.icntl[20] = 0;                            // ICNTL(21): solution on the host
}

bool passes(const SolverOptions& options, int i, int j, double v) {
    return !options.distributed || v != 0.0 || (i == j && mpi::isRoot());
}

void setEntries(DMUMPS_STRUC_C& id, const SolverOptions& options, MUMPS_INT8 nnz, MUMPS_INT* irn, MUMPS_INT* jcn,
                double* a) {
    if (options.distributed) id.nnz_loc = nnz, id.irn_loc = irn, id.jcn_loc = jcn, id.a_loc = a;
    else id.nnz = nnz, id.irn = irn, id.jcn = jcn, id.a = a;
}

void clearEntries(DMUMPS_STRUC_C& id) {
    id.irn = id.jcn = id.irn_loc = id.jcn_loc = nullptr;
    id.a = id.a_loc = nullptr;
}

double totalEntries(const SolverOptions& options, MUMPS_INT8 local) {
    double n = double(local);
    if (options.distributed) mpi::sum(std::span<double>(&n, 1));
    return n;
}

void shareSolution(const SolverOptions& options, std::span<double> x) {
    if (options.distributed) mpi::broadcast(x);
}

void logProcesses(const SolverOptions& options, const DMUMPS_STRUC_C& id, double peakMb) {
    if (!options.distributed) return;
    std::vector<double> peaks(size_t(mpi::size()), 0.0);
    peaks[size_t(mpi::rank())] = peakMb;
    mpi::sum(peaks);
    std::string list;
    for (double p : peaks) list += fmt::format(" {:.0f}", p);
    msg().infof(
        "    MUMPS on {} processes: {} MB on the largest (INFOG(21)), {} MB in all (INFOG(22)); resident peak "
        "per process (MB):{}",
        mpi::size(), id.infog[20], id.infog[21], list);
}

}  // namespace ma::mumps
