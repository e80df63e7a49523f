// MUMPS (Debian's parallel libdmumps_ptscotch on OpenMPI; libsmumps_ptscotch for the single-precision
// factors of MIXER_PRECISION='OUI'). Only src/solver sees the MUMPS headers; the communicator and the
// distributed input of a run on several processes are in solver/MumpsDistributed (docs/mpi.md).
#include <dmumps_c.h>
#include <fmt/format.h>
#include <malloc.h>
#include <smumps_c.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <thread>
#include <type_traits>
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

// The two arithmetics: double (the default) and single (MIXER_PRECISION='OUI': half the factors'
// memory and about twice the factorisation's speed, refined against the double matrix by
// ScaledDirectSolver).
struct DoubleArithmetic {
    using Struc = DMUMPS_STRUC_C;
    using Real = double;
    static void call(Struc& id) { dmumps_c(&id); }
};
struct SingleArithmetic {
    using Struc = SMUMPS_STRUC_C;
    using Real = float;
    static void call(Struc& id) { smumps_c(&id); }
};

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

// MemAvailable of /proc/meminfo in MB (0 when unreadable).
double availableMemoryMb() {
    std::ifstream in("/proc/meminfo");
    std::string key;
    double kb = 0.0;
    std::string unit;
    while (in >> key >> kb >> unit)
        if (key == "MemAvailable:") return kb / 1024.0;
    return 0.0;
}

// Where MUMPS writes its factors out of core: $TMPDIR, else /tmp.
std::string outOfCoreDirectory() {
    const char* dir = std::getenv("TMPDIR");
    return dir && *dir ? dir : "/tmp";
}

template <class Arithmetic>
class MumpsSolver : public ScaledDirectSolver {
    using Struc = typename Arithmetic::Struc;
    using Real = typename Arithmetic::Real;
    static constexpr bool kSingle = std::is_same_v<Real, float>;

public:
    explicit MumpsSolver(const SolverOptions& options) : ScaledDirectSolver(options) {}
    ~MumpsSolver() override { release(); }

    std::string name() const override { return kSingle ? "MUMPS (single-precision factors)" : "MUMPS"; }

protected:
    void factorizeScaled(const CsrMatrix& A, std::span<const double> s, MatrixKind kind,
                         std::span<const RowPoint> rowPoints) override {
        release();
        outOfCoreDir_.clear();
        const auto t0 = std::chrono::steady_clock::now();
        MemoryPhase phase;
        residentBeforeMb_ = phase.startMb();
        upperTriangle(A, s);
        initialise(kind);
        analyse(A, rowPoints);
        chooseMemoryMode();
        const double analysisPeak = phase.peakMb();
        // The ordering's graphs and METIS's work arrays were freed in the heap: give those pages
        // back before MUMPS allocates its factors, or they stay resident beside them.
        malloc_trim(0);
        MemoryPhase factorisation;
        factorise();
        logFactorisation(A, kind, secondsSince(t0), analysisPeak, factorisation);
        mumps::logProcesses(options_, id_.infog[20], id_.infog[21], std::max(analysisPeak, factorisation.peakMb()));
        // The factors are all the solve needs, unless MUMPS's error analysis (ICNTL(11)) reads A.
        if (!options_.conditionEstimate) {
            triplets_ = {};
            mumps::clearEntries(id_);
        }
    }

