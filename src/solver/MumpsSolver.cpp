// MUMPS (Debian's parallel libdmumps_ptscotch on OpenMPI). Only src/solver sees dmumps_c.h; the
// communicator and the distributed input of a run on several processes are in
// solver/MumpsDistributed (docs/mpi.md).
#include <dmumps_c.h>
#include <fmt/format.h>
#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <thread>
#include <vector>

#include "core/Error.hpp"
#include "core/MemoryUsage.hpp"
#include "core/Messages.hpp"
#include "core/Mpi.hpp"
#include "core/Timing.hpp"
#include "solver/CoordinateOrdering.hpp"
#include "solver/LinearSolverImpl.hpp"
#include "solver/MetisOrdering.hpp"
#include "solver/MumpsDistributed.hpp"
#include "solver/SolverMessages.hpp"

namespace ma {

namespace {

constexpr int kJobInit = -1, kJobEnd = -2, kJobAnalyse = 1, kJobFactorise = 2, kJobSolve = 3;
constexpr int kUserOrdering = 1;  // ICNTL(7)=1: PERM_IN

// RENUM -> MUMPS's ICNTL(7), or kUserOrdering for the nested dissections miniaster computes
// itself: METIS (which Debian's MUMPS lacks, solver/MetisOrdering) and, for AUTO when every unknown
// has a point, coordinate bisection (solver/CoordinateOrdering): on the ssnv511 grids the cheapest
// factorisation of all, and the fastest to find (docs/study.md, "Orderings").
int orderingCode(const std::string& renum, bool havePoints, std::string& used) {
    if (renum == "AUTO" && havePoints) return used = "COORDINATES", kUserOrdering;
    if (renum == "AMD") return used = "AMD", 0;
    if (renum == "AMF") return used = "AMF", 2;
    if (renum == "SCOTCH") return used = "SCOTCH", 3;
    if (renum == "PORD") return used = "PORD", 4;
    if (renum == "QAMD") return used = "QAMD", 6;
    if (renum == "PARMETIS" || renum == "PTSCOTCH") {
        used = renum == "PARMETIS" ? "METIS" : "SCOTCH";
        msg().infof("    RENUM='{}': MUMPS's analysis runs on the host alone, ordered by the sequential counterpart {}",
                    renum, used);
        return used == "METIS" ? kUserOrdering : 3;
    }
    return used = "METIS", kUserOrdering;  // METIS, AUTO
}

// A(i): MUMPS's INFO/INFOG sizes are counts when positive, millions when negative.
double mumpsCount(int value) { return value < 0 ? -1e6 * value : double(value); }

// Block low-rank factors (SOLVEUR ACCELERATION='LR*') are refused: Debian's MUMPS 5.5.1 (seq)
// clusters the separators through SCOTCH_graphBuild with an out-of-bounds write (valgrind: "Invalid
// write of size 4" under dmumps_lr_grouping_new), and one run in three of a 1e4-dof BLR
// factorisation crashed. On the 2e6-dof ssnv511a grid they would take 0.36 GB (10 %) off the peak
// (docs/fe.md). AUTO and FR* are full rank.
void refuseLowRank(const SolverOptions& o) {
    if (o.acceleration.rfind("LR", 0) == 0)
        throw NotImplemented("SOLVEUR/ACCELERATION='" + o.acceleration +
                             "': block low-rank factors are not available: the MUMPS 5.5.1 of this system writes out "
                             "of bounds while clustering them (use ACCELERATION='AUTO' or 'FR')");
}

bool isWorkspaceError(int code) {
    return code == -8 || code == -9 || code == -14 || code == -15 || code == -17 || code == -20;
}

std::string mumpsErrorText(int code, int detail) {
    switch (code) {
        case -5:
        case -7:
        case -13:
        case -22:
            return fmt::format(
                "MUMPS could not allocate memory (INFOG(1)={}, INFOG(2)={}): the system is too "
                "large for the available memory",
                code, detail);
        case -6: return fmt::format("the matrix is structurally singular (INFOG(1)=-6, structural rank {})", detail);
        case -10: return "the matrix is numerically singular (INFOG(1)=-10)";
        case -16: return fmt::format("MUMPS: invalid system size N={} (INFOG(1)=-16)", detail);
        default: return fmt::format("MUMPS failed with INFOG(1)={}, INFOG(2)={}", code, detail);
    }
}

class MumpsSolver : public ScaledDirectSolver {
public:
    explicit MumpsSolver(const SolverOptions& options) : ScaledDirectSolver(options) {}
    ~MumpsSolver() override { release(); }

