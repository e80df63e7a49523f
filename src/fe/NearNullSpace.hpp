#pragma once
// The near null space of a mechanical problem for algebraic multigrid (PETSc's GAMG and ML,
// docs/solver.md): the rigid motions of every block the X-FEM interfaces cut the model into.
//
// At a node a, the enriched shape functions N_a (U_0 + sum_k psi_k U_k) take one independent value
// in each "piece" of its support: the sub-cells where the slots have the same psi values (the
// node's own domain: psi = 0; the domain of slot k: psi_k = +-2, the others 0; the values come from
// the Enrichment's element descriptions, fe/Discretisation). A sub-cell joins the pieces of all its
// nodes; the connected sets of pieces are the blocks. A rigid motion R restricted to a block B is
// then exactly in the discrete space: at each node, the slot values for which the enriched
// displacement is R(x_a) in the pieces of B and 0 in the others, and K times it is 0 (to round-off).
#include <span>
#include <vector>

#include "fe/DirichletConstraints.hpp"
#include "fe/Discretisation.hpp"

namespace ma {

struct ModelBlocks {
    int count = 0;  // blocks
    // Per node (CSR): the pieces of its support, each with its psi values (slots 1.. of the node;
    // slot 0 is 1) and its block.
    std::vector<int> pieceOffsets;
    std::vector<std::vector<double>> piecePsi;
    std::vector<int> pieceBlock;
    // Blocks that share an element (colouring: two adjacent blocks never share a vector).
    std::vector<std::vector<int>> neighbours;
    std::vector<int> size;  // pieces of each block

    // The value of a node's slot in one of its pieces (piece: index into piecePsi): 1 for slot 0,
    // then the psi values, 0 beyond them.
    double slotValue(int piece, int slot) const {
        if (slot == 0) return 1.0;
        const auto& psi = piecePsi[static_cast<size_t>(piece)];
        return static_cast<size_t>(slot - 1) < psi.size() ? psi[static_cast<size_t>(slot - 1)] : 0.0;
    }
};

// Component comp of rigid motion `mode` at x (2D: 2 translations, the rotation about z; 3D: 3
// translations, the rotations about z, x and y).
double rigidModeValue(int mode, int comp, int dim, const Vec3& x);

// The blocks of the model (one for a classical connected model; one per connected part otherwise).
ModelBlocks findBlocks(const Discretisation& space);

// The rigid motions (2D: 2 translations, 1 rotation; 3D: 3 and 3) of the union of the blocks b with
// group[b] == g, for g = 0 .. groups - 1, on the free equations: vector (g, m) is values
// [(g * modes + m) * rows, ...). Eliminated unknowns are left out (as the equations are); empty
// when some equation has no node (multipliers, additional unknowns).
std::vector<double> groupRigidModes(const Discretisation& space, const ModelBlocks& blocks,
                                    const DirichletConstraints& constraints, int rows, std::span<const int> group,
                                    int groups);

// Greedy colouring of the blocks, largest first: adjacent blocks get different colours. Returns the
// colour of each block; `colours` is set to their number.
std::vector<int> colourBlocks(const ModelBlocks& blocks, int& colours);

// What the solver gets (SolverOptions::nearNullSpace): the rigid modes of each colour of blocks, so
// the vectors stay few however many blocks there are (ssnv511: 4 blocks meeting at the junction, 4
// colours, 12 modes in 2D, 24 in 3D), while within any element the blocks keep separate vectors.
struct NearNullSpace {
    std::vector<double> modes;
    int blocks = 0, colours = 0, perBlock = 0;
};
NearNullSpace blockNearNullSpace(const Discretisation& space, const DirichletConstraints& constraints, int rows);

}  // namespace ma
