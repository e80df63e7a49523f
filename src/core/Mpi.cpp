#include "core/Mpi.hpp"

#define OMPI_SKIP_MPICXX 1  // the C interface only
#include <mpi.h>

#include <sched.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"

namespace ma::mpi {

namespace {

enum Kind { kUser = 1, kNotImplemented, kNumerical, kInternal, kOutOfMemory, kOther, kSingular, kNonConvergence };

MPI_Comm gRunComm = MPI_COMM_NULL;   // the run's agreement (agreeOnRun)
std::optional<Failure> gRunFailure;  // agreed by it
constexpr int kNoticeTag = 29;       // "I failed, I wait in agreeOnRun" (one byte on gRunComm)
bool gNoticed = false;
std::vector<int> gPeers;

// Every process's id and machine, so that rank 0 can watch the ones beside it (parser/RunGuard).
void learnPeers() {
    char host[256] = {};
    ::gethostname(host, sizeof(host) - 1);
    const int mine[2] = {int(::getpid()), int(std::hash<std::string>()(host) & 0x7fffffff)};
    std::vector<int> all(2 * size_t(size()));
    MPI_Allgather(mine, 2, MPI_INT, all.data(), 2, MPI_INT, MPI_COMM_WORLD);
    gPeers.assign(size_t(size()), 0);
    for (int r = 0; r < size(); ++r)
        if (r != rank() && all[2 * r + 1] == mine[1]) gPeers[size_t(r)] = all[2 * r];
}

// Whether another process announced its failure (the notice is taken once, then remembered).
bool noticeArrived() {
    if (gNoticed) return true;
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kNoticeTag, gRunComm, &flag, &status);
    if (!flag) return false;
    char byte = 0;
    MPI_Recv(&byte, 1, MPI_CHAR, status.MPI_SOURCE, kNoticeTag, gRunComm, MPI_STATUS_IGNORE);
    gNoticed = true;
    return true;
}

// Waits for a collective's request; throws OtherProcessFailed when a failure is announced
// meanwhile (the failing process will never join: the request is left behind).
void complete(MPI_Request& request) {
    for (int done = 0;;) {
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        if (done) return;
        if (noticeArrived()) throw OtherProcessFailed();
        sched_yield();
    }
}

void announceFailure() {
    static const char byte = 1;
    for (int r = 0; r < size(); ++r) {
        if (r == rank()) continue;
        MPI_Request request;
        MPI_Isend(&byte, 1, MPI_CHAR, r, kNoticeTag, gRunComm, &request);
        MPI_Request_free(&request);
    }
}

}  // namespace

bool running() {
    int started = 0, ended = 0;
    MPI_Initialized(&started);
    MPI_Finalized(&ended);
    return started && !ended;
}

namespace {

template <class T>
void reduceThenBroadcast(std::span<T> values, MPI_Datatype type, MPI_Op op) {
    if (size() == 1 || values.empty()) return;
    if (gNoticed) throw OtherProcessFailed();
    void* data = values.data();
    const int n = static_cast<int>(values.size());
    MPI_Request request;
    if (rank() == 0) MPI_Ireduce(MPI_IN_PLACE, data, n, type, op, 0, MPI_COMM_WORLD, &request);
    else MPI_Ireduce(data, nullptr, n, type, op, 0, MPI_COMM_WORLD, &request);
    complete(request);
    MPI_Ibcast(data, n, type, 0, MPI_COMM_WORLD, &request);
    complete(request);
}

}  // namespace

bool launchedByMpirun() {
    return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK") || std::getenv("PMI_RANK");
}