    std::string name() const override { return "MUMPS"; }

protected:
    void factorizeScaled(const CsrMatrix& A, std::span<const double> s, MatrixKind kind,
                         std::span<const RowPoint> rowPoints) override {
        release();
        const auto t0 = std::chrono::steady_clock::now();
        MemoryPhase phase;
        residentBeforeMb_ = phase.startMb();
        upperTriangle(A, s);
        initialise(kind);
        analyse(A, rowPoints);
        const double analysisPeak = phase.peakMb();
        // The ordering's graphs and METIS's work arrays were freed in the heap: give those pages
        // back before MUMPS allocates its factors, or they stay resident beside them.
        malloc_trim(0);
        MemoryPhase factorisation;
        factorise();
        logFactorisation(A, kind, secondsSince(t0), analysisPeak, factorisation);
        mumps::logProcesses(options_, id_, std::max(analysisPeak, factorisation.peakMb()));
        // The factors are all the solve needs, unless MUMPS's error analysis (ICNTL(11)) reads A.
        if (!options_.conditionEstimate) {
            triplets_ = {};
            mumps::clearEntries(id_);
        }
    }

    void solveScaled(std::span<double> rhs) override {
        id_.rhs = rhs.data();
        id_.nrhs = 1;
        id_.lrhs = id_.n;
        id_.icntl[10] = options_.conditionEstimate && !conditionLogged_ ? 1 : 0;
        id_.job = kJobSolve;
        dmumps_c(&id_);
        if (id_.infog[0] < 0) throw NumericalError(mumpsErrorText(id_.infog[0], id_.infog[1]));
        mumps::shareSolution(options_, rhs);
        // Estimates are for the matrix MUMPS factorised: the diagonal-scaled one when scaling is on.
        if (options_.conditionEstimate && !conditionLogged_)
            msg().infof(
                "    MUMPS condition number estimates ({} matrix): cond1 = {:.3e}, cond2 = {:.3e}, backward errors "
                "{:.2e} {:.2e}",
                options_.diagonalScaling ? "scaled" : "unscaled", id_.rinfog[9], id_.rinfog[10], id_.rinfog[6],
                id_.rinfog[7]);
        conditionLogged_ = conditionLogged_ || options_.conditionEstimate;
    }

private:
    // Upper triangle of S A S, 1-based coordinates.
    // Each row's entries from its diagonal on (columns are sorted), written at offsets counted
    // first, on the solver's threads: 0.9 s on one thread at 2e6 rows, most of it the first
    // touch of 0.3 GB of fresh pages.
    void upperTriangle(const CsrMatrix& A, std::span<const double> s) {
        triplets_ = {};
        auto diagonal = [&](int i) {
            return std::lower_bound(A.cols.begin() + A.rowStart[i], A.cols.begin() + A.rowStart[i + 1], i) -
                   A.cols.begin();
        };
        auto passes = [&](int i, long long k) { return mumps::passes(options_, i, A.cols[k], A.values[k]); };
        std::vector<long long> offset(size_t(A.rows) + 1, 0);
        inRowRanges(A.rows, [&](int begin, int end) {
            for (int i = begin; i < end; ++i)
                for (long long k = diagonal(i); k < A.rowStart[i + 1]; ++k) offset[i + 1] += passes(i, k);
        });
        for (int i = 0; i < A.rows; ++i) offset[i + 1] += offset[i];
        triplets_.size = size_t(offset.back());
        triplets_.irn.reset(new MUMPS_INT[triplets_.size]), triplets_.jcn.reset(new MUMPS_INT[triplets_.size]);
        triplets_.a.reset(new double[triplets_.size]);
        inRowRanges(A.rows, [&](int begin, int end) {
            for (int i = begin; i < end; ++i)
                for (long long k = diagonal(i), at = offset[i]; k < A.rowStart[i + 1]; ++k)
                    if (passes(i, k)) {
                        triplets_.irn[at] = i + 1, triplets_.jcn[at] = A.cols[k] + 1;
                        triplets_.a[at++] = s[i] * A.values[k] * s[A.cols[k]];
                    }
        });
    }

    // fn(begin, end) over `rows` split in options_.threads equal ranges, one per thread.
    template <class Fn>
    void inRowRanges(int rows, Fn&& fn) const {
        const int threads = std::clamp(options_.threads, 1, 16);
        std::vector<std::thread> workers;
        for (int t = 1; t < threads; ++t)
            workers.emplace_back([&, t] { fn(int(1LL * rows * t / threads), int(1LL * rows * (t + 1) / threads)); });
        fn(0, int(1LL * rows / threads));
        for (auto& w : workers) w.join();
    }