    void solveScaled(std::span<double> rhs) override {
        if constexpr (kSingle) {
            rhsReal_.resize(rhs.size());  // rounded to single: the refinement corrects it
            for (size_t i = 0; i < rhs.size(); ++i) rhsReal_[i] = static_cast<Real>(rhs[i]);
            id_.rhs = rhsReal_.data();
        } else {
            id_.rhs = rhs.data();
        }
        id_.nrhs = 1;
        id_.lrhs = id_.n;
        id_.icntl[10] = options_.conditionEstimate && !conditionLogged_ ? 1 : 0;
        id_.job = kJobSolve;
        Arithmetic::call(id_);
        if (id_.infog[0] < 0) throw NumericalError(mumpsErrorText(id_.infog[0], id_.infog[1]));
        if constexpr (kSingle) std::copy(rhsReal_.begin(), rhsReal_.end(), rhs.begin());
        mumps::shareSolution(options_, rhs);
        // Estimates are for the matrix MUMPS factorised: the diagonal-scaled one when scaling is on.
        if (options_.conditionEstimate && !conditionLogged_)
            msg().infof(
                "    MUMPS condition number estimates ({} matrix): cond1 = {:.3e}, cond2 = {:.3e}, backward errors "
                "{:.2e} {:.2e}",
                options_.diagonalScaling ? "scaled" : "unscaled", double(id_.rinfog[9]), double(id_.rinfog[10]),
                double(id_.rinfog[6]), double(id_.rinfog[7]));
        conditionLogged_ = conditionLogged_ || options_.conditionEstimate;
    }

private:
    // Upper triangle of S A S, 1-based coordinates, without the entries FILTRAGE_MATRICE leaves out.
    // Each row's entries from its diagonal on (columns are sorted), written at offsets counted
    // first, on the solver's threads: 0.9 s on one thread at 2e6 rows, most of it the first
    // touch of 0.3 GB of fresh pages.
    void upperTriangle(const CsrMatrix& A, std::span<const double> s) {
        triplets_ = {};
        auto diagonal = [&](int i) {
            return std::lower_bound(A.cols.begin() + A.rowStart[i], A.cols.begin() + A.rowStart[i + 1], i) -
                   A.cols.begin();
        };
        const std::vector<double> kept = filterDiagonal(A);
        const double f = options_.matrixFilter;
        auto passes = [&](int i, long long k) {
            const int j = A.cols[k];
            if (!kept.empty() && i != j && std::abs(A.values[k]) < f * (kept[size_t(i)] + kept[size_t(j)]))
                return false;
            return mumps::passes(options_, i, j, A.values[k]);
        };
        std::vector<long long> offset(size_t(A.rows) + 1, 0);
        inRowRanges(A.rows, [&](int begin, int end) {
            for (int i = begin; i < end; ++i)
                for (long long k = diagonal(i); k < A.rowStart[i + 1]; ++k) offset[i + 1] += passes(i, k);
        });
        for (int i = 0; i < A.rows; ++i) offset[i + 1] += offset[i];
        triplets_.size = size_t(offset.back());
        triplets_.irn.reset(new MUMPS_INT[triplets_.size]), triplets_.jcn.reset(new MUMPS_INT[triplets_.size]);
        triplets_.a.reset(new Real[triplets_.size]);
        inRowRanges(A.rows, [&](int begin, int end) {
            for (int i = begin; i < end; ++i)
                for (long long k = diagonal(i), at = offset[i]; k < A.rowStart[i + 1]; ++k)
                    if (passes(i, k)) {
                        triplets_.irn[at] = i + 1, triplets_.jcn[at] = A.cols[k] + 1;
                        triplets_.a[at++] = static_cast<Real>(s[i] * A.values[k] * s[A.cols[k]]);
                    }
        });
        if (!kept.empty()) {
            long long upper = 0;
            for (int i = 0; i < A.rows; ++i) upper += A.rowStart[i + 1] - diagonal(i);
            msg().infof(
                "    FILTRAGE_MATRICE={:g}: {} of the {} entries of the upper triangle factorised (|K_ij| < {:g} "
                "(|K_ii| + |K_jj|) left out; the refinement works against the whole matrix)",
                f, triplets_.size, upper, f);
        }
    }

    // |K_ii| of the assembled matrix (summed over the processes when distributed) when
    // FILTRAGE_MATRICE is on, else empty.
    std::vector<double> filterDiagonal(const CsrMatrix& A) const {
        if (!(options_.matrixFilter > 0.0)) return {};
        std::vector<double> d = options_.distributed ? summedDiagonal(A) : diagonalOf(A);
        for (double& v : d) v = std::abs(v);
        return d;
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
        id_ = Struc{};
        conditionLogged_ = false;
        id_.job = kJobInit;
        id_.par = 1;
        // SYM=1 (positive definite, no pivoting) performs no null-pivot detection: a floating body
        // goes through unnoticed (checked). SYM=2 detects it at a similar cost, so SYM=1 is used only
        // when the detection is off (NPREC < 0) or asked for (TYPE_RESOL='SYMDEF').
        const bool spd = kind == MatrixKind::SymmetricPositiveDefinite;
        id_.sym = spd && (options_.nprec < 0 || options_.typeResol == "SYMDEF") ? 1 : 2;
        id_.comm_fortran = mumps::communicator(options_);
        Arithmetic::call(id_);
        initialised_ = true;
        if (id_.infog[0] < 0) throw NumericalError(mumpsErrorText(id_.infog[0], id_.infog[1]));
        // Silence MUMPS's own printing; we log what matters.
        // Units 0, not -1: MUMPS's guarded messages test LP > 0 either way, but a few of its error
        // paths write to ICNTL(1) unguarded, and gfortran stops a process that writes to a negative
        // unit (seen on 4 processes: "Unit number is negative" in dfac_process_blocfacto_LDLT.F,
        // the others then waited for it forever). Unit 0 is stderr.
        id_.icntl[0] = 0, id_.icntl[1] = 0, id_.icntl[2] = 0, id_.icntl[3] = 0;
        id_.icntl[13] = options_.pcentPivot;
        // A positive definite matrix scaled to a unit diagonal has its largest entry of every row and
        // column there (|K_ij| <= sqrt(K_ii K_jj)): it is equilibrated, and MUMPS's own scaling
        // (ICNTL(8)=77 picks its iterative row and column scaling) only costs a pass per factorisation.
        if (options_.diagonalScaling && spd) id_.icntl[7] = 0;
        mumps::setInputFormat(id_, options_);
        // Symbolic factorisation from column counts (ICNTL(58)=2, MUMPS 5.5) rather than on the quotient
        // graph: the same flops and factor entries, and JOB=1 a third cheaper given PERM_IN (docs/solver.md).
        id_.icntl[57] = 2;
        refuseLowRank(options_);
        if (options_.acceleration == "FR+" || options_.acceleration == "FR++")
            msg().alarm(FACTOR_48, options_.acceleration);
        if (options_.nprec >= 0) {  // null pivot detection (code_aster's NPREC)
            id_.icntl[23] = 1;
            id_.cntl[2] = static_cast<Real>(std::pow(10.0, -options_.nprec));
        }
    }

