// The near null space for multigrid (fe/NearNullSpace.hpp): on free X-FEM models (no Dirichlet
// condition) cut into blocks by interfaces, every rigid motion of every block is in the discrete
// space and the stiffness matrix maps it to zero (to round-off), 2D and 3D, junctions included; the
// block modes add up to the model's rigid modes; the colouring separates blocks that meet.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

#include "core/Messages.hpp"
#include "fe/Assembly.hpp"
#include "fe/DirichletConstraints.hpp"
#include "fe/NearNullSpace.hpp"
#include "fe/SparsityPattern.hpp"
#include "fe_test_support.hpp"
#include "xfem_free_model.hpp"
#include "xfem_test_meshes.hpp"

using namespace ma;

namespace {

using xfemtest::freeModel, xfemtest::FreeModel, xfemtest::Interface, xfemtest::junction, xfemtest::maxAbs,
    xfemtest::plane;

// max |K v| / (max |K_ij| max |v|) over the vectors of `modes` (count of them).
double worstResidual(const CsrMatrix& K, const std::vector<double>& modes, int count) {
    const size_t n = static_cast<size_t>(K.rows);
    const double kmax = maxAbs(K.values);
    double worst = 0.0;
    std::vector<double> y(n);
    for (int m = 0; m < count; ++m) {
        std::span<const double> v(modes.data() + static_cast<size_t>(m) * n, n);
        EXPECT_GT(maxAbs(v), 0.0) << "mode " << m << " is empty";
        K.multiply(v, y);
        worst = std::max(worst, maxAbs(y) / (kmax * maxAbs(v)));
    }
    return worst;
}

// Per-block modes: K maps each to 0, and they add up to the model's rigid modes (standard dofs
// R(x), Heaviside dofs 0). Returns the per-block modes.
std::vector<double> checkBlockModes(const FreeModel& f, int expectedBlocks) {
    const int count = f.blocks.count, perBlock = f.space->dim() == 2 ? 3 : 6;
    EXPECT_EQ(count, expectedBlocks);
    std::vector<int> own(static_cast<size_t>(count));
    std::iota(own.begin(), own.end(), 0);
    const auto modes = groupRigidModes(*f.space, f.blocks, f.constraints, f.K.rows, own, count);
    EXPECT_LT(worstResidual(f.K, modes, count * perBlock), 1e-13);
    const auto whole = groupRigidModes(*f.space, f.blocks, f.constraints, f.K.rows, std::vector<int>(own.size(), 0), 1);
    const size_t n = static_cast<size_t>(f.K.rows);
    double gap = 0.0;
    for (int m = 0; m < perBlock; ++m)
        for (size_t i = 0; i < n; ++i) {
            double sum = 0.0;
            for (int b = 0; b < count; ++b) sum += modes[(static_cast<size_t>(b * perBlock + m)) * n + i];
            gap = std::max(gap, std::abs(sum - whole[static_cast<size_t>(m) * n + i]));
        }
    EXPECT_LT(gap, 1e-13);
    return modes;
}

}  // namespace

TEST(NearNullSpace, BlockRigidModesOfCutModels2D) {
    for (CellType kind : {CellType::QUAD4, CellType::TRIA3}) {
        SCOPED_TRACE(kind == CellType::QUAD4 ? "QUAD4" : "TRIA3");
        const auto mesh = xfemtest::square(7, kind);
        // The junction through cells, then on node rows (interfaces along element edges).
        checkBlockModes(freeModel(mesh, junction(0.3, -0.4, false)), 4);
        checkBlockModes(freeModel(xfemtest::square(6, kind), junction(0.0, 0.0, false)), 4);
        // One inclined interface: 2 blocks; two parallel ones, a strip less than a cell wide: 3.
        checkBlockModes(freeModel(mesh, {{plane(0.3, 1, 0, -0.2)}}), 2);
        checkBlockModes(freeModel(mesh, {{plane(1, 0.2, 0, -0.1)}, {plane(1, 0.2, 0, -0.8)}}), 3);
        // A branch ending on the first interface (JONCTION): 3 blocks.
        checkBlockModes(freeModel(mesh, {{plane(0, 1, 0, -0.4)}, {plane(1, 0, 0, -0.3), true, {0.3, 5, 0}}}), 3);
    }
}

TEST(NearNullSpace, BlockRigidModesOfCutModels3D) {
    for (CellType kind : {CellType::HEXA8, CellType::TETRA4}) {
        SCOPED_TRACE(kind == CellType::HEXA8 ? "HEXA8" : "TETRA4");
        const auto mesh = xfemtest::slab(5, kind);
        checkBlockModes(freeModel(mesh, junction(0.3, -0.4, true)), 4);
        checkBlockModes(freeModel(xfemtest::slab(4, kind), junction(0.0, 0.0, true)), 4);
        checkBlockModes(freeModel(mesh, {{plane(0.3, 1, 0.2, -0.2)}}), 2);
    }
}

