#include "solver/SymmetricSmoother.hpp"

#include <fmt/format.h>

#include <vector>

#include "solver/KrylovSettings.hpp"
#include "solver/SparseMatrix.hpp"

namespace ma {

namespace {

// This process's rows of an upper triangle in PETSc's CSR arrays (global columns).
struct UpperRows {
    std::vector<PetscInt> rowStart{0}, cols;
    std::vector<PetscScalar> values;

    void reserve(size_t rows, size_t entries) {
        rowStart.reserve(rows + 1), cols.reserve(entries), values.reserve(entries);
    }
    void endRow() { rowStart.push_back(PetscInt(cols.size())); }
    PetscInt rows() const { return PetscInt(rowStart.size()) - 1; }
};

Mat sbaijOf(const UpperRows& upper, PetscInt size, MPI_Comm comm) {
    Mat matrix = nullptr;
    checkPetsc(MatCreate(comm, &matrix), "MatCreate");
    checkPetsc(MatSetSizes(matrix, upper.rows(), upper.rows(), size, size), "MatSetSizes");
    checkPetsc(MatSetType(matrix, MATSBAIJ), "MatSetType");
    // Only the call of the matrix's own type (sequential or parallel) acts.
    checkPetsc(MatSeqSBAIJSetPreallocationCSR(matrix, 1, upper.rowStart.data(), upper.cols.data(), upper.values.data()),
               "MatSeqSBAIJSetPreallocationCSR");
    checkPetsc(MatMPISBAIJSetPreallocationCSR(matrix, 1, upper.rowStart.data(), upper.cols.data(), upper.values.data()),
               "MatMPISBAIJSetPreallocationCSR");
    return matrix;
}

}  // namespace

Mat upperTriangleOf(const CsrMatrix& B, size_t first, PetscInt size, MPI_Comm comm) {
    UpperRows upper;
    size_t entries = 0;
    for (size_t k = 0; k < size_t(B.rows); ++k)
        for (long long a = B.rowStart[k]; a < B.rowStart[k + 1]; ++a) entries += size_t(B.cols[size_t(a)]) >= first + k;
    upper.reserve(size_t(B.rows), entries);
    for (size_t k = 0; k < size_t(B.rows); ++k) {
        for (long long a = B.rowStart[k]; a < B.rowStart[k + 1]; ++a)
            if (size_t(B.cols[size_t(a)]) >= first + k)
                upper.cols.push_back(B.cols[size_t(a)]), upper.values.push_back(B.values[size_t(a)]);
        upper.endRow();
    }
    return sbaijOf(upper, size, comm);
}

namespace {

// The smoother of level l when it sweeps by SOR on its level's assembled matrix; null otherwise.
KSP sorSmootherOf(PC pc, PetscInt level, Mat& matrix) {
    KSP smoother = nullptr;
    PC inner = nullptr;
    Mat a = nullptr, p = nullptr;
    PetscBool sor = PETSC_FALSE;
    if (PCMGGetSmoother(pc, level, &smoother) != 0 || KSPGetOperators(smoother, &a, &p) != 0 ||
        KSPGetPC(smoother, &inner) != 0)
        return nullptr;
    PetscObjectTypeCompare(reinterpret_cast<PetscObject>(inner), PCSOR, &sor);
    matrix = p;
    return sor && a == p ? smoother : nullptr;
}

// The upper triangle of a level's matrix (this process's rows), read row by row.
Mat upperTriangleOfLevel(Mat level) {
    PetscInt first = 0, end = 0, size = 0;
    checkPetsc(MatGetOwnershipRange(level, &first, &end), "MatGetOwnershipRange");
    checkPetsc(MatGetSize(level, &size, nullptr), "MatGetSize");
    MatInfo info;
    checkPetsc(MatGetInfo(level, MAT_LOCAL, &info), "MatGetInfo");
    UpperRows upper;
    upper.reserve(size_t(end - first), size_t(info.nz_used) / 2 + size_t(end - first));
    for (PetscInt i = first; i < end; ++i) {
        PetscInt count = 0;
        const PetscInt* cols = nullptr;
        const PetscScalar* values = nullptr;
        checkPetsc(MatGetRow(level, i, &count, &cols, &values), "MatGetRow");
        for (PetscInt k = 0; k < count; ++k)
            if (cols[k] >= i) upper.cols.push_back(cols[k]), upper.values.push_back(values[k]);
        checkPetsc(MatRestoreRow(level, i, &count, &cols, &values), "MatRestoreRow");
        upper.endRow();
    }
    MPI_Comm comm = MPI_COMM_NULL;
    checkPetsc(PetscObjectGetComm(reinterpret_cast<PetscObject>(level), &comm), "PetscObjectGetComm");
    return sbaijOf(upper, size, comm);
}

// A Chebyshev smoother estimates its eigenvalues again, with `steps` GMRES steps, at its next set-up:
// PETSc makes an estimate only for a matrix it has not seen, so the operators are set again (the
// same ones where they were not changed). False for another smoother.
bool estimateAgain(KSP smoother, int steps) {
    KSP estimator = nullptr;
    PetscBool chebyshev = PETSC_FALSE;
    PetscObjectTypeCompare(reinterpret_cast<PetscObject>(smoother), KSPCHEBYSHEV, &chebyshev);
    if (!chebyshev || KSPChebyshevEstEigGetKSP(smoother, &estimator) != 0 || !estimator) return false;
    PetscReal rtol = 0.0, abstol = 0.0, dtol = 0.0;
    checkPetsc(KSPGetTolerances(estimator, &rtol, &abstol, &dtol, nullptr), "KSPGetTolerances");
    checkPetsc(KSPSetTolerances(estimator, rtol, abstol, dtol, steps), "KSPSetTolerances");
    checkPetsc(KSPChebyshevEstEigSet(smoother, PETSC_DECIDE, PETSC_DECIDE, PETSC_DECIDE, PETSC_DECIDE),
               "KSPChebyshevEstEigSet");
    Mat a = nullptr, p = nullptr;
    checkPetsc(KSPGetOperators(smoother, &a, &p), "KSPGetOperators");
    checkPetsc(KSPSetOperators(smoother, a, p), "KSPSetOperators");
    return true;
}

}  // namespace

int smoothOnUpperTriangles(PC pc, Mat finestUpper, int estimateSteps) {
    PetscInt levels = 0;
    if (PCMGGetLevels(pc, &levels) != 0) return 0;
    int changed = 0;
    for (PetscInt l = 0; l < levels; ++l) {  // level 0: the coarsest, smoothed when it is the only one
        KSP level = nullptr;
        if (PCMGGetSmoother(pc, l, &level) != 0) continue;
        Mat matrix = nullptr;
        KSP smoother = l > 0 ? sorSmootherOf(pc, l, matrix) : nullptr;  // `level` when it sweeps by SOR
        bool setUp = false;
        if (smoother) {
            Mat upper = l == levels - 1 ? finestUpper : upperTriangleOfLevel(matrix);
            checkPetsc(KSPSetOperators(smoother, upper, upper), "KSPSetOperators");
            checkPetsc(PCMGSetResidual(pc, l, PCMGResidualDefault, upper), "PCMGSetResidual");
            if (upper != finestUpper) MatDestroy(&upper);  // the smoother holds it
            ++changed, setUp = true;
        }
        if (estimateSteps > 0 && estimateAgain(level, estimateSteps)) setUp = true;
        if (setUp) checkPetsc(KSPSetUp(level), "KSPSetUp (a smoother on its matrix's upper triangle)");
    }
    return changed;
}

std::string eigenvalueBoundsOf(KSP smoother) {
    KSP estimator = nullptr;
    KSPType type = nullptr;
    PetscInt steps = 0;
    if (KSPChebyshevEstEigGetKSP(smoother, &estimator) != 0 || !estimator || KSPGetType(estimator, &type) != 0 ||
        KSPGetTolerances(estimator, nullptr, nullptr, nullptr, &steps) != 0)
        return {};
    return fmt::format(" (eigenvalue bounds from {} {} step(s))", steps, type ? type : "?");
}

}  // namespace ma
