// The piece basis for multigrid on X-FEM models (fe/PieceCopies.hpp, solver/PieceBasis.hpp): on free
// models cut into blocks by interfaces that meet at a junction, T^T K T maps each of the model's
// rigid modes evaluated at the node copies to zero (to round-off), T maps them back to the model's
// rigid modes; and a solve through the piece basis (CG with ML, GAMG, BOOMER) gives the direct
// solver's answer.
#include <gtest/gtest.h>

#include <sstream>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/Messages.hpp"
#include "fe/Assembly.hpp"
#include "fe/DirichletConstraints.hpp"
#include "fe/NearNullSpace.hpp"
#include "fe/PieceCopies.hpp"
#include "fe/SparsityPattern.hpp"
#include "fe_test_support.hpp"
#include "solver/LinearSolver.hpp"
#include "xfem_free_model.hpp"
#include "xfem_test_meshes.hpp"

using namespace ma;

namespace {

using xfemtest::FreeModel, xfemtest::maxAbs;

// ssnv511's interfaces joined at (x0, y0).
FreeModel junctionModel(const std::shared_ptr<Mesh>& mesh, double x0, double y0) {
    return xfemtest::freeModel(mesh, xfemtest::junction(x0, y0, mesh->dim == 3));
}

// max over the modes of |B v| / (max |B_ij| max |v|).
double worstResidual(const CsrMatrix& B, const std::vector<double>& modes) {
    const size_t n = size_t(B.rows);
    double worst = 0.0;
    std::vector<double> y(n);
    for (size_t m = 0; m < modes.size() / n; ++m) {
        const std::span<const double> v(modes.data() + m * n, n);
        EXPECT_GT(maxAbs(v), 0.0);
        B.multiply(v, y);
        worst = std::max(worst, maxAbs(y) / (maxAbs(B.values) * maxAbs(v)));
    }
    return worst;
}

void checkPieceModes(const FreeModel& f) {
    const PieceBasis basis = pieceBasisOf(*f.space, f.constraints, f.K.rows);
    ASSERT_GT(basis.copies, 0) << basis.refusal;
    EXPECT_EQ(basis.blocks, 4);
    const int dim = f.space->dim(), modes = dim == 2 ? 3 : 6;
    const size_t n = size_t(basis.size()), rows = size_t(f.K.rows);
    ASSERT_EQ(basis.modes.size(), size_t(modes) * n);
    // Every free equation is a combination of piece values; no copy is padding on a free model.
    EXPECT_EQ(std::count(basis.padding.begin(), basis.padding.end(), 1), 0);
    EXPECT_GT(n, rows - 1);
    const CsrMatrix whole = pieceBasisMatrix(f.K, basis, 0.0);
    const CsrMatrix kept = pieceBasisMatrix(f.K, basis, 1e-10);
    EXPECT_LT(worstResidual(whole, basis.modes), 1e-13);
    EXPECT_LT(worstResidual(kept, basis.modes), 1e-13);
    // Copies of pieces that do not meet are not coupled: their computed round-off is left out.
    EXPECT_LT(kept.nonZeros(), whole.nonZeros());
    // T maps the modes at the copies to the model's rigid modes: R(x) on the standard unknowns, 0 on
    // the Heaviside ones.
    const DofNumbering& numbering = f.space->numbering();
    std::vector<double> u(rows);
    double gap = 0.0;
    for (int m = 0; m < modes; ++m) {
        toEquations(basis, basis.modes.data() + size_t(m) * n, u.data());
        for (int node = 0; node < numbering.nodeCount(); ++node)
            for (int k = 0; k < numbering.slots(node); ++k)
                for (int c = 0; c < dim; ++c) {
                    const int e = f.constraints.eq[size_t(numbering.dof(node, k, c))];
                    if (e < 0) continue;
                    const double expected =
                        k == 0 ? rigidModeValue(m, c, dim, f.space->mesh().coords[size_t(node)]) : 0.0;
                    gap = std::max(gap, std::abs(u[size_t(e)] - expected));
                }
    }
    EXPECT_LT(gap, 1e-12);
}

}  // namespace

