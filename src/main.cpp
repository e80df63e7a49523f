// miniaster: runs code_aster command files (.comm / .export); converts and plots results. See README.md.
#include <malloc.h>

#include <cstdio>
#include <exception>
#include <string>

#include "MiniasterCommit.hpp"
#include "cli/MpiConfinement.hpp"
#include "cli/MpiLaunch.hpp"
#include "cli/MpirunChild.hpp"
#include "cli/ResultTools.hpp"
#include "core/Mpi.hpp"
#include "med_io/MedLibrary.hpp"
#include "parser/RunGuard.hpp"
#include "parser/Supervisor.hpp"

namespace {

// glibc's heap gives a freed block of more than M_MMAP_THRESHOLD back to the system at once, and
// the free top of the heap beyond M_TRIM_THRESHOLD; both start at 128 kB and rise only when some
// large block happens to be freed. Left there, vectors of a few MB come in new zeroed pages at each
// allocation (1.7-1.9 us of system time a page here): refined ssnv511a N = 501 took 313 600 page
// faults, 277 000 with these values (docs/solver.md, "Heap"). 32 MB is glibc's own ceiling for the
// first; what a command frees is still returned when it ends (malloc_trim, the supervisor), since
// P memory_limit watches resident memory.
void configureHeap() {
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
}

}  // namespace

int main(int argc, char** argv) {
    const std::string command = argc >= 2 ? argv[1] : "";
    configureHeap();
    if (command == "--version") {
        std::printf("miniaster %s (%s)\n", MINIASTER_VERSION, MINIASTER_COMMIT);
        return 0;
    }
    if (command == "convert") return ma::cli::convertMain(argc, argv);
    if (command == "plot") return ma::cli::plotMain(argc, argv);
    if (command == "--help" || command == "-h")
        std::fputs(
            "usage: miniaster convert RESULT.rmed OUT.vtu    (every field and step, for ParaView)\n"
            "       miniaster plot RESULT.rmed [--field NAME] [--component C] [--deformed SCALE] -o OUT.png\n"
            "       miniaster --version\n",
            stdout);
    if (const auto refused = ma::cli::confineMpiLibraries()) {
        std::fprintf(stderr, "miniaster: %s; nothing was run\n", refused->c_str());
        return 1;
    }
    if (command == "run")
        if (const int status = ma::cli::launchProcessesIfAsked(argc, argv); status >= 0) return status;
    if (command == "run") ma::armStopSignals();  // a stop during MPI_Init is handled once the run starts
    if (command == "run" && ma::mpi::launchedByMpirun()) ma::cli::stopWithMpirun();
    ma::med::initialiseBeforeMpi();
    try {
        ma::mpi::initialise(&argc, &argv);
        ma::mpi::abortJobOnEarlyExit();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "miniaster: %s (OpenMPI)\n", e.what());
        return 1;
    }
    const int status = ma::supervisorMain(argc, argv);
    const bool root = ma::mpi::isRoot();
    ma::mpi::finalise();
    // The run's status is rank 0's (every process agreed on the failures): mpirun returns it. A
    // non-zero status of another process would make mpirun abort the job while rank 0 finishes.
    return root ? status : 0;
}