    void initialise(MatrixKind kind) {
        id_ = DMUMPS_STRUC_C{};
        conditionLogged_ = false;
        id_.job = kJobInit;
        id_.par = 1;
        // SYM=1 (positive definite, no pivoting) performs no null-pivot detection: a floating body
        // goes through unnoticed (checked). SYM=2 detects it at a similar cost, so SYM=1 is used only
        // when the detection is off (NPREC < 0) or asked for (TYPE_RESOL='SYMDEF').
        const bool spd = kind == MatrixKind::SymmetricPositiveDefinite;
        id_.sym = spd && (options_.nprec < 0 || options_.typeResol == "SYMDEF") ? 1 : 2;
        id_.comm_fortran = mumps::communicator(options_);
        dmumps_c(&id_);
        initialised_ = true;
        if (id_.infog[0] < 0) throw NumericalError(mumpsErrorText(id_.infog[0], id_.infog[1]));
        // Silence MUMPS's own printing; we log what matters.
        // Units 0, not -1: MUMPS's guarded messages test LP > 0 either way, but a few of its error
        // paths write to ICNTL(1) unguarded, and gfortran stops a process that writes to a negative
        // unit (seen on 4 processes: "Unit number is negative" in dfac_process_blocfacto_LDLT.F,
        // the others then waited for it forever). Unit 0 is stderr.
        id_.icntl[0] = 0, id_.icntl[1] = 0, id_.icntl[2] = 0, id_.icntl[3] = 0;
        id_.icntl[13] = options_.pcentPivot;
        mumps::setInputFormat(id_, options_);
        refuseLowRank(options_);
        if (options_.nprec >= 0) {  // null pivot detection (code_aster's NPREC)
            id_.icntl[23] = 1;
            id_.cntl[2] = std::pow(10.0, -options_.nprec);
        }
    }

    // JOB=1 with the ordering RENUM asks for (the nested dissections computed here and given as
    // PERM_IN).
    void analyse(const CsrMatrix& A, std::span<const RowPoint> rowPoints) {
        const auto t0 = std::chrono::steady_clock::now();
        const bool havePoints = rowPoints.size() == size_t(A.rows) && A.rows > 0;
        id_.icntl[6] = orderingCode(options_.renum, havePoints, ordering_);
        orderingNote_.clear();
        // On the host (rank 0) only, on the whole matrix's pattern (docs/mpi.md).
        if (id_.icntl[6] == kUserOrdering)
            mpi::collectively([&] {
                if (!mpi::isRoot()) return;
                const CsrMatrix whole = options_.wholePattern ? options_.wholePattern() : CsrMatrix{};
                const CsrMatrix& graph = options_.wholePattern ? whole : A;
                const bool byPoints = ordering_ == "COORDINATES";
                const FillReducingOrdering nd = byPoints
                                                    ? coordinateNestedDissection(graph, rowPoints, options_.threads)
                                                    : nestedDissectionOrdering(graph, options_.threads);
                permIn_.resize(nd.pivotRank.size());
                for (size_t i = 0; i < permIn_.size(); ++i) permIn_[i] = nd.pivotRank[i] + 1;
                id_.perm_in = permIn_.data();
                orderingNote_ = fmt::format("{} on the matrix graph ({} unknowns in {} vertices, {} edges) {:.3f} s",
                                            byPoints ? "nested dissection by coordinate bisection" : "METIS_NodeND",
                                            A.rows, nd.vertices, nd.graphEdges, nd.seconds);
            });
        id_.n = A.rows;
        const auto nnz = static_cast<MUMPS_INT8>(triplets_.size);
        mumps::setEntries(id_, options_, nnz, triplets_.irn.get(), triplets_.jcn.get(), triplets_.a.get());
        entries_ = mumps::totalEntries(options_, nnz);
        id_.job = kJobAnalyse;
        dmumps_c(&id_);
        std::vector<MUMPS_INT>().swap(permIn_);
        id_.perm_in = nullptr;
        if (id_.infog[0] < 0) throw NumericalError(mumpsErrorText(id_.infog[0], id_.infog[1]));
        analysisSeconds_ = secondsSince(t0);
        predictedFlops_ = id_.rinfog[0];
    }

