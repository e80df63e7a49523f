// Krylov methods of Debian's PETSc 3.18 (SOLVEUR METHODE='PETSC' and 'GCPC', docs/solver.md). Only
// this file sees petscksp.h. The system PETSc iterates on is the diagonal-scaled S A S of the direct
// solvers (docs/fe.md): the X-FEM enriched rows cut in small fractions come to a unit diagonal, and
// the residual PETSc tests against RESI_RELA is that of the scaled system; the .mess gives the
// residual of the assembled one too. With factors as the preconditioner (LDLT_SP/DP) S A S is never
// stored: PETSc multiplies through a shell, and MUMPS factorises A with the same scaling (at N = 1001
// on ssnv511a the copy was 440 MB of a 3.1 GB peak).
#include <fmt/format.h>
#include <petscksp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "core/MemoryUsage.hpp"
#include "core/Messages.hpp"
#include "core/Mpi.hpp"
#include "core/Timing.hpp"
#include "solver/BlasThreads.hpp"
#include "solver/KrylovSettings.hpp"
#include "solver/LinearSolverImpl.hpp"
#include "solver/PiecesOnProcesses.hpp"
#include "solver/ScaledOperator.hpp"
#include "solver/SymmetricSmoother.hpp"

namespace ma {

namespace {

// PETSc on the MPI the process already runs, once; its errors come back as codes (no printing,
// no signal handlers of its own). PetscFinalize is not called: it must precede MPI_Finalize, which
// core/Mpi runs at exit; the objects are destroyed by their owners before.
void initialisePetsc() {
    static bool done = false;
    if (done) return;
    mpi::initialise();
    checkPetsc(PetscOptionsSetValue(nullptr, "-no_signal_handler", "true"), "PetscOptionsSetValue");
    checkPetsc(PetscInitializeNoArguments(), "PetscInitializeNoArguments");
    checkPetsc(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr), "PetscPushErrorHandler");
    done = true;
}

// S A S assembled, for PETSc's own preconditioners (they read the matrix entries). Distributed: each
// process's part (the pattern of its own cells) is added into the whole pattern and the values are
// summed over the processes: the whole matrix on every process.
CsrMatrix scaledCopy(const CsrMatrix& A, const std::vector<double>& s, const SolverOptions& options) {
    CsrMatrix B = A;
    if (options.distributed) {
        B = options.wholePattern();
        B.values.assign(B.cols.size(), 0.0);
        for (int i = 0; i < A.rows; ++i)
            for (long long k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) {
                const long long at = B.find(i, A.cols[size_t(k)]);
                if (at < 0) throw NumericalError("PETSc: a process's matrix entry lies outside the whole pattern");
                B.values[size_t(at)] += A.values[size_t(k)];
            }
        mpi::sum(B.values);
    }
    for (int i = 0; i < B.rows; ++i)
        for (long long k = B.rowStart[i]; k < B.rowStart[i + 1]; ++k)
            B.values[size_t(k)] *= s[size_t(i)] * s[size_t(B.cols[size_t(k)])];
    return B;
}

// The MUMPS factors of PRE_COND='LDLT_SP'/'LDLT_DP', applied once per Krylov iteration.
struct FactorPreconditioner {
    std::unique_ptr<ScaledDirectSolver> factors;
    int applications = 0;
    double seconds = 0.0, cpuSeconds = 0.0;  // wall, and CPU of the calling thread
};

PetscErrorCode applyFactors(PC pc, Vec x, Vec y) {
    void* context = nullptr;
    PetscCall(PCShellGetContext(pc, &context));
    auto* p = static_cast<FactorPreconditioner*>(context);
    const auto t0 = std::chrono::steady_clock::now();
    const double cpu0 = threadCpuSeconds();
    PetscCall(VecCopy(x, y));
    PetscInt n = 0;
    PetscCall(VecGetLocalSize(y, &n));
    PetscScalar* v = nullptr;
    PetscCall(VecGetArray(y, &v));
    try {
        p->factors->applyFactors(std::span<double>(v, size_t(n)));
    } catch (const std::exception&) {
        PetscCall(VecRestoreArray(y, &v));
        return PETSC_ERR_LIB;
    }
    PetscCall(VecRestoreArray(y, &v));
    ++p->applications;
    p->seconds += secondsSince(t0);
    p->cpuSeconds += threadCpuSeconds() - cpu0;
    return 0;
}

class PetscKrylovSolver : public LinearSolver {
public:
    explicit PetscKrylovSolver(const SolverOptions& options) : options_(options) { initialisePetsc(); }
    ~PetscKrylovSolver() override { destroy(); }

