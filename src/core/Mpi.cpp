#include "core/Mpi.hpp"

#define OMPI_SKIP_MPICXX 1  // the C interface only
#include <mpi.h>

#include <cstdlib>
#include <new>
#include <stdexcept>
#include <vector>

#include "core/Error.hpp"

namespace ma::mpi {

namespace {

enum Kind { kUser = 1, kNotImplemented, kNumerical, kInternal, kOutOfMemory, kOther, kSingular, kNonConvergence };

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
    void* data = values.data();
    const int n = static_cast<int>(values.size());
    if (rank() == 0) MPI_Reduce(MPI_IN_PLACE, data, n, type, op, 0, MPI_COMM_WORLD);
    else MPI_Reduce(data, nullptr, n, type, op, 0, MPI_COMM_WORLD);
    MPI_Bcast(data, n, type, 0, MPI_COMM_WORLD);
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
    }
    int provided = 0;
    if (MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
        throw std::runtime_error("MPI_Init_thread failed");
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

void broadcast(std::span<double> values) {
    if (size() > 1 && !values.empty())
        MPI_Bcast(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
}

void broadcast(std::span<int> values) {
    if (size() > 1 && !values.empty())
        MPI_Bcast(values.data(), static_cast<int>(values.size()), MPI_INT, 0, MPI_COMM_WORLD);
}

int fortranWorld() {
    initialise();
    return static_cast<int>(MPI_Comm_c2f(MPI_COMM_WORLD));
}

int fortranSelf() {
    initialise();
    return static_cast<int>(MPI_Comm_c2f(MPI_COMM_SELF));
}

std::optional<Failure> agree(const std::optional<Failure>& local) {
    if (size() == 1) return local;
    int mine = local ? rank() : size(), first = size();
    MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (first == size()) return std::nullopt;
    Failure agreed = rank() == first ? *local : Failure{};
    int header[2] = {agreed.kind, static_cast<int>(agreed.text.size())};
    MPI_Bcast(header, 2, MPI_INT, first, MPI_COMM_WORLD);
    agreed.kind = header[0];
    agreed.text.resize(static_cast<size_t>(header[1]));
    MPI_Bcast(agreed.text.data(), header[1], MPI_CHAR, first, MPI_COMM_WORLD);
    return agreed;
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
