// The piece basis for multigrid on X-FEM models (fe/PieceCopies.hpp, solver/PieceBasis.hpp): on free
// models cut into blocks by interfaces that meet at a junction, T^T K T maps each of the model's
// rigid modes evaluated at the node copies to zero (to round-off), T maps them back to the model's
// rigid modes; and a solve through the piece basis (CG with ML, GAMG, BOOMER) gives the direct
// solver's answer.
#include <gtest/gtest.h>

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

TEST(PieceBasis, RigidModesAtTheCopiesAreNullModes3D) {
    checkPieceModes(junctionModel(xfemtest::slab(5, CellType::HEXA8), 0.3, -0.4));
    checkPieceModes(junctionModel(xfemtest::slab(4, CellType::HEXA8), 0.0, 0.0));  // on node rows
    checkPieceModes(junctionModel(xfemtest::slab(5, CellType::TETRA4), 0.3, -0.4));
}

TEST(PieceBasis, RigidModesAtTheCopiesAreNullModes2D) {
    checkPieceModes(junctionModel(xfemtest::square(7, CellType::QUAD4), 0.3, -0.4));
    checkPieceModes(junctionModel(xfemtest::square(7, CellType::TRIA3), 0.3, -0.4));
}

// K + c diag(K) (positive definite) solved by MUMPS and by CG through the piece basis with each
// multigrid preconditioner: the same answer to 1e-10, and the .mess says which basis, how many
// modes, and that GAMG's and ML's smoothers multiply by the assembled matrix, not through the shell
// (ML also with OPTION_PETSC='-pc_use_amat true', which asks for the shell).
TEST(PieceBasis, SolveThroughThePiecesIsTheDirectOne) {
    const FreeModel f = junctionModel(xfemtest::slab(6, CellType::HEXA8), 0.3, -0.4);
    CsrMatrix A = f.K;
    for (int i = 0; i < A.rows; ++i) A.values[size_t(A.find(i, i))] *= 1.0 + 1e-2;
    std::vector<double> b(size_t(A.rows));
    for (int i = 0; i < A.rows; ++i) b[size_t(i)] = std::sin(0.37 * i) + 0.5;
    std::vector<double> direct = b;
    {
        SolverOptions o;
        auto solver = makeLinearSolver(o);
        solver->factorize(A, MatrixKind::SymmetricPositiveDefinite);
        solver->solve(direct);
    }
    const std::vector<std::pair<std::string, std::string>> settings = {{"ML", ""},
                                                                       {"GAMG", ""},
                                                                       {"BOOMER", ""},
                                                                       {"ML", "-pc_use_amat true"}};
    for (const auto& [pc, given] : settings) {
        SCOPED_TRACE(pc + " " + given);
        SolverOptions o;
        o.method = "PETSC", o.algorithm = "CG", o.preconditioner = pc, o.resiRela = 1e-13;
        o.petscOptions = given;
        o.pieceBasis = [&] { return pieceBasisOf(*f.space, f.constraints, A.rows); };
        const size_t from = msg().messText().size();
        auto solver = makeLinearSolver(o);
        solver->factorize(A, MatrixKind::SymmetricPositiveDefinite);
        std::vector<double> x = b;
        solver->solve(x);
        double diff = 0.0;
        for (size_t i = 0; i < x.size(); ++i) diff = std::max(diff, std::abs(x[i] - direct[i]));
        EXPECT_LT(diff / maxAbs(direct), 1e-10);
        const std::string mess = msg().messText().substr(from);
        EXPECT_NE(mess.find("piece basis of the X-FEM model (4 block(s))"), std::string::npos) << mess;
        if (pc == "BOOMER") continue;
        EXPECT_NE(mess.find("near null space: 6 rigid body modes"), std::string::npos) << mess;
        const std::string smoother =
            pc == "GAMG" ? "finest smoother chebyshev 2 step(s) of jacobi on the assembled matrix"
                         : std::string("finest smoother chebyshev 2 step(s) of sor (1 symmetric sweep(s)) on the ") +
                               (given.empty() ? "assembled matrix" : "shell matrix");
        EXPECT_NE(mess.find(smoother), std::string::npos) << mess;
    }
}
