#pragma once
// What OpenMPI and hwloc may touch outside the run's outputs (README "Security", docs/mpi.md
// "What a run touches"): set in the environment before MPI_Init, so that every process of the job
// (and the mpirun the binary starts) reads it; a value the user gives is left as it is.
#include <optional>
#include <string>

namespace ma::cli {

// Every process, before MPI_Init:
// - hwloc without its display plugins (the GL plugin connects to the X servers :0..:9, on
//   127.0.0.1:6000-6009 and their sockets; the OpenCL one loads the vendors' drivers);
// - OpenMPI's shared-memory framework without its POSIX probe (a file in /dev/shm);
// - unless started by a mpirun (which has its own), OpenMPI's session folder (a one-process run's,
//   or that of the job the launcher starts: its contact file, PMIx's stores, the processes'
//   shared-memory segments) is $TMPDIR/miniaster-mpi.miniaster-tmp.<host>.<pid>, removed by
//   MPI_Finalize or by mpirun at its end; those of runs killed before (SIGKILL) are removed here.
// Returns the reason when TMPDIR cannot hold that folder (nothing is run).
std::optional<std::string> confineMpiLibraries();

// The launcher, before it becomes `mpirun`: the processes of one machine talk through shared
// memory only (no TCP transport listening on every interface).
void confineLaunchedJob();

}  // namespace ma::cli