// T^T K T computed densely from T and K, against pieceBasisMatrix's rows (those of the nodes with one
// piece are A's rows mapped, the others summed): the same entries.
void checkTransposedProduct(const FreeModel& f) {
    const PieceBasis basis = pieceBasisOf(*f.space, f.constraints, f.K.rows);
    ASSERT_GT(basis.copies, 0) << basis.refusal;
    const size_t n = size_t(basis.size()), rows = size_t(f.K.rows);
    std::vector<double> KT(rows * n, 0.0), dense(n * n, 0.0);  // K T, then T^T K T
    const CsrMatrix &K = f.K, &T = basis.T;
    for (size_t i = 0; i < rows; ++i)
        for (long long a = K.rowStart[i]; a < K.rowStart[i + 1]; ++a) {
            const size_t j = size_t(K.cols[size_t(a)]);
            for (long long c = T.rowStart[j]; c < T.rowStart[j + 1]; ++c)
                KT[i * n + size_t(T.cols[size_t(c)])] += K.values[size_t(a)] * T.values[size_t(c)];
        }
    std::vector<int> readers(n, 0);  // equations reading each unknown
    for (size_t i = 0; i < rows; ++i)
        for (long long c = T.rowStart[i]; c < T.rowStart[i + 1]; ++c) {
            const size_t k = size_t(T.cols[size_t(c)]);
            ++readers[k];
            for (size_t l = 0; l < n; ++l) dense[k * n + l] += T.values[size_t(c)] * KT[i * n + l];
        }
    const CsrMatrix B = pieceBasisMatrix(K, basis, 0.0);
    ASSERT_EQ(size_t(B.rows), n);
    const double scale = maxAbs(K.values);
    for (size_t k = 0; k < n; ++k) {
        std::vector<double> row(n, 0.0);
        for (long long a = B.rowStart[k]; a < B.rowStart[k + 1]; ++a)
            row[size_t(B.cols[size_t(a)])] = B.values[size_t(a)];
        for (size_t l = 0; l < n; ++l)
            EXPECT_NEAR(row[l], dense[k * n + l], 1e-14 * scale) << "row " << k << " column " << l;
    }
    EXPECT_GT(std::count(readers.begin(), readers.end(), 1), 0);  // rows of both kinds
    EXPECT_GT(std::count_if(readers.begin(), readers.end(), [](int r) { return r > 1; }), 0);
}

TEST(PieceBasis, TheMatrixIsTTransposedKTEntryByEntry) {
    checkTransposedProduct(junctionModel(xfemtest::square(7, CellType::QUAD4), 0.3, -0.4));
    checkTransposedProduct(junctionModel(xfemtest::slab(4, CellType::HEXA8), 0.3, -0.4));
}

TEST(PieceBasis, RigidModesAtTheCopiesAreNullModes3D) {
    checkPieceModes(junctionModel(xfemtest::slab(5, CellType::HEXA8), 0.3, -0.4));
    checkPieceModes(junctionModel(xfemtest::slab(4, CellType::HEXA8), 0.0, 0.0));  // on node rows
    checkPieceModes(junctionModel(xfemtest::slab(5, CellType::TETRA4), 0.3, -0.4));
}

TEST(PieceBasis, RigidModesAtTheCopiesAreNullModes2D) {
    checkPieceModes(junctionModel(xfemtest::square(7, CellType::QUAD4), 0.3, -0.4));
    checkPieceModes(junctionModel(xfemtest::square(7, CellType::TRIA3), 0.3, -0.4));
}