    // JOB=2; on a workspace error the analysis is kept and only JOB=2 reruns with a larger
    // ICNTL(14): for a too small real workspace (-9) by what was missing relative to the
    // analysis' estimate of it (INFO(8)), otherwise doubled.
    void factorise() {
        const auto t0 = std::chrono::steady_clock::now();
        for (int attempt = 0;; ++attempt) {
            id_.job = kJobFactorise;
            dmumps_c(&id_);
            const int code = id_.infog[0];
            if (isWorkspaceError(code) && attempt < 4) {
                const int before = id_.icntl[13];
                const double estimate = mumpsCount(id_.info[7]), missing = mumpsCount(id_.info[1]);
                int relaxed = std::max(2 * before, 50);
                if (code == -9 && estimate > 0.0 && id_.info[1] != 0)
                    relaxed = std::max(
                        before + 20,
                        int(std::ceil(100.0 * ((1.0 + before / 100.0) * estimate + missing) / estimate - 100.0)) + 20);
                id_.icntl[13] = relaxed;
                msg().infof(
                    "    MUMPS workspace too small (INFOG(1)={}, INFO(2)={}): factorisation again (JOB=2, the "
                    "analysis kept) with ICNTL(14)={} instead of {}",
                    code, id_.info[1], relaxed, before);
                continue;
            }
            if (code == -10 || code == -6)
                throw SingularSystemError(fmt::format("singular system: {}. Likely cause: {}.",
                                                      mumpsErrorText(code, id_.infog[1]), options_.singularHint));
            if (code < 0) throw NumericalError(mumpsErrorText(code, id_.infog[1]));
            break;
        }
        factorisationSeconds_ = secondsSince(t0);
        if (options_.nprec >= 0 && id_.infog[27] > 0)
            throw SingularSystemError(
                fmt::format("singular system: MUMPS found {} null pivot(s) (pivot below 1e-{} of the norm of the "
                            "diagonal-scaled matrix, "
                            "SOLVEUR/NPREC={}). Likely cause: {}.",
                            id_.infog[27], options_.nprec, options_.nprec, options_.singularHint));
    }

    void logFactorisation(const CsrMatrix& A, MatrixKind kind, double total, double analysisPeakMb,
                          const MemoryPhase& factorisation) const {
        static const char* orderings[] = {"AMD", "PERM_IN", "AMF", "SCOTCH", "PORD", "METIS", "QAMD", "AUTO"};
        const int usedOrdering = id_.infog[6];
        msg().infof("    MUMPS ({}): n = {}, non-zeros (upper triangle) = {}{}, ordering {} (asked {}){}",
                    id_.sym == 1 ? "SYM=1, positive definite" : "SYM=2, general symmetric", A.rows, entries_,
                    options_.distributed
                        ? fmt::format(" in distributed triplets from {} processes (ICNTL(18)=3)", mpi::size())
                        : "",
                    usedOrdering == kUserOrdering            ? ordering_ + " (PERM_IN)"
                    : usedOrdering >= 0 && usedOrdering <= 7 ? orderings[usedOrdering]
                                                             : "?",
                    options_.renum, orderingNote_.empty() ? "" : ": " + orderingNote_);
        msg().infof(
            "    MUMPS analysis {:.3f} s: predicted flops {:.3e} (RINFOG(1)), factor entries {:.4g} (INFOG(20)), "
            "memory {} MB (INFOG(17))",
            analysisSeconds_, predictedFlops_, mumpsCount(id_.infog[19]), id_.infog[16]);
        msg().infof(
            "    MUMPS factorisation {:.3f} s: {:.3e} flops (RINFOG(3), {:.1f} GFLOP/s), factor entries = {}, "
            "peak memory {} MB (INFOG(22)); analysis + factorisation {:.3f} s",
            factorisationSeconds_, id_.rinfog[2],
            factorisationSeconds_ > 0 ? id_.rinfog[2] / factorisationSeconds_ / 1e9 : 0.0,
            static_cast<long long>(mumpsCount(id_.infog[28])), id_.infog[21], total);
        msg().infof(
            "    memory (resident, process): {:.0f} MB before the analysis, peak {:.0f} MB in the analysis, "
            "{:.0f} MB in the factorisation",
            residentBeforeMb_, analysisPeakMb, factorisation.peakMb());
        if (id_.sym == 2 && id_.infog[11] > 0) {
            if (kind == MatrixKind::SymmetricPositiveDefinite) msg().alarm(FACTOR_10, id_.infog[11]);
            else msg().infof("    MUMPS: {} negative pivots (expected: one per Lagrange multiplier)", id_.infog[11]);
        }
    }

    void release() {
        if (!initialised_ || !mpi::running()) return;  // (MPI already ended at exit: nothing to free)
        id_.job = kJobEnd;
        dmumps_c(&id_);
        initialised_ = false;
    }

    DMUMPS_STRUC_C id_{};
    bool conditionLogged_ = false;  // once per factorisation (refinement steps solve again)
    bool initialised_ = false;
    std::string ordering_, orderingNote_;
    double entries_ = 0.0;  // given by all processes
    double analysisSeconds_ = 0.0, predictedFlops_ = 0.0, factorisationSeconds_ = 0.0, residentBeforeMb_ = 0.0;
    std::vector<MUMPS_INT> permIn_;
    // MUMPS's input: the upper triangle of S A S, 1-based (uninitialised storage, each entry
    // written once by upperTriangle).
    struct Triplets {
        std::unique_ptr<MUMPS_INT[]> irn, jcn;
        std::unique_ptr<double[]> a;
        size_t size = 0;
    } triplets_;
};

}  // namespace

std::unique_ptr<LinearSolver> makeMumpsSolver(const SolverOptions& options) {
    return std::make_unique<MumpsSolver>(options);
}

}  // namespace ma
