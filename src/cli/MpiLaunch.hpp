#pragma once
// `miniaster run --np K CASE` and `P mpi_nbcpu K` in the .export (the command line wins): the
// binary started by hand replaces itself by `mpirun -np K <itself> <the same arguments>`
// (docs/mpi.md). Under mpirun (or with one process) it is the run itself.
namespace ma::cli {

// Returns -1 when this process goes on with the run; otherwise it has become mpirun (no return),
// or mpirun could not be started: the exit status (1, message on stderr).
int launchProcessesIfAsked(int argc, char** argv);

}  // namespace ma::cli
