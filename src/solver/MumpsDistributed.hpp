#pragma once
// Internal to src/solver: what MUMPS needs on several processes (docs/mpi.md), apart from the
// solver itself (MumpsSolver.cpp). A distributed matrix (SolverOptions::distributed) is the sum of
// the processes' parts: each holds the global pattern with its own cells' entries. MUMPS gets them
// as distributed triplets (ICNTL(18)=3, global 1-based indices, entries given by several processes
// summed); the right-hand side (the same on every process) and the solution are centralised on
// rank 0 (ICNTL(20)=0, ICNTL(21)=0) and the solution broadcast.
#include <dmumps_c.h>

#include <span>

#include "solver/LinearSolver.hpp"

namespace ma::mumps {

// MUMPS's communicator: all processes when distributed, else this process alone.
int communicator(const SolverOptions& options);
// After JOB=-1: the distributed input format.
void setInputFormat(DMUMPS_STRUC_C& id, const SolverOptions& options);
// Whether this process passes entry (i, j) of value v of its part: a distributed part passes its
// non-zeros only, and rank 0 also the diagonal entries of its pattern, zero or not.
bool passes(const SolverOptions& options, int i, int j, double v);
// The entries (1-based) as MUMPS's centralised or distributed input.
void setEntries(DMUMPS_STRUC_C& id, const SolverOptions& options, MUMPS_INT8 nnz, MUMPS_INT* irn, MUMPS_INT* jcn,
                double* a);
void clearEntries(DMUMPS_STRUC_C& id);
// Entries given to MUMPS by all processes.
double totalEntries(const SolverOptions& options, MUMPS_INT8 local);
// After JOB=3: the solution (on rank 0) to every process.
void shareSolution(const SolverOptions& options, std::span<double> x);

// After JOB=2, distributed: MUMPS's memory on its largest process and every process's resident
// peak (`peakMb`: this process's) in the .mess.
void logProcesses(const SolverOptions& options, const DMUMPS_STRUC_C& id, double peakMb);

}  // namespace ma::mumps
