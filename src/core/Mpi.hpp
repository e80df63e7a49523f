#pragma once
// The processes of a run (OpenMPI), for every layer without mpi.h (docs/mpi.md). A program
// started without mpirun is one process (an MPI "singleton"); with K processes every one runs the
// same command file on the replicated mesh, only rank 0 writes and prints, and the distributed
// parts (each process's own cells) meet in the sums below.
//
// Lock-step rule: every process calls the collective functions below in the same order. A region
// that computes on a process's own data and may fail there alone runs inside collectively(): the
// processes then agree, and all of them throw the error of the lowest failing rank (same type,
// same text), so that none is left waiting in the next collective.
#include <exception>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace ma::mpi {

// MPI_Init_thread (MPI_THREAD_FUNNELED: only the main thread calls MPI) unless done; started
// without mpirun, the singleton is told to start no helper daemon and to use the in-process
// transport (0.05 s instead of 0.4 s). MPI_Finalize at exit. Idempotent: the unit tests' MUMPS
// calls it lazily.
void initialise(int* argc = nullptr, char*** argv = nullptr);
void finalise();
// For a program's main(): an exit() before finalise() on one of several processes aborts the job
// (MPI_Abort) instead of leaving the others waiting for it.
void abortJobOnEarlyExit();
// Between MPI_Init and MPI_Finalize (objects released at exit check it before a collective call).
bool running();

int rank();
int size();
inline bool isRoot() { return rank() == 0; }
// True when started by mpirun (or another OpenMPI launcher), before MPI_Init.
bool launchedByMpirun();

// Element-wise sums and maxima over the processes, reduced on rank 0 in a fixed order and then
// broadcast: the same bits on every process, run after run.
void sum(std::span<double> values);
void sum(std::span<long double> values);
void max(std::span<double> values);
void broadcast(std::span<double> values);  // from rank 0
void broadcast(std::span<int> values);     // from rank 0
// Every process's `mine` laid end to end in rank order into `whole` on every process; counts[r] is
// process r's length (the same counts on every process, whole.size() their sum). NumericalError
// when a count or an offset exceeds MPI's int (the same on every process: they hold the same counts).
void gatherToAll(std::span<const double> mine, std::span<double> whole, std::span<const size_t> counts);

// The process ids of the other processes that run on this machine, by rank (0: another machine,
// or this process), learned at initialise().
const std::vector<int>& peersOnThisMachine();

// MPI_Comm_c2f(MPI_COMM_WORLD) / MPI_COMM_SELF, for MUMPS's comm_fortran.
int fortranWorld();
int fortranSelf();

// The error agreement: every process calls it at the same point with its own failure (empty:
// none). Returns the failure of the lowest failing rank on every process, or nothing.
struct Failure {
    int kind = 0;  // see Mpi.cpp: which exception type to rethrow
    std::string text;
    int rank = -1;  // the process it comes from (set by the agreement)
};
std::optional<Failure> agree(const std::optional<Failure>& local);

// The run's agreement (the supervisor's, before and after every command and at the end of the
// command file): the same, on a communicator of its own, so that a process that failed alone
// never meets a collective of the command the others are in. Once a failure is agreed, every
// later call returns it at once on every process (all of them learned it at the same call).
// A failing process waits at most `failureWaitSeconds` for the others; past it (they are blocked
// in a collective of the command, MUMPS's for instance), its failure goes to stderr and the job
// is aborted (MPI_Abort): never a silent hang.
std::optional<Failure> agreeOnRun(const std::optional<Failure>& local, double failureWaitSeconds = 60.0);
// Failure <-> exception of the engine's types (core/Error.hpp), std::bad_alloc and the others.
Failure failureOf(const std::exception_ptr& error);
[[noreturn]] void rethrow(const Failure& failure);

// Thrown by a collective below when another process failed alone and waits in agreeOnRun (it
// announced it): the command stops on this process too, and the supervisor joins that agreement,
// where it learns the failure. From then on every collective throws it at once.
struct OtherProcessFailed : std::runtime_error {
    OtherProcessFailed() : std::runtime_error("another MPI process failed") {}
};

// Runs f() on every process; when it threw on any of them, every process throws the error of the
// lowest failing rank (see above). One process: f() as is.
template <class F>
void collectively(F&& f) {
    if (size() == 1) {
        f();
        return;
    }
    std::optional<Failure> local;
    try {
        f();
    } catch (const OtherProcessFailed&) { throw; } catch (...) {
        local = failureOf(std::current_exception());
    }
    if (const auto agreed = agree(local)) rethrow(*agreed);
}

// Last resort (a process cannot reach the next agreement): ends every process of the job.
[[noreturn]] void abortAll(int status);

}  // namespace ma::mpi