namespace {

// A positive definite system, its right-hand side and MUMPS's answer.
struct KnownSystem {
    CsrMatrix A;
    std::vector<double> b, direct;
};

// K + c diag(K): positive definite, for a free model.
KnownSystem regularised(const FreeModel& f, double c = 1e-2) {
    KnownSystem r{f.K, std::vector<double>(size_t(f.K.rows)), {}};
    for (int i = 0; i < r.A.rows; ++i) r.A.values[size_t(r.A.find(i, i))] *= 1.0 + c;
    for (int i = 0; i < r.A.rows; ++i) r.b[size_t(i)] = std::sin(0.37 * i) + 0.5;
    r.direct = r.b;
    SolverOptions o;
    auto solver = makeLinearSolver(o);
    solver->factorize(r.A, MatrixKind::SymmetricPositiveDefinite);
    solver->solve(r.direct);
    return r;
}

struct PieceSolve {
    double error;  // max |x - direct| / max |direct|
    std::string mess;
};

// CG through the piece basis with multigrid preconditioner `pc` and OPTION_PETSC `given`.
PieceSolve solveInPieces(const FreeModel& f, const KnownSystem& r, const std::string& pc, const std::string& given,
                         double resiRela = 1e-13) {
    SolverOptions o;
    o.method = "PETSC", o.algorithm = "CG", o.preconditioner = pc, o.resiRela = resiRela;
    o.petscOptions = given;
    o.pieceBasis = [&] { return pieceBasisOf(*f.space, f.constraints, r.A.rows); };
    const size_t from = msg().messText().size();
    auto solver = makeLinearSolver(o);
    solver->factorize(r.A, MatrixKind::SymmetricPositiveDefinite);
    std::vector<double> x = r.b;
    solver->solve(x);
    double diff = 0.0;
    for (size_t i = 0; i < x.size(); ++i) diff = std::max(diff, std::abs(x[i] - r.direct[i]));
    return {diff / maxAbs(r.direct), msg().messText().substr(from)};
}

// The rows of each multigrid level in a .mess excerpt ("N levels (rows a / b / ...)"), finest first.
std::vector<int> levelRowsIn(const std::string& mess) {
    std::vector<int> rows;
    const size_t at = mess.find(" levels (rows ");
    if (at == std::string::npos) return rows;
    std::istringstream in(mess.substr(at + 14, mess.find(')', at) - at - 14));
    for (std::string word; in >> word;)
        if (word != "/") rows.push_back(std::stoi(word));
    return rows;
}

// The Krylov iterations of the last solve in a .mess excerpt ("solve ... s: N iterations").
int iterationsIn(const std::string& mess) {
    const size_t at = mess.rfind(" iterations, ");
    if (at == std::string::npos) return -1;
    const size_t from = mess.rfind(' ', at - 1) + 1;
    return std::stoi(mess.substr(from, at - from));
}

// The free model clamped on its faces x = -5 and x = 5 (ssnv511c's SG and SD; no node there is
// enriched): those unknowns eliminated, the principal submatrix of K on the others.
struct Clamped {
    DirichletConstraints constraints;
    KnownSystem system;
};

Clamped clampedOnSides(const FreeModel& f) {
    Clamped c{f.constraints, {}};
    const DofNumbering& numbering = f.space->numbering();
    const auto& coords = f.space->mesh().coords;
    for (int node = 0; node < numbering.nodeCount(); ++node)
        if (std::abs(std::abs(coords[size_t(node)][0]) - 5.0) < 1e-12)
            for (int k = 0; k < numbering.slots(node); ++k)
                for (int comp = 0; comp < 3; ++comp) c.constraints.fixed[size_t(numbering.dof(node, k, comp))] = 1;
    std::vector<int> kept(size_t(f.K.rows), -1);  // old equation -> new
    int next = 0;
    for (size_t d = 0; d < c.constraints.eq.size(); ++d) {
        int& e = c.constraints.eq[d];
        if (e < 0) continue;
        e = c.constraints.fixed[d] ? -1 : (kept[size_t(e)] = next++);
    }
    c.constraints.freeCount = next;
    CsrMatrix& A = c.system.A;
    A.rows = next;
    for (int i = 0; i < f.K.rows; ++i) {
        if (kept[size_t(i)] < 0) continue;
        for (long long a = f.K.rowStart[size_t(i)]; a < f.K.rowStart[size_t(i) + 1]; ++a)
            if (const int j = kept[size_t(f.K.cols[size_t(a)])]; j >= 0)
                A.cols.push_back(j), A.values.push_back(f.K.values[size_t(a)]);
        A.rowStart.push_back(static_cast<long long>(A.cols.size()));
    }
    c.system.b.assign(size_t(next), 0.0);
    for (int i = 0; i < next; ++i) c.system.b[size_t(i)] = std::sin(0.37 * i) + 0.5;
    c.system.direct = c.system.b;
    auto solver = makeLinearSolver(SolverOptions{});
    solver->factorize(A, MatrixKind::SymmetricPositiveDefinite);
    solver->solve(c.system.direct);
    return c;
}

}  // namespace