void initialise(int* argc, char*** argv) {
    int started = 0;
    MPI_Initialized(&started);
    if (started) return;
    if (!launchedByMpirun()) {  // a singleton: no orted, no network transports to probe
        setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
        setenv("OMPI_MCA_pml", "ob1", 0);
        setenv("OMPI_MCA_btl", "self", 0);
        // Singletons of one user otherwise share OpenMPI's default session folder
        // (/tmp/ompi.<host>.<uid>/jf.0), which one process's MPI_Finalize removes while another's
        // MPI_Init creates it (parallel unit tests). A folder per process, named as the run's own
        // (src/cli/MpiConfinement, which sets it first) so that a killed process's is cleaned up.
        const char* tmp = std::getenv("TMPDIR");
        const std::string session = temporaryPathFor(std::string(tmp && *tmp ? tmp : "/tmp") + "/miniaster-mpi");
        setenv("OMPI_MCA_orte_top_session_dir", session.c_str(), 0);
    }
    int provided = 0;
    if (MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
        throw std::runtime_error("MPI_Init_thread failed");
    MPI_Comm_dup(MPI_COMM_WORLD, &gRunComm);
    learnPeers();
    std::atexit(finalise);
}

void abortJobOnEarlyExit() {
    // Reached with MPI still running only when a library ends the process with exit() before
    // main() finalises (gfortran's runtime errors inside MUMPS do): on several processes the
    // others would wait for this one in their next collective, and MPI_Finalize here for them,
    // forever. MPI_Abort has mpirun end them all, with exit status 1. Registered after
    // initialise(), so it runs before finalise()'s own handler.
    std::atexit([] {
        if (running() && size() > 1) MPI_Abort(MPI_COMM_WORLD, 1);
    });
}

void finalise() {
    if (running()) MPI_Finalize();
}

int rank() {
    static int r = -1;
    if (r < 0) {
        initialise();
        MPI_Comm_rank(MPI_COMM_WORLD, &r);
    }
    return r;
}

int size() {
    static int s = 0;
    if (s == 0) {
        initialise();
        MPI_Comm_size(MPI_COMM_WORLD, &s);
    }
    return s;
}

void sum(std::span<double> values) { reduceThenBroadcast(values, MPI_DOUBLE, MPI_SUM); }
void sum(std::span<long double> values) { reduceThenBroadcast(values, MPI_LONG_DOUBLE, MPI_SUM); }
void max(std::span<double> values) { reduceThenBroadcast(values, MPI_DOUBLE, MPI_MAX); }

namespace {

void broadcastFromRoot(void* data, size_t n, MPI_Datatype type) {
    if (size() == 1 || n == 0) return;
    if (gNoticed) throw OtherProcessFailed();
    MPI_Request request;
    MPI_Ibcast(data, static_cast<int>(n), type, 0, MPI_COMM_WORLD, &request);
    complete(request);
}

}  // namespace

void broadcast(std::span<double> values) { broadcastFromRoot(values.data(), values.size(), MPI_DOUBLE); }
void broadcast(std::span<int> values) { broadcastFromRoot(values.data(), values.size(), MPI_INT); }

void gatherToAll(std::span<const double> mine, std::span<double> whole, std::span<const size_t> counts) {
    if (size() == 1) {
        std::copy(mine.begin(), mine.end(), whole.begin());
        return;
    }
    std::vector<int> lengths, offsets;
    size_t offset = 0;
    for (size_t count : counts) {
        if (count > size_t(INT_MAX) || offset > size_t(INT_MAX))
            throw NumericalError(fmt::format("gathering {} values from {} processes exceeds MPI's int counts",
                                             whole.size(), counts.size()));
        lengths.push_back(int(count)), offsets.push_back(int(offset));
        offset += count;
    }
    if (gNoticed) throw OtherProcessFailed();
    MPI_Request request;
    MPI_Iallgatherv(mine.data(), int(mine.size()), MPI_DOUBLE, whole.data(), lengths.data(), offsets.data(), MPI_DOUBLE,
                    MPI_COMM_WORLD, &request);
    complete(request);
}

const std::vector<int>& peersOnThisMachine() { return gPeers; }

int fortranWorld() {
    initialise();
    return static_cast<int>(MPI_Comm_c2f(MPI_COMM_WORLD));
}

int fortranSelf() {
    initialise();
    return static_cast<int>(MPI_Comm_c2f(MPI_COMM_SELF));
}

namespace {

// The lowest failing rank's failure, broadcast from it (every process knows `first`).
Failure broadcastFailure(const std::optional<Failure>& local, int first, MPI_Comm comm) {
    Failure agreed = rank() == first ? *local : Failure{};
    int header[2] = {agreed.kind, static_cast<int>(agreed.text.size())};
    MPI_Bcast(header, 2, MPI_INT, first, comm);
    agreed.kind = header[0];
    agreed.text.resize(static_cast<size_t>(header[1]));
    MPI_Bcast(agreed.text.data(), header[1], MPI_CHAR, first, comm);
    agreed.rank = first;
    return agreed;
}

// Waits for `request`, at most `seconds` (polling, a yield between tries); false past it.
bool waitAtMost(MPI_Request& request, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    for (int done = 0;;) {
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        if (done) return true;
        if (std::chrono::steady_clock::now() > end) return false;
        sched_yield();
    }
}

}  // namespace

std::optional<Failure> agree(const std::optional<Failure>& local) {
    if (size() == 1) return local;
    if (gNoticed) throw OtherProcessFailed();
    int mine = local ? rank() : size(), first = size();
    MPI_Request request;
    MPI_Iallreduce(&mine, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD, &request);
    complete(request);
    if (first == size()) return std::nullopt;
    return broadcastFailure(local, first, MPI_COMM_WORLD);
}

std::optional<Failure> agreeOnRun(const std::optional<Failure>& local, double failureWaitSeconds) {
    if (size() == 1) return local;
    if (gRunFailure) return gRunFailure;
    int mine = local ? rank() : size(), first = size();
    MPI_Request request;
    if (local) announceFailure();
    MPI_Iallreduce(&mine, &first, 1, MPI_INT, MPI_MIN, gRunComm, &request);
    if (!local) {
        MPI_Wait(&request, MPI_STATUS_IGNORE);
    } else if (!waitAtMost(request, failureWaitSeconds)) {
        std::fprintf(stderr,
                     "miniaster: MPI process %d of %d: %s\nminiaster: MPI process %d of %d: the other processes did "
                     "not reach the agreement on this failure within %g s (they wait inside a collective operation "
                     "of the command); the job is aborted\n",
                     rank(), size(), local->text.c_str(), rank(), size(), failureWaitSeconds);
        std::fflush(stderr);
        abortAll(1);
    }
    if (first == size()) return std::nullopt;
    gRunFailure = broadcastFailure(local, first, gRunComm);
    return gRunFailure;
}

Failure failureOf(const std::exception_ptr& error) {
    try {
        std::rethrow_exception(error);
    } catch (const UserError& e) { return {kUser, e.what()}; } catch (const NotImplemented& e) {
        return {kNotImplemented, e.what()};
    } catch (const SingularSystemError& e) { return {kSingular, e.what()}; } catch (const NonConvergenceError& e) {
        return {kNonConvergence, e.what()};
    } catch (const NumericalError& e) { return {kNumerical, e.what()}; } catch (const InternalError& e) {
        return {kInternal, e.what()};
    } catch (const std::bad_alloc&) { return {kOutOfMemory, ""}; } catch (const std::exception& e) {
        return {kOther, e.what()};
    } catch (...) { return {kOther, "unexpected error of unknown type"}; }
}

void rethrow(const Failure& f) {
    switch (f.kind) {
        case kUser: throw UserError(f.text);
        case kNotImplemented: throw NotImplemented(f.text);
        case kNumerical: throw NumericalError(f.text);
        case kSingular: throw SingularSystemError(f.text);
        case kNonConvergence: throw NonConvergenceError(f.text);
        case kInternal: throw InternalError(f.text);
        case kOutOfMemory: throw std::bad_alloc();
        default: throw std::runtime_error(f.text);
    }
}

void abortAll(int status) {
    if (running()) MPI_Abort(MPI_COMM_WORLD, status);
    std::_Exit(status);
}

}  // namespace ma::mpi
