#pragma once
// mpirun started by `miniaster run --np K` runs as a child of the launcher, which stays its parent
// (docs/mpi.md): a stop signal sent to the launcher (a batch scheduler's SIGTERM, Ctrl-C) goes to
// the MPI processes themselves, which end the run as one process does (rank 0 writes the
// INTERRUPTED paragraph, or, when the run has already ended, completes it). mpirun is not
// signalled: OpenMPI 4.1's mpirun aborting a job whose processes are finishing crashes in
// PMIx_Finalize, and while it aborts it stops reading their output.
#include <vector>

namespace ma::cli {

// Runs `argv` (mpirun and its arguments, null-terminated), forwards the stop signals as above and
// returns the run's exit status: mpirun's 0, 1 or 2; 1 for any other end (said on stderr).
int runMpirun(std::vector<char*>& argv);

// A process of the job (under mpirun): SIGTERM when its mpirun ends first, so that a launcher or a
// mpirun killed with SIGKILL (which forwards nothing) leaves no process running on (the stop is
// handled as any SIGTERM: the INTERRUPTED paragraph). mpirun itself gets SIGKILL when the launcher
// that started it dies (runMpirun).
void stopWithMpirun();

}  // namespace ma::cli
