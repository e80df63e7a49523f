#pragma once
// What OpenMPI and hwloc may touch outside the run's outputs (README "Security", docs/mpi.md
// "What a run touches"): set in the environment before MPI_Init, so that every process of the job
// (and the mpirun the binary starts) reads it; a value the user gives is left as it is.
#include <optional>
#include <string>

namespace ma::cli {

// Every process, before MPI_Init: hwloc without its display plugins (the GL plugin connects to
// the X servers :0..:9, on 127.0.0.1:6000-6009 and their sockets; OpenCL loads vendor drivers),
// and OpenMPI's shared-memory framework without its POSIX probe (a file in /dev/shm). The
// session folders of killed --np runs (below) are removed here.
void confineMpiLibraries();

// The launcher, before it becomes `mpirun`: OpenMPI's session folder (its contact file, PMIx's
// stores, the shared-memory segments of the processes) in one folder of the run,
// $TMPDIR/miniaster-mpi.miniaster-tmp.<host>.<pid>, which mpirun removes at its end; the
// processes talk through shared memory only.
// Returns the reason when TMPDIR cannot hold that folder.
std::optional<std::string> confineLaunchedJob();

}  // namespace ma::cli
