#pragma once
// `miniaster run --np K CASE` and `P mpi_nbcpu K` in the .export (the command line wins): the
// binary started by hand runs `mpirun -np K <itself> <the same arguments>` as its child and stays
// its parent (cli/MpirunChild.hpp, docs/mpi.md). Under mpirun (or with one process) it is the run
// itself.
namespace ma::cli {

// Returns -1 when this process goes on with the run; otherwise the exit status of the run on K
// processes, or 1 (message on stderr) when K is more than the machine holds or mpirun cannot start.
int launchProcessesIfAsked(int argc, char** argv);

}  // namespace ma::cli
