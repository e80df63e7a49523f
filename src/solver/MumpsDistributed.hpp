#pragma once
// Internal to src/solver: what MUMPS needs on several processes (docs/mpi.md), apart from the
// solver itself (MumpsSolver.cpp). A distributed matrix (SolverOptions::distributed) is the sum of
// the processes' parts: each holds the global pattern with its own cells' entries. MUMPS gets them
// as distributed triplets (ICNTL(18)=3, global 1-based indices, entries given by several processes
// summed); the right-hand side (the same on every process) and the solution are centralised on
// rank 0 (ICNTL(20)=0, ICNTL(21)=0) and the solution broadcast.
#include <dmumps_c.h>
#include <smumps_c.h>

#include <span>

#include "solver/LinearSolver.hpp"

namespace ma::mumps {

// MUMPS's communicator: all processes when distributed, else this process alone.
int communicator(const SolverOptions& options);
// After JOB=-1: the distributed input format (Struc: DMUMPS_STRUC_C or SMUMPS_STRUC_C).
template <class Struc>
void setInputFormat(Struc& id, const SolverOptions& options) {
    id.icntl[4] = 0;                             // ICNTL(5): assembled
    id.icntl[17] = options.distributed ? 3 : 0;  // ICNTL(18): distributed triplets, or on the host
    id.icntl[19] = 0;                            // ICNTL(20): dense right-hand side on the host
    id.icntl[20] = 0;                            // ICNTL(21): solution on the host
}
// Whether this process passes entry (i, j) of value v of its part: a distributed part passes its
// non-zeros only, and rank 0 also the diagonal entries of its pattern, zero or not.
bool passes(const SolverOptions& options, int i, int j, double v);
// The entries (1-based) as MUMPS's centralised or distributed input.
template <class Struc, class Real>
void setEntries(Struc& id, const SolverOptions& options, MUMPS_INT8 nnz, MUMPS_INT* irn, MUMPS_INT* jcn, Real* a) {
    if (options.distributed) id.nnz_loc = nnz, id.irn_loc = irn, id.jcn_loc = jcn, id.a_loc = a;
    else id.nnz = nnz, id.irn = irn, id.jcn = jcn, id.a = a;
}
template <class Struc>
void clearEntries(Struc& id) {
    id.irn = id.jcn = id.irn_loc = id.jcn_loc = nullptr;
    id.a = id.a_loc = nullptr;
}
// Entries given to MUMPS by all processes.
double totalEntries(const SolverOptions& options, MUMPS_INT8 local);
// After JOB=3: the solution (on rank 0) to every process.
void shareSolution(const SolverOptions& options, std::span<double> x);

// After JOB=2, distributed: MUMPS's memory on its largest process (INFOG(21)) and in all
// (INFOG(22)) and every process's resident peak (`peakMb`: this process's) in the .mess.
void logProcesses(const SolverOptions& options, int largestMb, int totalMb, double peakMb);

}  // namespace ma::mumps
