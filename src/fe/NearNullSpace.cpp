#include "fe/NearNullSpace.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <numeric>

namespace ma {

namespace {

// Union-find over the pieces of the nodes.
struct PieceSets {
    std::vector<int> parent;
    int find(int i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    }
    void join(int i, int j) {
        i = find(i), j = find(j);
        if (i != j) parent[std::max(i, j)] = std::min(i, j);
    }
};

// The pieces met while walking the elements: per node, (psi values of slots 1.., piece id).
struct PieceTable {
    std::vector<std::vector<std::pair<std::vector<double>, int>>> ofNode;
    PieceSets sets;
    int piece(int node, const std::vector<double>& psi) {
        auto& list = ofNode[static_cast<size_t>(node)];
        for (const auto& [values, id] : list)
            if (values == psi) return id;
        const int id = static_cast<int>(sets.parent.size());
        sets.parent.push_back(id);
        list.emplace_back(psi, id);
        return id;
    }
};

// The pieces of the nodes of element e, joined sub-cell by sub-cell.
void walkElement(const Discretisation& space, size_t e, PieceTable& table, ElementIntegration& scratch) {
    const DofNumbering& numbering = space.numbering();
    const auto nodes = space.mesh().cellNodes(space.model().elements[e].cell);
    std::vector<double> psi;
    auto visitPoint = [&](const ElementIntegration* ei, int p) {
        int first = -1;
        for (size_t a = 0; a < nodes.size(); ++a) {
            const int node = nodes[a];
            psi.assign(static_cast<size_t>(std::max(numbering.slots(node) - 1, 0)), 0.0);
            if (ei)
                for (int k = 1; k < ei->slots[a] && k <= static_cast<int>(psi.size()); ++k)
                    psi[static_cast<size_t>(k - 1)] = ei->multiplier(p, static_cast<int>(a), k);
            const int id = table.piece(node, psi);
            if (first < 0) first = id;
            table.sets.join(first, id);
        }
    };
    if (!space.isEnriched(e)) {
        visitPoint(nullptr, 0);
        return;
    }
    const ElementIntegration& ei = space.integrationOf(e, scratch);
    // psi is constant on a sub-cell: one point of each is enough.
    for (size_t p = 0; p < ei.refPoints.size(); ++p)
        if (p == 0 || ei.pointSubcell[p] != ei.pointSubcell[p - 1]) visitPoint(&ei, static_cast<int>(p));
}

}  // namespace

// Rotation values per component: about z (2D and 3D), then about x and y (3D).
double rigidModeValue(int mode, int comp, int dim, const Vec3& x) {
    if (mode < dim) return mode == comp ? 1.0 : 0.0;
    const double rotations[3][3] = {{-x[1], x[0], 0.0}, {0.0, -x[2], x[1]}, {x[2], 0.0, -x[0]}};
    return rotations[mode - dim][comp];
}

ModelBlocks findBlocks(const Discretisation& space) {
    const DofNumbering& numbering = space.numbering();
    PieceTable table;
    table.ofNode.resize(static_cast<size_t>(numbering.nodeCount()));
    ElementIntegration scratch;
    for (size_t e = 0; e < space.elementCount(); ++e) walkElement(space, e, table, scratch);
    ModelBlocks blocks;
    std::vector<int> blockOfRoot(table.sets.parent.size(), -1);
    blocks.pieceOffsets.assign(1, 0);
    for (const auto& list : table.ofNode) {
        for (const auto& [psi, id] : list) {
            int& b = blockOfRoot[static_cast<size_t>(table.sets.find(id))];
            if (b < 0) b = blocks.count++, blocks.size.push_back(0);
            ++blocks.size[static_cast<size_t>(b)];
            blocks.piecePsi.push_back(psi);
            blocks.pieceBlock.push_back(b);
        }
        blocks.pieceOffsets.push_back(static_cast<int>(blocks.pieceBlock.size()));
    }
    // Adjacent: the blocks of the pieces of the nodes of one element (an interface along element
    // faces leaves every element in one block, but its nodes carry pieces of both sides).
    blocks.neighbours.resize(static_cast<size_t>(blocks.count));
    std::vector<int> met;
    for (size_t e = 0; e < space.elementCount(); ++e) {
        if (!space.isEnriched(e)) continue;
        met.clear();
        for (int node : space.mesh().cellNodes(space.model().elements[e].cell))
            for (int j = blocks.pieceOffsets[static_cast<size_t>(node)];
                 j < blocks.pieceOffsets[static_cast<size_t>(node) + 1]; ++j)
                met.push_back(blocks.pieceBlock[static_cast<size_t>(j)]);
        std::sort(met.begin(), met.end());
        met.erase(std::unique(met.begin(), met.end()), met.end());
        for (int b : met)
            for (int c : met)
                if (b != c) blocks.neighbours[static_cast<size_t>(b)].push_back(c);
    }
    for (auto& n : blocks.neighbours) {
        std::sort(n.begin(), n.end());
        n.erase(std::unique(n.begin(), n.end()), n.end());
    }
    return blocks;
}

std::vector<double> groupRigidModes(const Discretisation& space, const ModelBlocks& blocks,
                                    const DirichletConstraints& constraints, int rows, std::span<const int> group,
                                    int groups) {
    if (constraints.freeCount != rows) return {};
    const DofNumbering& numbering = space.numbering();
    const auto& coords = space.mesh().coords;
    const int dim = numbering.dim(), modes = dim == 2 ? 3 : 6;
    const size_t n = static_cast<size_t>(rows);
    std::vector<double> v(static_cast<size_t>(groups * modes) * n, 0.0);
    Eigen::VectorXd target, slotValues;
    for (int node = 0; node < numbering.nodeCount(); ++node) {
        const int p0 = blocks.pieceOffsets[static_cast<size_t>(node)];
        const int pieces = blocks.pieceOffsets[static_cast<size_t>(node) + 1] - p0;
        if (pieces == 0) continue;
        const int slots = numbering.slots(node);
        // Row j: the enriched value in piece j of the slot values (slot 0: 1, then the psi values).
        Eigen::MatrixXd psi(pieces, slots);
        for (int j = 0; j < pieces; ++j)
            for (int k = 0; k < slots; ++k) psi(j, k) = blocks.slotValue(p0 + j, k);
        // Slots that act in no piece (inactive) get 0: the minimum-norm solution.
        const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> solver(psi);
        std::vector<char> done(static_cast<size_t>(groups), 0);
        for (int j = 0; j < pieces; ++j) {
            const int g = group[static_cast<size_t>(blocks.pieceBlock[static_cast<size_t>(p0 + j)])];
            if (done[static_cast<size_t>(g)]) continue;
            done[static_cast<size_t>(g)] = 1;
            target.setZero(pieces);
            for (int i = 0; i < pieces; ++i)
                if (group[static_cast<size_t>(blocks.pieceBlock[static_cast<size_t>(p0 + i)])] == g) target(i) = 1.0;
            slotValues = pieces == 1 ? Eigen::VectorXd::Unit(slots, 0) : Eigen::VectorXd(solver.solve(target));
            for (int k = 0; k < slots; ++k)
                for (int comp = 0; comp < dim; ++comp) {
                    const int d = numbering.dof(node, k, comp);
                    const int e = d < 0 ? -1 : constraints.eq[static_cast<size_t>(d)];
                    if (e < 0 || e >= rows || slotValues(k) == 0.0) continue;
                    for (int m = 0; m < modes; ++m)
                        v[static_cast<size_t>(g * modes + m) * n + static_cast<size_t>(e)] =
                            slotValues(k) * rigidModeValue(m, comp, dim, coords[static_cast<size_t>(node)]);
                }
        }
    }
    return v;
}

std::vector<int> colourBlocks(const ModelBlocks& blocks, int& colours) {
    std::vector<int> order(static_cast<size_t>(blocks.count)), colour(static_cast<size_t>(blocks.count), -1);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return blocks.size[static_cast<size_t>(a)] > blocks.size[static_cast<size_t>(b)];
    });
    colours = 0;
    std::vector<char> taken;
    for (int b : order) {
        taken.assign(static_cast<size_t>(colours) + 1, 0);
        for (int c : blocks.neighbours[static_cast<size_t>(b)])
            if (const int k = colour[static_cast<size_t>(c)]; k >= 0) taken[static_cast<size_t>(k)] = 1;
        int k = 0;
        while (taken[static_cast<size_t>(k)]) ++k;
        colour[static_cast<size_t>(b)] = k;
        colours = std::max(colours, k + 1);
    }
    return colour;
}

NearNullSpace blockNearNullSpace(const Discretisation& space, const DirichletConstraints& constraints, int rows) {
    NearNullSpace out;
    if (constraints.freeCount != rows) return out;
    const ModelBlocks blocks = findBlocks(space);
    const std::vector<int> colour = colourBlocks(blocks, out.colours);
    out.blocks = blocks.count;
    out.perBlock = space.dim() == 2 ? 3 : 6;
    out.modes = groupRigidModes(space, blocks, constraints, rows, colour, out.colours);
    return out;
}

}  // namespace ma