// The model's global rigid modes with zero Heaviside values (what multigrid had before) are not
// the motion of one block: K does not map such a vector to zero. This is what the block modes add.
TEST(NearNullSpace, OneBlockWithoutItsJumpIsNotANullMode) {
    const FreeModel f = freeModel(xfemtest::square(7, CellType::QUAD4), junction(0.3, -0.4, false));
    std::vector<double> modes = checkBlockModes(f, 4);
    const DofNumbering& numbering = f.space->numbering();
    for (int node = 0; node < numbering.nodeCount(); ++node)
        for (int k = 1; k < numbering.slots(node); ++k)
            for (int c = 0; c < 2; ++c)
                if (const int e = f.constraints.eq[static_cast<size_t>(numbering.dof(node, k, c))]; e >= 0)
                    modes[static_cast<size_t>(e)] = 0.0;  // block 0's x translation without its jumps
    EXPECT_GT(worstResidual(f.K, modes, 1), 1e-2);
}

// The solver's near null space: blocks that meet get different colours; ssnv511's four blocks all
// meet at the junction (4 colours, 12 vectors in 2D, 24 in 3D), and each vector is still a null mode.
TEST(NearNullSpace, ColoursKeepMeetingBlocksApart) {
    for (bool threeD : {false, true}) {
        const FreeModel f = threeD ? freeModel(xfemtest::slab(4, CellType::HEXA8), junction(0.0, 0.0, true))
                                   : freeModel(xfemtest::square(7, CellType::QUAD4), junction(0.3, -0.4, false));
        int colours = 0;
        const auto colour = colourBlocks(f.blocks, colours);
        EXPECT_EQ(colours, 4);
        for (int b = 0; b < f.blocks.count; ++b)
            for (int c : f.blocks.neighbours[static_cast<size_t>(b)])
                EXPECT_NE(colour[static_cast<size_t>(b)], colour[static_cast<size_t>(c)]);
        const NearNullSpace space = blockNearNullSpace(*f.space, f.constraints, f.K.rows);
        EXPECT_EQ(space.modes.size(), static_cast<size_t>(threeD ? 24 : 12) * static_cast<size_t>(f.K.rows));
        EXPECT_LT(worstResidual(f.K, space.modes, threeD ? 24 : 12), 1e-13);
    }
    // Parallel interfaces: the outer blocks do not meet and share a colour (6 vectors, not 9).
    const FreeModel strip =
        freeModel(xfemtest::square(9, CellType::QUAD4), {{plane(1, 0, 0, 2.2)}, {plane(1, 0, 0, -2.3)}});
    EXPECT_EQ(strip.blocks.count, 3);
    int colours = 0;
    colourBlocks(strip.blocks, colours);
    EXPECT_EQ(colours, 2);
    // Many pieces: five parallel interfaces, six blocks, still two colours (6 vectors, not 18).
    std::vector<Interface> comb;
    for (double x : {-3.9, -2.1, -0.3, 1.6, 3.3}) comb.push_back({plane(1, 0.1, 0, -x)});
    const FreeModel combed = freeModel(xfemtest::square(19, CellType::QUAD4), comb);
    checkBlockModes(combed, 6);
    colourBlocks(combed.blocks, colours);
    EXPECT_EQ(colours, 2);
    const NearNullSpace space = blockNearNullSpace(*combed.space, combed.constraints, combed.K.rows);
    EXPECT_EQ(space.modes.size(), 6 * static_cast<size_t>(combed.K.rows));
    EXPECT_LT(worstResidual(combed.K, space.modes, 6), 1e-13);
}

// A classical model: one block per connected part; its modes are the rigid modes.
TEST(NearNullSpace, ClassicalModelIsOneBlock) {
    msg().setEcho(false);
    auto mesh = fetest::planeMesh(4, 3, false);
    auto model = fetest::affeModele(mesh, "D_PLAN", {"ALL"});
    Discretisation space(model, fetest::material(model, 2.0e5, 0.3), ExtraUnknowns{});
    const DirichletConstraints constraints = buildDirichletConstraints(space, {}, 0.0, 0);
    CsrMatrix K = buildSparsityPattern(space, constraints, nullptr);
    assembleSystemMatrix(space, constraints, nullptr, std::vector<double>(space.numbering().size(), 0.0), K);
    const NearNullSpace nns = blockNearNullSpace(space, constraints, K.rows);
    EXPECT_EQ(nns.blocks, 1);
    EXPECT_EQ(nns.colours, 1);
    EXPECT_LT(worstResidual(K, nns.modes, 3), 1e-13);
}
