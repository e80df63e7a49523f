#include "solver/SymmetricSmoother.hpp"

#include <vector>

#include "solver/KrylovSettings.hpp"
#include "solver/SparseMatrix.hpp"

namespace ma {

Mat upperTriangleOf(const CsrMatrix& B, size_t first, PetscInt size, MPI_Comm comm) {
    std::vector<PetscInt> rowStart{0}, cols;
    std::vector<PetscScalar> values;
    for (size_t k = 0; k < size_t(B.rows); ++k) {
        for (long long a = B.rowStart[k]; a < B.rowStart[k + 1]; ++a)
            if (size_t(B.cols[size_t(a)]) >= first + k)
                cols.push_back(B.cols[size_t(a)]), values.push_back(B.values[size_t(a)]);
        rowStart.push_back(PetscInt(cols.size()));
    }
    Mat upper = nullptr;
    checkPetsc(MatCreate(comm, &upper), "MatCreate");
    checkPetsc(MatSetSizes(upper, B.rows, B.rows, size, size), "MatSetSizes");
    checkPetsc(MatSetType(upper, MATSBAIJ), "MatSetType");
    // Only the call of the matrix's own type (sequential or parallel) acts.
    checkPetsc(MatSeqSBAIJSetPreallocationCSR(upper, 1, rowStart.data(), cols.data(), values.data()),
               "MatSeqSBAIJSetPreallocationCSR");
    checkPetsc(MatMPISBAIJSetPreallocationCSR(upper, 1, rowStart.data(), cols.data(), values.data()),
               "MatMPISBAIJSetPreallocationCSR");
    return upper;
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
    CsrMatrix rows;
    rows.rows = int(end - first);
    for (PetscInt i = first; i < end; ++i) {
        PetscInt count = 0;
        const PetscInt* cols = nullptr;
        const PetscScalar* values = nullptr;
        checkPetsc(MatGetRow(level, i, &count, &cols, &values), "MatGetRow");
        for (PetscInt k = 0; k < count; ++k)
            if (cols[k] >= i) rows.cols.push_back(int(cols[k])), rows.values.push_back(values[k]);
        checkPetsc(MatRestoreRow(level, i, &count, &cols, &values), "MatRestoreRow");
        rows.rowStart.push_back(static_cast<long long>(rows.cols.size()));
    }
    MPI_Comm comm = MPI_COMM_NULL;
    checkPetsc(PetscObjectGetComm(reinterpret_cast<PetscObject>(level), &comm), "PetscObjectGetComm");
    return upperTriangleOf(rows, size_t(first), size, comm);
}

}  // namespace

int smoothOnUpperTriangles(PC pc, Mat finestUpper) {
    PetscInt levels = 0;
    if (PCMGGetLevels(pc, &levels) != 0) return 0;
    int changed = 0;
    for (PetscInt l = 1; l < levels; ++l) {
        Mat matrix = nullptr;
        KSP smoother = sorSmootherOf(pc, l, matrix);
        if (!smoother) continue;
        Mat upper = l == levels - 1 ? finestUpper : upperTriangleOfLevel(matrix);
        checkPetsc(KSPSetOperators(smoother, upper, upper), "KSPSetOperators");
        if (upper != finestUpper) MatDestroy(&upper);  // the smoother holds it
        checkPetsc(KSPSetUp(smoother), "KSPSetUp (a smoother on its matrix's upper triangle)");
        ++changed;
    }
    return changed;
}

}  // namespace ma
