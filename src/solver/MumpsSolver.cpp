// Sequential MUMPS (libdmumps_seq). Only this file sees dmumps_c.h and MUMPS's fake mpi.h
// (/usr/include/mumps_seq): MED code includes OpenMPI's mpi.h, and the two never meet in one
// translation unit. MUMPS seq needs no MPI_Init; its Fortran MPI stubs (mpi_*_) come from
// libmpiseq and do not clash with OpenMPI's C symbols (verified by test solver_med_mumps).
#include <dmumps_c.h>
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <vector>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "solver/LinearSolverImpl.hpp"

namespace ma {

namespace {

constexpr int kJobInit = -1, kJobEnd = -2, kJobAnalyseFactorise = 4, kJobSolve = 3;
constexpr int kUseCommWorld = -987654;

double seconds(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int orderingCode(const std::string& renum, std::string& used) {
    if (renum == "AMD") return used = "AMD", 0;
    if (renum == "AMF") return used = "AMF", 2;
    if (renum == "SCOTCH") return used = "SCOTCH", 3;
    if (renum == "PORD") return used = "PORD", 4;
    if (renum == "QAMD") return used = "QAMD", 6;
    if (renum == "METIS" || renum == "PARMETIS" || renum == "PTSCOTCH") {
        msg().infof("    RENUM='{}' is not available in this MUMPS build (Debian seq: AMD, AMF, QAMD, PORD, "
                    "SCOTCH): SCOTCH is used",
                    renum);
        return used = "SCOTCH", 3;
    }
    return used = "AUTO", 7;
}

std::string mumpsErrorText(int code, int detail) {
    switch (code) {
        case -5:
        case -7:
        case -13:
        case -22:
            return fmt::format("MUMPS could not allocate memory (INFOG(1)={}, INFOG(2)={}): the system is too "
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
    void factorizeScaled(const CsrMatrix& A, std::span<const double> s, MatrixKind kind) override {
        release();
        const auto t0 = std::chrono::steady_clock::now();
        // Upper triangle of S A S, 1-based coordinates.
        irn_.clear(), jcn_.clear(), a_.clear();
        irn_.reserve(A.nonZeros() / 2 + A.rows), jcn_.reserve(A.nonZeros() / 2 + A.rows), a_.reserve(A.nonZeros() / 2 + A.rows);
        for (int i = 0; i < A.rows; ++i)
            for (long long k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k)
                if (A.cols[k] >= i) {
                    irn_.push_back(i + 1);
                    jcn_.push_back(A.cols[k] + 1);
                    a_.push_back(s[i] * A.values[k] * s[A.cols[k]]);
                }
        id_ = DMUMPS_STRUC_C{};
        conditionLogged_ = false;
        id_.job = kJobInit;
        id_.par = 1;
        // SYM=1 (positive definite, no pivoting) performs no null-pivot detection: a floating body
        // goes through unnoticed (checked). SYM=2 detects it at a similar cost, so SYM=1 is used only
        // when the detection is off (NPREC < 0) or asked for (TYPE_RESOL='SYMDEF').
        const bool spd = kind == MatrixKind::SymmetricPositiveDefinite;
        id_.sym = spd && (options_.nprec < 0 || options_.typeResol == "SYMDEF") ? 1 : 2;
        id_.comm_fortran = kUseCommWorld;
        dmumps_c(&id_);
        initialised_ = true;
        if (id_.infog[0] < 0) throw NumericalError(mumpsErrorText(id_.infog[0], id_.infog[1]));
        // Silence MUMPS's own printing; we log what matters.
        id_.icntl[0] = -1, id_.icntl[1] = -1, id_.icntl[2] = -1, id_.icntl[3] = 0;
        std::string ordering;
        id_.icntl[6] = orderingCode(options_.renum, ordering);
        id_.icntl[13] = options_.pcentPivot;
        if (options_.nprec >= 0) {  // null pivot detection (code_aster's NPREC)
            id_.icntl[23] = 1;
            id_.cntl[2] = std::pow(10.0, -options_.nprec);
        }
        id_.n = A.rows;
        id_.nnz = static_cast<MUMPS_INT8>(a_.size());
        id_.irn = irn_.data();
        id_.jcn = jcn_.data();
        id_.a = a_.data();
        for (int attempt = 0;; ++attempt) {
            id_.job = kJobAnalyseFactorise;
            dmumps_c(&id_);
            const int code = id_.infog[0];
            // Workspace too small: relax and retry (what code_aster does with PCENT_PIVOT).
            if ((code == -8 || code == -9 || code == -14 || code == -15 || code == -17 || code == -20) && attempt < 4) {
                id_.icntl[13] = std::max(2 * id_.icntl[13], 50);
                msg().infof("    MUMPS workspace too small (INFOG(1)={}): retrying with ICNTL(14)={}", code,
                            id_.icntl[13]);
                continue;
            }
            if (code == -10 || code == -6)
                throw NumericalError(fmt::format("singular system: {}. Likely cause: {}.",
                                                 mumpsErrorText(code, id_.infog[1]), options_.singularHint));
            if (code < 0) throw NumericalError(mumpsErrorText(code, id_.infog[1]));
            break;
        }
        if (options_.nprec >= 0 && id_.infog[27] > 0)
            throw NumericalError(fmt::format(
                "singular system: MUMPS found {} null pivot(s) (pivot below 1e-{} of the norm of the diagonal-scaled matrix, "
                "SOLVEUR/NPREC={}). Likely cause: {}.",
                id_.infog[27], options_.nprec, options_.nprec, options_.singularHint));
        static const char* orderings[] = {"AMD", "user", "AMF", "SCOTCH", "PORD", "METIS", "QAMD", "AUTO"};
        const int usedOrdering = id_.infog[6];
        msg().infof("    MUMPS ({}): n = {}, non-zeros (upper triangle) = {}, ordering {} (asked {}), "
                    "factor entries = {}, factorisation {:.3f} s, peak memory {} MB",
                    id_.sym == 1 ? "SYM=1, positive definite" : "SYM=2, general symmetric", A.rows, a_.size(),
                    usedOrdering >= 0 && usedOrdering <= 7 ? orderings[usedOrdering] : "?", ordering,
                    id_.infog[28] < 0 ? -static_cast<long long>(id_.infog[28]) * 1000000 : id_.infog[28],
                    seconds(t0), id_.infog[21]);
        if (id_.sym == 2 && id_.infog[11] > 0) {
            if (spd)
                msg().alarm("FACTOR_10", fmt::format("MUMPS found {} negative pivot(s) in a stiffness matrix that should "
                                                     "be positive definite (inverted or degenerate elements?)",
                                                     id_.infog[11]));
            else
                msg().infof("    MUMPS: {} negative pivots (expected: one per Lagrange multiplier)", id_.infog[11]);
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
        // Estimates are for the matrix MUMPS factorised: the diagonal-scaled one when scaling is on.
        if (options_.conditionEstimate && !conditionLogged_)
            msg().infof("    MUMPS condition number estimates ({} matrix): cond1 = {:.3e}, cond2 = {:.3e}, backward errors "
                        "{:.2e} {:.2e}",
                        options_.diagonalScaling ? "scaled" : "unscaled", id_.rinfog[9], id_.rinfog[10],
                        id_.rinfog[6], id_.rinfog[7]);
        conditionLogged_ = conditionLogged_ || options_.conditionEstimate;
    }

private:
    void release() {
        if (!initialised_) return;
        id_.job = kJobEnd;
        dmumps_c(&id_);
        initialised_ = false;
    }

    DMUMPS_STRUC_C id_{};
    bool conditionLogged_ = false;  // once per factorisation (refinement steps solve again)
    bool initialised_ = false;
    LargeVector<MUMPS_INT> irn_, jcn_;
    LargeVector<double> a_;
};

}  // namespace

std::unique_ptr<LinearSolver> makeMumpsSolver(const SolverOptions& options) {
    return std::make_unique<MumpsSolver>(options);
}

}  // namespace ma