    std::string name() const override {
        return fmt::format("{} (ALGORITHME='{}', PRE_COND='{}')", options_.method, krylovAlgorithm(options_),
                           options_.preconditioner);
    }

    void factorize(const CsrMatrix& A, MatrixKind kind, std::span<const RowPoint> rowPoints) override {
        refuseUnsound(options_, kind == MatrixKind::SymmetricIndefinite);
        const bool keep = factors_.factors && A_ && A.rows == A_->rows && lastIterations_ >= 0 &&
                          lastIterations_ <= options_.reacPrecond;
        A_ = &A;
        kind_ = kind;
        rowPoints_.assign(rowPoints.begin(), rowPoints.end());
        destroyOperator();
        choosePieceBasis(kind, A);
        if (piece_.copies > 0) {
            factorizeInPieces(A);
        } else {
            scale_ = diagonalScalingOf(A, options_);
            operator_.A = A_, operator_.scale = &scale_, operator_.basis = nullptr;
            operator_.distributed = options_.distributed;
            if (usesFactors(options_)) {
                scaled_ = CsrMatrix{}, rowStart_.clear();
                createShell(A.rows);
            } else {
                scaled_ = scaledCopy(A, scale_, options_);
                createAssembled(matrix_);
            }
            checkPetsc(MatSetOption(matrix_, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
            if (options_.preconditioner == "GAMG" || options_.preconditioner == "ML") {
                std::vector<double> modes = options_.nearNullSpace ? options_.nearNullSpace() : std::vector<double>{};
                attachNearNullSpace(modes, matrix_);
            }
        }
        if (keep) {
            msg().infof(
                "    {}: preconditioner kept from the previous matrix (its last solve took {} iterations, "
                "REAC_PRECOND={})",
                name(), lastIterations_, options_.reacPrecond);
            checkPetsc(KSPSetOperators(ksp_, matrix_, preconditionerMatrix()), "KSPSetOperators");
            stale_ = true;
            return;
        }
        setUp();
    }

    double solve(std::span<double> rhs) override {
        const std::vector<double> b(rhs.begin(), rhs.end());
        for (;;) {
            const int reason = iterate(b, rhs);
            if (reason > 0) break;
            if (!stale_) throw NumericalError(stallText(reason));
            msg().infof("    {}: {} with the kept preconditioner: computed again for this matrix", name(),
                        reason == kInaccurate ? "inaccurate" : KSPConvergedReasons[reason]);
            setUp();
        }
        std::vector<double> r;
        const ResidualInfo res =
            options_.distributed ? distributedResidualOf(*A_, rhs, b, r) : residualOf(*A_, rhs, b, r, options_.threads);
        msg().infof(
            "    {}: residual of the assembled system ||Ku-f||/||f|| = {:.3e}, componentwise backward error {:.2e}",
            name(), res.normwise, res.componentwise);
        checkSolution(rhs, options_.resiRela > 0.0 ? 0.0 : res.normwise, options_);
        return res.normwise;
    }

private:
    // A new KSP and preconditioner for the current operator; logs the preconditioner's cost.
    void setUp() {
        const auto t0 = std::chrono::steady_clock::now();
        MemoryPhase phase;
        destroySolver();
        checkPetsc(KSPCreate(comm_, &ksp_), "KSPCreate");
        checkPetsc(KSPSetOperators(ksp_, matrix_, preconditionerMatrix()), "KSPSetOperators");
        configureKrylov(ksp_, options_);
        PC pc = nullptr;
        checkPetsc(KSPGetPC(ksp_, &pc), "KSPGetPC");
        if (usesFactors(options_)) {
            SolverOptions f = factorOptions(options_);
            factors_.factors = makeMumpsFactors(f);
            factors_.factors->factorizeWith(*A_, scale_, kind_, rowPoints_);  // S A S
            factors_.applications = 0, factors_.seconds = 0.0;
            checkPetsc(PCSetType(pc, PCSHELL), "PCSetType");
            checkPetsc(PCShellSetContext(pc, &factors_), "PCShellSetContext");
            checkPetsc(PCShellSetApply(pc, applyFactors), "PCShellSetApply");
            checkPetsc(PCShellSetName(pc, options_.preconditioner.c_str()), "PCShellSetName");
        } else {
            factors_.factors.reset();
            configurePreconditioner(pc, options_, pmat_ != nullptr);
        }
        setUpWithOptionPetsc(ksp_, options_, pmat_ != nullptr);
        if (upper_)
            smoothOnUpperTriangles(pc, upper_,
                                   estimatesAfterSetUp(options_, pmat_ != nullptr) ? kSmootherEstimateSteps : 0);
        stale_ = false;
        msg().infof("    {}: preconditioner built in {:.3f} s, resident peak {:.0f} MB (from {:.0f} MB){}{}", name(),
                    secondsSince(t0), phase.peakMb(), phase.startMb(),
                    nearNullModes_ ? fmt::format("; near null space: {} rigid body modes", nearNullModes_)
                                   : std::string(),
                    hierarchyOf(pc));
    }

    // GAMG's and ML's levels: their count and the operator complexity (the non-zeros of all levels'
    // matrices over the finest one's), deterministic measures of the hierarchy's cost.
    static std::string hierarchyOf(PC pc) {
        PetscBool multigrid = PETSC_FALSE;
        PetscObjectTypeCompareAny(reinterpret_cast<PetscObject>(pc), &multigrid, PCGAMG, PCML, "");
        PetscInt levels = 0;
        if (!multigrid || PCMGGetLevels(pc, &levels) != 0 || levels < 1) return {};
        double total = 0.0, finest = 0.0;
        std::string rows;
        for (PetscInt l = levels - 1; l >= 0; --l) {
            KSP smoother = nullptr;
            Mat a = nullptr, p = nullptr;
            MatInfo info;
            PetscInt m = 0;
            PetscBool upper = PETSC_FALSE;
            if (PCMGGetSmoother(pc, l, &smoother) != 0 || KSPGetOperators(smoother, &a, &p) != 0 ||
                MatGetInfo(p, MAT_GLOBAL_SUM, &info) != 0 || MatGetSize(p, &m, nullptr) != 0)
                return {};
            // A smoother on its matrix's upper triangle (SymmetricSmoother.hpp): the matrix has both.
            PetscObjectTypeCompareAny(reinterpret_cast<PetscObject>(p), &upper, MATSEQSBAIJ, MATMPISBAIJ, "");
            const double nonZeros = upper ? 2.0 * info.nz_used - double(m) : info.nz_used;
            total += nonZeros;
            if (l == levels - 1) finest = nonZeros;
            rows += fmt::format("{}{}", rows.empty() ? "" : " / ", m);
        }
        return fmt::format("; {} levels (rows {}), operator complexity {:.2f}{}", levels, rows,
                           finest > 0.0 ? total / finest : 0.0, finestSmootherOf(pc, levels));
    }

    // The finest level's smoother as PETSc runs it (miniaster's defaults and OPTION_PETSC applied):
    // method, steps, preconditioner, and the matrix its products use.
    static std::string finestSmootherOf(PC pc, PetscInt levels) {
        KSP smoother = nullptr;
        PC inner = nullptr;
        Mat a = nullptr, p = nullptr;
        KSPType method = nullptr;
        PCType kind = nullptr;
        PetscInt steps = 0;
        MatType type = nullptr;
        if (PCMGGetSmoother(pc, levels - 1, &smoother) != 0 || KSPGetType(smoother, &method) != 0 ||
            KSPGetTolerances(smoother, nullptr, nullptr, nullptr, &steps) != 0 || KSPGetPC(smoother, &inner) != 0 ||
            PCGetType(inner, &kind) != 0 || KSPGetOperators(smoother, &a, &p) != 0 || MatGetType(a, &type) != 0)
            return {};
        std::string sweeps;
        PetscBool sor = PETSC_FALSE;
        PetscObjectTypeCompare(reinterpret_cast<PetscObject>(inner), PCSOR, &sor);
        PetscInt its = 0, local = 0;
        MatSORType order = SOR_FORWARD_SWEEP;
        if (sor && PCSORGetIterations(inner, &its, &local) == 0 && PCSORGetSymmetric(inner, &order) == 0)
            sweeps = fmt::format(" ({}{} sweep(s))", its * local,
                                 (order & SOR_SYMMETRIC_SWEEP) == SOR_SYMMETRIC_SWEEP ||
                                         (order & SOR_LOCAL_SYMMETRIC_SWEEP) == SOR_LOCAL_SYMMETRIC_SWEEP
                                     ? " symmetric"
                                     : "");
        const std::string matrix = a != p                               ? fmt::format("{} matrix", type ? type : "?")
                                   : type && std::strstr(type, "sbaij") ? "assembled matrix's upper triangle (sbaij)"
                                                                        : "assembled matrix";
        return fmt::format("; finest smoother {} {} step(s) of {}{} on the {}{}", method ? method : "?", steps,
                           kind ? kind : "?", sweeps, matrix, eigenvalueBoundsOf(smoother));
    }

    // X-FEM models with GAMG, ML or BOOMER on a positive definite system: the piece basis
    // (SolverOptions::pieceBasis), shared between the processes when distributed, or the reason it
    // is not used.
    void choosePieceBasis(MatrixKind kind, const CsrMatrix& A) {
        piece_ = PieceBasis{}, shared_ = SharedPieces{}, comm_ = PETSC_COMM_SELF;
        if (!options_.pieceBasis || kind != MatrixKind::SymmetricPositiveDefinite || !isMultigrid(options_)) return;
        const auto t0 = std::chrono::steady_clock::now();
        piece_ = options_.pieceBasis();
        if (piece_.copies > 0 && options_.distributed) {
            std::vector<int> ownerOfCopy = bisectCopies(piece_, mpi::size());
            if (!ownerOfCopy.empty()) matchSharesToParts(ownerOfCopy, piece_, A);
            std::vector<PieceShare> shares = shareCopies(piece_, ownerOfCopy, mpi::size());
            if (shares.empty()) piece_ = PieceBasis{}, piece_.refusal = "fewer nodes than processes";
            else shared_ = SharedPieces{std::move(shares), mpi::rank()}, comm_ = PETSC_COMM_WORLD;
        }
        basisSeconds_ = secondsSince(t0);
        if (piece_.copies == 0)
            msg().infof("    {}: piece basis not used: {} (the blocks' rigid modes instead)", name(), piece_.refusal);
    }

    // PETSc iterates on S T^T A T S (S: the unit diagonal scaling of T^T A T) through a shell; the
    // preconditioner is built from its assembled copy without the round-off couplings of disjoint
    // pieces, with one block per node copy and the rigid modes at the copies. Shared between the
    // processes, each builds its share's rows.
    void factorizeInPieces(const CsrMatrix& A) {
        const auto t0 = std::chrono::steady_clock::now();
        const size_t n = size_t(piece_.size());
        double equationsNonZeros = double(A.nonZeros());
        if (shared_.active()) {
            const CsrMatrix rows = summedShareRows(shared_, A);
            equationsNonZeros = double(rows.nonZeros());
            mpi::sum(std::span<double>(&equationsNonZeros, 1));
            const std::vector<double> own = pieceBasisDiagonal(rows, shared_.mine(), piece_);
            std::vector<double> diagonal(n);
            shared_.gather(piece_.blockSize, own.data(), diagonal.data());
            scaled_ = pieceBasisRows(rows, shared_.mine(), piece_, diagonal, kPieceRoundOff);
            std::vector<double> mine;
            mpi::collectively([&] { mine = unitDiagonalScaling(scaled_); });
            scale_.assign(n, 1.0);
            shared_.gather(piece_.blockSize, mine.data(), scale_.data());
        } else {
            scaled_ = pieceBasisMatrix(A, piece_, kPieceRoundOff);
            scale_ = unitDiagonalScaling(scaled_);
        }
        const size_t first = firstUnknown();
        for (size_t k = 0; k < size_t(scaled_.rows); ++k)
            for (long long a = scaled_.rowStart[k]; a < scaled_.rowStart[k + 1]; ++a)
                scaled_.values[size_t(a)] *= scale_[first + k] * scale_[size_t(scaled_.cols[size_t(a)])];
        operator_.A = A_, operator_.scale = &scale_, operator_.basis = &piece_, operator_.distributed = false;
        operator_.shared = shared_.active() ? &shared_ : nullptr;
        localUnknowns_ = scaled_.rows;
        createShell(scaled_.rows, int(n));
        createAssembled(pmat_);
        if (options_.preconditioner == "ML") upper_ = upperTriangleOf(scaled_, firstUnknown(), piece_.size(), comm_);
        checkPetsc(MatSetOption(matrix_, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
        checkPetsc(MatSetOption(pmat_, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
        logPieceBasis(A.rows, equationsNonZeros, secondsSince(t0));
        if (shared_.active()) scaled_ = CsrMatrix{};  // PETSc's parallel matrix holds a copy
        if (options_.preconditioner != "BOOMER") attachNearNullSpace(piece_.modes, pmat_);
        std::vector<double>().swap(piece_.modes);
    }

    // 1/sqrt(d_kk) of each row of B (global columns, rows from firstUnknown()).
    std::vector<double> unitDiagonalScaling(const CsrMatrix& B) const {
        const size_t first = firstUnknown();
        std::vector<double> scale(size_t(B.rows), 1.0);
        for (size_t k = 0; k < size_t(B.rows); ++k)
            for (long long a = B.rowStart[k]; a < B.rowStart[k + 1]; ++a)
                if (size_t(B.cols[size_t(a)]) == first + k) {
                    const double d = B.values[size_t(a)];
                    if (!(d > 0.0))
                        throw NumericalError(fmt::format(
                            "{}: the piece basis has a non-positive diagonal {:g} (a piece without stiffness)", name(),
                            d));
                    scale[k] = 1.0 / std::sqrt(d);
                }
        return scale;
    }

    // This process's first unknown of the Krylov system (0 unless the piece basis is shared).
    size_t firstUnknown() const { return shared_.active() ? size_t(piece_.blockSize * shared_.mine().copyBegin) : 0; }

    void logPieceBasis(int equations, double equationsNonZeros, double seconds) const {
        long long padding = 0;
        for (char c : piece_.padding) padding += c;
        double nonZeros = double(scaled_.nonZeros());
        if (shared_.active()) mpi::sum(std::span<double>(&nonZeros, 1));
        msg().infof(
            "    {}: piece basis of the X-FEM model ({} block(s)): {} node copies, {} unknowns ({} of them eliminated "
            "components kept as identity rows) for {} equations; preconditioner matrix {} non-zeros (the "
            "equations' {}), block size {}{}, copies found in {:.3f} s, matrix built in {:.3f} s",
            name(), piece_.blocks, piece_.copies, piece_.size(), padding, equations, static_cast<long long>(nonZeros),
            static_cast<long long>(equationsNonZeros), piece_.blockSize,
            shared_.active()
                ? fmt::format(", shared by {} processes (coordinate bisection of the nodes)", shared_.shares.size())
                : std::string(),
            basisSeconds_, seconds);
    }

    void createShell(int local, int n) {
        checkPetsc(MatCreateShell(comm_, local, local, n, n, &operator_, &matrix_), "MatCreateShell");
        checkPetsc(MatShellSetOperation(matrix_, MATOP_MULT, reinterpret_cast<void (*)(void)>(multiplyScaled)),
                   "MatShellSetOperation");
    }
    void createShell(int n) { createShell(n, n); }
    // scaled_ as PETSc's matrix: this process's rows of a parallel matrix when the piece basis is
    // shared, else the whole matrix on its arrays. Block size: the piece basis's copies.
    void createAssembled(Mat& target) {
        rowStart_.assign(scaled_.rowStart.begin(), scaled_.rowStart.end());
        const PetscInt bs = piece_.copies > 0 ? piece_.blockSize : 1;
        if (shared_.active()) {
            checkPetsc(MatCreate(comm_, &target), "MatCreate");
            checkPetsc(MatSetSizes(target, scaled_.rows, scaled_.rows, piece_.size(), piece_.size()), "MatSetSizes");
            checkPetsc(MatSetBlockSize(target, bs), "MatSetBlockSize");
            checkPetsc(MatSetType(target, MATMPIAIJ), "MatSetType");
            checkPetsc(MatMPIAIJSetPreallocationCSR(target, rowStart_.data(), scaled_.cols.data(),
                                                    scaled_.values.data()),
                       "MatMPIAIJSetPreallocationCSR");
            return;
        }
        checkPetsc(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF, scaled_.rows, scaled_.rows, rowStart_.data(),
                                             scaled_.cols.data(), scaled_.values.data(), &target),
                   "MatCreateSeqAIJWithArrays");
        if (bs > 1) checkPetsc(MatSetBlockSize(target, bs), "MatSetBlockSize");
    }
    Mat preconditionerMatrix() const { return pmat_ ? pmat_ : matrix_; }

    // The rigid modes of the model's blocks (SolverOptions::nearNullSpace) as the near null space of
    // S A S (y = S^-1 x: each mode divided by S), orthonormalised, for GAMG's and ML's coarse spaces:
    // without them aggregation sees only constants, and the iterations grow with N (docs/solver.md).
    // Shared between processes, each orthonormalises its share (the sums over all processes).
    void attachNearNullSpace(std::vector<double>& modes, Mat target) {
        const size_t n = scale_.size(), first = firstUnknown(), m = piece_.copies > 0 ? size_t(localUnknowns_) : n;
        if (n == 0 || modes.size() < n || modes.size() % n != 0) return;
        const size_t k = modes.size() / n;
        const auto sum = [this](double value) {
            if (shared_.active()) mpi::sum(std::span<double>(&value, 1));
            return value;
        };
        std::vector<Vec> vecs;
        for (size_t mode = 0; mode < k; ++mode) {
            double* v = modes.data() + mode * n + first;
            for (size_t i = 0; i < m; ++i) v[i] /= scale_[first + i];
            for (size_t p = 0; p < mode; ++p) {  // modified Gram-Schmidt against the previous modes
                const double* q = modes.data() + p * n + first;
                double dotq = 0.0;
                for (size_t i = 0; i < m; ++i) dotq += v[i] * q[i];
                dotq = sum(dotq);
                for (size_t i = 0; i < m; ++i) v[i] -= dotq * q[i];
            }
            double norm = 0.0;
            for (size_t i = 0; i < m; ++i) norm += v[i] * v[i];
            norm = std::sqrt(sum(norm));
            if (!(norm > 0.0)) continue;
            for (size_t i = 0; i < m; ++i) v[i] /= norm;
            Vec vec = nullptr;
            checkPetsc(MatCreateVecs(target, &vec, nullptr), "MatCreateVecs");
            PetscScalar* a = nullptr;
            checkPetsc(VecGetArray(vec, &a), "VecGetArray");
            std::copy(v, v + m, a);
            checkPetsc(VecRestoreArray(vec, &a), "VecRestoreArray");
            vecs.push_back(vec);
        }
        MatNullSpace space = nullptr;
        const PetscErrorCode code = MatNullSpaceCreate(comm_, PETSC_FALSE, PetscInt(vecs.size()), vecs.data(), &space);
        if (code == 0) MatSetNearNullSpace(target, space), MatNullSpaceDestroy(&space);
        for (Vec& v : vecs) VecDestroy(&v);
        checkPetsc(code, "MatNullSpaceCreate");
        nearNullModes_ = int(vecs.size());
    }

    // KSPSolve on S A S y = S b, x = S y; returns PETSc's converged reason. lastResidual_ is the true
    // relative residual ||S b - S A S y|| / ||S b||, whatever norm the method iterated on.
    // S b, or S T^T b in the piece basis (the share's rows when it is shared).
    std::vector<double> scaledRightHandSide(const std::vector<double>& b) const {
        const size_t first = firstUnknown();
        std::vector<double> sb(piece_.copies > 0 ? size_t(localUnknowns_) : b.size());
        if (shared_.active()) {
            std::vector<double> mine;
            for (int i : shared_.mine().equations) mine.push_back(b[size_t(i)]);
            toPieces(piece_, shared_.mine(), mine.data(), sb.data());
        } else if (piece_.copies > 0) toPieces(piece_, b.data(), sb.data());
        else std::copy(b.begin(), b.end(), sb.begin());
        for (size_t i = 0; i < sb.size(); ++i) sb[i] *= scale_[first + i];
        return sb;
    }

    // x = S y, or T S y in the piece basis (the whole y gathered from the shares when it is shared).
    void toSolution(std::vector<double>& y, std::span<double> x) const {
        const size_t first = firstUnknown();
        for (size_t i = 0; i < y.size(); ++i) y[i] *= scale_[first + i];
        if (shared_.active()) {
            std::vector<double> whole(scale_.size());
            shared_.gather(piece_.blockSize, y.data(), whole.data());
            toEquations(piece_, whole.data(), x.data());
        } else if (piece_.copies > 0) {
            toEquations(piece_, y.data(), x.data());
        } else {
            std::copy(y.begin(), y.end(), x.begin());
        }
    }

    // Shared between processes, each holds its share of S b and y.
    int iterate(const std::vector<double>& b, std::span<double> x) {
        const auto t0 = std::chrono::steady_clock::now();
        std::vector<double> sb = scaledRightHandSide(b);
        const size_t n = sb.size();
        std::vector<double> y(n, 0.0), r(n);
        Vec vb = nullptr, vy = nullptr;
        if (shared_.active()) {
            checkPetsc(VecCreateMPIWithArray(comm_, 1, PetscInt(n), piece_.size(), sb.data(), &vb),
                       "VecCreateMPIWithArray");
            checkPetsc(VecCreateMPIWithArray(comm_, 1, PetscInt(n), piece_.size(), y.data(), &vy),
                       "VecCreateMPIWithArray");
        } else {
            checkPetsc(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, PetscInt(n), sb.data(), &vb), "VecCreateSeqWithArray");
            checkPetsc(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, PetscInt(n), y.data(), &vy), "VecCreateSeqWithArray");
        }
        const int appliedBefore = factors_.applications;
        const double applyBefore = factors_.seconds, applyCpuBefore = factors_.cpuSeconds;
        PetscErrorCode code = 0;
        {
            const OneBlasThread oneThread;
            code = KSPSolve(ksp_, vb, vy);
        }
        KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
        PetscInt iterations = 0;
        PetscReal estimate = 0.0;
        KSPGetConvergedReason(ksp_, &reason);
        KSPGetIterationNumber(ksp_, &iterations);
        KSPGetResidualNorm(ksp_, &estimate);
        VecDestroy(&vb), VecDestroy(&vy);
        checkPetsc(code, "KSPSolve");
        operator_.apply(y.data(), r.data());
        long double sums[2] = {0.0L, 0.0L};
        for (size_t i = 0; i < n; ++i) sums[0] += (sb[i] - r[i]) * (sb[i] - r[i]), sums[1] += sb[i] * sb[i];
        if (shared_.active()) mpi::sum(sums);
        const long double num = sums[0], den = sums[1];
        lastIterations_ = int(iterations);
        lastResidual_ = double(den > 0.0L ? std::sqrt(num / den) : std::sqrt(num));
        toSolution(y, x);
        msg().infof(
            "    {} solve {:.3f} s: {} iterations, {}, relative residual of the scaled system {:.3e} (the method's "
            "own estimate {:.3e}; RESI_RELA={:g}){}",
            name(), secondsSince(t0), lastIterations_, KSPConvergedReasons[reason], lastResidual_,
            den > 0.0L ? double(estimate) / double(std::sqrt(den)) : double(estimate), options_.resiRela,
            factors_.factors ? fmt::format("; {} applications of the {} factors, {:.3f} s (cpu {:.3f} s)",
                                           factors_.applications - appliedBefore, options_.preconditioner,
                                           factors_.seconds - applyBefore, factors_.cpuSeconds - applyCpuBefore)
                             : std::string());
        // Converged by its own estimate but not in truth (GMRES right-preconditioned by single-precision
        // factors rebuilds x with a preconditioner that is not exactly linear): not an answer either.
        if (reason > 0 && lastResidual_ > kTrueResidualSlack * options_.resiRela) return kInaccurate;
        return int(reason);
    }

    std::string stallText(int reason) const {
        const std::string what =
            reason == kInaccurate
                ? fmt::format(
                      "converged by its own residual estimate after {} iterations, but the true relative "
                      "residual {:.3e} is above {} x SOLVEUR/RESI_RELA = {:g}",
                      lastIterations_, lastResidual_, kTrueResidualSlack, options_.resiRela)
                : fmt::format(
                      "{} after {} iterations, relative residual {:.3e} above SOLVEUR/RESI_RELA = {:g} "
                      "(NMAX_ITER={})",
                      KSPConvergedReasons[reason], lastIterations_, lastResidual_, options_.resiRela,
                      options_.maxIterations);
        return fmt::format("linear solver {} did not converge: {}. {}", name(), what,
                           stallAdvice(options_, reason == kInaccurate));
    }

    void destroyOperator() {
        if (matrix_) MatDestroy(&matrix_);
        if (pmat_) MatDestroy(&pmat_);
        if (upper_) MatDestroy(&upper_);
    }
    void destroySolver() {
        if (ksp_) KSPDestroy(&ksp_);
    }
    void destroy() {
        if (!mpi::running()) return;
        destroySolver();
        destroyOperator();
    }

    // iterate()'s reason for "converged, but the true residual is above kTrueResidualSlack x RESI_RELA"
    // (the recursive residual of a converged Krylov method drifts from the true one by a few units).
    static constexpr int kInaccurate = -1000;
    static constexpr double kTrueResidualSlack = 10.0;
    // Couplings of T^T A T below this fraction of sqrt(a_kk a_ll) are the round-off of pieces that do
    // not meet (their exact value is 0); the preconditioner leaves them out, the operator keeps them.
    static constexpr double kPieceRoundOff = 1e-10;

    SolverOptions options_;
    const CsrMatrix* A_ = nullptr;
    MatrixKind kind_ = MatrixKind::SymmetricPositiveDefinite;
    std::vector<RowPoint> rowPoints_;
    std::vector<double> scale_;
    ScaledOperator operator_;
    CsrMatrix scaled_;  // S A S for PETSc's own preconditioners (empty with factors)
    std::vector<PetscInt> rowStart_;
    Mat matrix_ = nullptr;
    Mat pmat_ = nullptr;     // the preconditioner's matrix when it is not matrix_ (piece basis)
    Mat upper_ = nullptr;    // ML's finest smoother's matrix: the upper triangle of pmat_ (SBAIJ)
    PieceBasis piece_;       // copies == 0: PETSc iterates on the equations
    SharedPieces shared_;    // the piece basis's shares on several processes (inactive: one process's)
    int localUnknowns_ = 0;  // this process's unknowns of the piece basis
    MPI_Comm comm_ = PETSC_COMM_SELF;
    KSP ksp_ = nullptr;
    FactorPreconditioner factors_;
    int nearNullModes_ = 0;
    bool stale_ = false;  // the preconditioner is that of a previous matrix (REAC_PRECOND)
    int lastIterations_ = -1;
    double lastResidual_ = 0.0;
    double basisSeconds_ = 0.0;  // the piece basis: its copies found (and shared between the processes)
};

}  // namespace

}  // namespace ma

// The module's entry point (solver/LinearSolver.cpp loads it): a new solver the caller owns.
extern "C" ma::LinearSolver* miniaster_make_petsc_solver(const ma::SolverOptions& options) {
    ma::refuseUnsound(options, false);
    return new ma::PetscKrylovSolver(options);
}
