#include "mesh/SkinOrientation.hpp"

#include <algorithm>

#include "core/Error.hpp"
#include "mesh/MeshQueries.hpp"

namespace ma {

std::vector<int> reversedOrder(CellType t) {
    switch (t) {
        case CellType::SEG2: return {1, 0};
        case CellType::SEG3: return {1, 0, 2};
        case CellType::TRIA3: return {0, 2, 1};
        case CellType::TRIA6: return {0, 2, 1, 5, 4, 3};
        case CellType::TRIA7: return {0, 2, 1, 5, 4, 3, 6};
        case CellType::QUAD4: return {0, 3, 2, 1};
        case CellType::QUAD8: return {0, 3, 2, 1, 7, 6, 5, 4};
        case CellType::QUAD9: return {0, 3, 2, 1, 7, 6, 5, 4, 8};
        default: return {};
    }
}

SkinOrientationReport orientSkin(Mesh& mesh, const std::vector<int>& skin, const std::vector<int>& bodies,
                                 int bodyDim) {
    const NodeCellIndex around(mesh, bodyDim, bodies);

    SkinOrientationReport report;
    for (int f : skin) {
        const CellType t = mesh.cellTypes[size_t(f)];
        if (cellDimension(t) != bodyDim - 1)
            throw UserError("cell " + mesh.cellNames[size_t(f)] + " (" + cellTypeName(t) +
                            ") is not a boundary cell of a " + std::to_string(bodyDim) + "D mesh");
        auto nodes = mesh.cellNodes(f);
        const int nv = vertexCount(t);
        std::vector<int> neighbours;
        for (const int b : around.cellsOf(nodes[0])) {
            auto bn = mesh.cellNodes(b);
            bool all = true;
            for (int j = 1; j < nv && all; ++j) all = std::find(bn.begin(), bn.end(), nodes[size_t(j)]) != bn.end();
            if (all && std::find(neighbours.begin(), neighbours.end(), b) == neighbours.end()) neighbours.push_back(b);
        }
        if (neighbours.empty())
            throw UserError("cell " + mesh.cellNames[size_t(f)] + " has no adjacent " + std::to_string(bodyDim) +
                            "D cell: it cannot be oriented");
        if (neighbours.size() > 1)
            throw UserError("cell " + mesh.cellNames[size_t(f)] + " lies between cells " +
                            mesh.cellNames[size_t(neighbours[0])] + " and " + mesh.cellNames[size_t(neighbours[1])] +
                            ": it is not on the skin (restrict the neighbours with GROUP_MA_VOLU / GROUP_MA_SURF)");
        ++report.checked;
        const Vec3 n = cellNormal(mesh, f);
        const Vec3 gb = vertexCentroid(mesh, neighbours[0]), gf = vertexCentroid(mesh, f);
        const Vec3 g{gb[0] - gf[0], gb[1] - gf[1], gb[2] - gf[2]};
        if (dot(n, g) > 0) {
            auto order = reversedOrder(t);
            if (order.empty()) throw NotImplemented("reorienting " + cellTypeName(t) + " cells");
            std::vector<int> old(nodes.begin(), nodes.end());
            int* out = mesh.connectivity.data() + mesh.cellOffsets[size_t(f)];
            for (size_t k = 0; k < order.size(); ++k) out[k] = old[size_t(order[k])];
            ++report.reoriented;
        }
    }
    return report;
}

}  // namespace ma