// K + c diag(K) solved by MUMPS and by CG through the piece basis with each multigrid
// preconditioner: the same answer to 1e-10, and the .mess says which basis, how many modes, and that
// GAMG's and ML's smoothers multiply by the assembled matrix, not through the shell (ML on its upper
// triangle; with OPTION_PETSC='-pc_use_amat true', which asks for the shell, through the shell).
TEST(PieceBasis, SolveThroughThePiecesIsTheDirectOne) {
    // 4 000 unknowns: ML coarsens them once (its coarsening stops below 2 000 rows).
    const FreeModel f = junctionModel(xfemtest::slab(24, CellType::HEXA8), 0.3, -0.4);
    const KnownSystem r = regularised(f);
    const std::vector<std::pair<std::string, std::string>> settings = {{"ML", ""},
                                                                       {"GAMG", ""},
                                                                       {"BOOMER", ""},
                                                                       {"ML", "-pc_use_amat true"}};
    for (const auto& [pc, given] : settings) {
        SCOPED_TRACE(pc + " " + given);
        const PieceSolve s = solveInPieces(f, r, pc, given);
        EXPECT_LT(s.error, 1e-10);
        const std::string& mess = s.mess;
        EXPECT_NE(mess.find("piece basis of the X-FEM model (4 block(s))"), std::string::npos) << mess;
        if (pc == "BOOMER") continue;
        EXPECT_NE(mess.find("near null space: 6 rigid body modes"), std::string::npos) << mess;
        const std::string smoother =
            pc == "GAMG" ? "finest smoother chebyshev 2 step(s) of jacobi on the assembled matrix"
                         : std::string("finest smoother chebyshev 2 step(s) of sor (1 symmetric sweep(s)) on the ") +
                               (given.empty() ? "assembled matrix's upper triangle (sbaij)" : "shell matrix");
        EXPECT_NE(mess.find(smoother), std::string::npos) << mess;
        if (pc != "ML") continue;
        const std::vector<int> levels = levelRowsIn(mess);
        ASSERT_EQ(levels.size(), 2u) << mess;
        EXPECT_GE(levels[0], 2000) << mess;
        EXPECT_LT(levels[1], 2000) << mess;  // solved by LU
    }
}

// ML in the piece basis runs W-cycles (the .mess lists the option): on ssnv511c's 10:1 flat cells,
// clamped on two sides, they take fewer iterations than V-cycles (OPTION_PETSC='-pc_mg_cycle_type
// v'), for the same answer. The hierarchy coarsened to the end (-pc_ml_maxCoarseSize 1: this model's
// 7 000 rows would otherwise make two levels, where W and V are one cycle).
TEST(PieceBasis, WCyclesTakeFewerIterationsOnFlatCells) {
    FreeModel f = junctionModel(xfemtest::slab(12, CellType::HEXA8, 12), 0.3, -0.4);
    Clamped c = clampedOnSides(f);
    f.constraints = c.constraints;
    const PieceSolve w = solveInPieces(f, c.system, "ML", "-pc_ml_maxCoarseSize 1", 1e-12);
    const PieceSolve v = solveInPieces(f, c.system, "ML", "-pc_ml_maxCoarseSize 1 -pc_mg_cycle_type v", 1e-12);
    EXPECT_LT(w.error, 1e-10);
    EXPECT_LT(v.error, 1e-10);
    EXPECT_GT(levelRowsIn(w.mess).size(), 2u) << w.mess;
    EXPECT_NE(w.mess.find("-mg_levels_ksp_max_it 2 -pc_mg_cycle_type w"), std::string::npos) << w.mess;
    EXPECT_GT(iterationsIn(w.mess), 0) << w.mess;
    EXPECT_LT(iterationsIn(w.mess), iterationsIn(v.mess)) << w.mess << v.mess;
}

// ML's smoothers sweep the upper triangles of their matrices, where their eigenvalue bounds are
// estimated in 10 GMRES steps; ML's set-up, which estimates them first on the whole matrices, does it
// in one step. The solve is the one of PETSc's own path (OPTION_PETSC on the estimates: 10 steps in
// both estimates): the same iterations, the same answer (to the round-off of ML's random start
// vectors, which move from one construction to the next in a process); bounds from a single step
// would not do.
TEST(PieceBasis, SmoothersEstimateTheirBoundsOnTheMatricesTheySweep) {
    FreeModel f = junctionModel(xfemtest::slab(12, CellType::HEXA8, 12), 0.3, -0.4);
    Clamped c = clampedOnSides(f);
    f.constraints = c.constraints;
    const PieceSolve ours = solveInPieces(f, c.system, "ML", "-pc_ml_maxCoarseSize 1", 1e-12);
    const PieceSolve petsc =
        solveInPieces(f, c.system, "ML", "-pc_ml_maxCoarseSize 1 -mg_levels_esteig_ksp_max_it 10", 1e-12);
    EXPECT_LT(ours.error, 1e-10);
    EXPECT_LT(petsc.error, 1e-10);
    EXPECT_NE(ours.mess.find("upper triangle (sbaij) (eigenvalue bounds from 10 gmres step(s))"), std::string::npos)
        << ours.mess;
    EXPECT_GT(iterationsIn(ours.mess), 0) << ours.mess;
    EXPECT_EQ(iterationsIn(ours.mess), iterationsIn(petsc.mess)) << ours.mess << petsc.mess;
    // Bounds from one step fall below the largest eigenvalue: CG stops on an indefinite preconditioner.
    EXPECT_THROW(solveInPieces(f, c.system, "ML", "-pc_ml_maxCoarseSize 1 -mg_levels_esteig_ksp_max_it 1", 1e-12),
                 NumericalError);
}