    // JOB=1 with the ordering RENUM asks for (the nested dissections computed here and given as
    // PERM_IN).
    void analyse(const CsrMatrix& A, std::span<const RowPoint> rowPoints) {
        const auto t0 = std::chrono::steady_clock::now();
        const bool havePoints = rowPoints.size() == size_t(A.rows) && A.rows > 0;
        id_.icntl[6] = orderingCode(options_.renum, havePoints, ordering_);
        orderingNote_.clear();
        // On the host (rank 0) only, on the whole matrix's pattern (docs/mpi.md), when distributed.
        if (id_.icntl[6] == kUserOrdering)
            mpi::collectively([&] {
                // A MUMPS of one process (MPI_COMM_SELF: PETSc's LDLT_SP factors on each of several
                // processes) is its own host: every process orders its own matrix.
                if (options_.distributed && !mpi::isRoot()) return;
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
        const auto t1 = std::chrono::steady_clock::now();
        const double cpu0 = threadCpuSeconds();
        Arithmetic::call(id_);
        mumpsAnalysisCpu_ = threadCpuSeconds() - cpu0;
        mumpsAnalysisSeconds_ = secondsSince(t1);
        std::vector<MUMPS_INT>().swap(permIn_);
        id_.perm_in = nullptr;
        if (id_.infog[0] < 0) throw NumericalError(mumpsErrorText(id_.infog[0], id_.infog[1]));
        analysisSeconds_ = secondsSince(t0);
        predictedFlops_ = double(id_.rinfog[0]);
    }

    // JOB=2; on a workspace error the analysis is kept and only JOB=2 reruns with a larger
    // ICNTL(14): for a too small real workspace (-9) by what was missing relative to the
    // analysis' estimate of it (INFO(8)), otherwise doubled.
    void factorise() {
        const auto t0 = std::chrono::steady_clock::now();
        for (int attempt = 0;; ++attempt) {
            id_.job = kJobFactorise;
            Arithmetic::call(id_);
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
                throw SingularSystemError(fmt::format("singular system: {}{}. Likely cause: {}.",
                                                      mumpsErrorText(code, id_.infog[1]), singleNote(),
                                                      options_.singularHint));
            if (code < 0) throw NumericalError(mumpsErrorText(code, id_.infog[1]));
            break;
        }
        factorisationSeconds_ = secondsSince(t0);
        if (options_.nprec >= 0 && id_.infog[27] > 0)
            throw SingularSystemError(
                fmt::format("singular system: MUMPS found {} null pivot(s) (pivot below 1e-{} of the norm of the "
                            "diagonal-scaled matrix, "
                            "SOLVEUR/NPREC={}){}. Likely cause: {}.",
                            id_.infog[27], options_.nprec, options_.nprec, singleNote(), options_.singularHint));
    }

    std::string singleNote() const {
        return kSingle ? " in the single-precision factorisation of MIXER_PRECISION='OUI' (with 'NON' the double "
                         "factorisation may not be singular)"
                       : "";
    }

    // GESTION_MEMOIRE after the analysis: IN_CORE, OUT_OF_CORE (ICNTL(22)=1, the factors in files
    // under $TMPDIR), AUTO (in core unless MUMPS's in-core estimate INFOG(17) exceeds the memory
    // available now), EVAL (the estimates, then the command stops, as in code_aster).
    void chooseMemoryMode() {
        const std::string& mode = options_.memory;
        const double available = availableMemoryMb();
        const double inCore = id_.infog[16], outOfCore = id_.infog[26];
        bool ooc = mode == "OUT_OF_CORE";
        if (mode == "AUTO" && available > 0.0 && inCore > available) {
            ooc = true;
            msg().infof(
                "    GESTION_MEMOIRE='AUTO': MUMPS's in-core estimate {:.0f} MB exceeds the {:.0f} MB available: "
                "the factors go out of core",
                inCore, available);
        }
        if (mode == "EVAL" || ooc || mode == "IN_CORE")
            msg().infof(
                "    GESTION_MEMOIRE='{}': MUMPS estimates {:.0f} MB in core (INFOG(17)), {:.0f} MB out of core "
                "(INFOG(27)); {:.0f} MB available; the analysis predicts {:.3e} flops (RINFOG(1)), {:.4g} factor "
                "entries (INFOG(20))",
                mode, inCore, outOfCore, available, predictedFlops_, mumpsCount(id_.infog[19]));
        if (mode == "EVAL")
            throw UserError(fmt::format(
                "SOLVEUR/GESTION_MEMOIRE='EVAL': the memory estimates of MUMPS for this system of {} unknowns are in "
                "the .mess ({:.0f} MB in core, {:.0f} MB out of core); the command stops after them without "
                "factorising, as in code_aster (choose IN_CORE, OUT_OF_CORE or AUTO to compute)",
                id_.n, inCore, outOfCore));
        id_.icntl[21] = ooc ? 1 : 0;
        if (ooc) {
            const std::string dir = outOfCoreDirectory();
            const std::string prefix = fmt::format("miniaster_{}_", mpi::rank());
            std::snprintf(id_.ooc_tmpdir, sizeof id_.ooc_tmpdir, "%s", dir.c_str());
            std::snprintf(id_.ooc_prefix, sizeof id_.ooc_prefix, "%s", prefix.c_str());
            outOfCoreDir_ = dir;
        }
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
            "    MUMPS analysis {:.3f} s (JOB=1 {:.3f} s, cpu {:.3f} s): predicted flops {:.3e} (RINFOG(1)), factor "
            "entries {:.4g} (INFOG(20)), memory {} MB (INFOG(17))",
            analysisSeconds_, mumpsAnalysisSeconds_, mumpsAnalysisCpu_, predictedFlops_, mumpsCount(id_.infog[19]),
            id_.infog[16]);
        msg().infof(
            "    MUMPS factorisation {:.3f} s: {:.3e} flops (RINFOG(3), {:.1f} GFLOP/s), factor entries = {}, "
            "peak memory {} MB (INFOG(22)); analysis + factorisation {:.3f} s",
            factorisationSeconds_, double(id_.rinfog[2]),
            factorisationSeconds_ > 0 ? double(id_.rinfog[2]) / factorisationSeconds_ / 1e9 : 0.0,
            static_cast<long long>(mumpsCount(id_.infog[28])), id_.infog[21], total);
        if (!outOfCoreDir_.empty())
            msg().infof("    MUMPS out of core (ICNTL(22)=1): factors written under {}", outOfCoreDir_);
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
        Arithmetic::call(id_);
        initialised_ = false;
    }

    Struc id_{};
    std::vector<Real> rhsReal_;  // single precision: the right-hand side MUMPS solves in place
    std::string outOfCoreDir_;
    bool conditionLogged_ = false;  // once per factorisation (refinement steps solve again)
    bool initialised_ = false;
    std::string ordering_, orderingNote_;
    double entries_ = 0.0;  // given by all processes
    double mumpsAnalysisSeconds_ = 0.0, mumpsAnalysisCpu_ = 0.0;
    double analysisSeconds_ = 0.0, predictedFlops_ = 0.0, factorisationSeconds_ = 0.0, residentBeforeMb_ = 0.0;
    std::vector<MUMPS_INT> permIn_;
    // MUMPS's input: the upper triangle of S A S, 1-based (uninitialised storage, each entry
    // written once by upperTriangle).
    struct Triplets {
        std::unique_ptr<MUMPS_INT[]> irn, jcn;
        std::unique_ptr<Real[]> a;
        size_t size = 0;
    } triplets_;
};

}  // namespace

std::unique_ptr<ScaledDirectSolver> makeMumpsFactors(const SolverOptions& options) {
    if (options.mixedPrecision) return std::make_unique<MumpsSolver<SingleArithmetic>>(options);
    return std::make_unique<MumpsSolver<DoubleArithmetic>>(options);
}

std::unique_ptr<LinearSolver> makeMumpsSolver(const SolverOptions& options) {
    if (options.mixedPrecision) return std::make_unique<MumpsSolver<SingleArithmetic>>(options);
    return std::make_unique<MumpsSolver<DoubleArithmetic>>(options);
}

}  // namespace ma
