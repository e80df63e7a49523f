#include "mesh/CellPartition.hpp"

#include <fmt/format.h>
#include <metis.h>

#include <numeric>

#include "core/Error.hpp"

namespace ma {

std::vector<int> partitionCells(const Mesh& mesh, std::span<const int> cells, std::span<const int> weights, int dim,
                                int parts) {
    const size_t n = cells.size();
    std::vector<int> owner(n, 0);
    if (parts <= 1 || n == 0) return owner;
    if (n <= size_t(parts)) {
        std::iota(owner.begin(), owner.end(), 0);
        return owner;
    }
    // The cells' nodes, numbered compactly (METIS counts every node it is given).
    std::vector<idx_t> compact(size_t(mesh.nodeCount()), -1), eptr{0}, eind;
    idx_t nodes = 0;
    for (int cell : cells) {
        for (int node : mesh.cellNodes(cell)) {
            if (compact[size_t(node)] < 0) compact[size_t(node)] = nodes++;
            eind.push_back(compact[size_t(node)]);
        }
        eptr.push_back(idx_t(eind.size()));
    }
    std::vector<idx_t> vwgt(weights.begin(), weights.end()), epart(n), npart(static_cast<size_t>(nodes));
    idx_t ne = idx_t(n), nn = nodes, ncommon = dim, nparts = parts, objval = 0;
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_SEED] = 1;
    const int rc = METIS_PartMeshDual(&ne, &nn, eptr.data(), eind.data(), vwgt.empty() ? nullptr : vwgt.data(), nullptr,
                                      &ncommon, &nparts, nullptr, options, &objval, epart.data(), npart.data());
    if (rc != METIS_OK)
        throw NumericalError(
            fmt::format("METIS_PartMeshDual could not partition {} cells into {} parts (code {})", n, parts, rc));
    for (size_t i = 0; i < n; ++i) owner[i] = int(epart[i]);
    return owner;
}

}  // namespace ma
