#include "med_io/MedCellOrder.hpp"

#include <algorithm>
#include <array>
#include <vector>

namespace ma::med {

namespace {
// 1-based tables, as in code_aster's lrmtyp (NUMNOA: MED number of the j-th internal node).
// MED orients the first face of a volume outward, code_aster (= VTK/gmsh for linear cells)
// inward: the vertices of the first face are reversed; mid-edge nodes follow their edges.
// Internal quadratic volumes list bottom edges, then vertical edges, then top edges; MED lists
// bottom, top, then vertical edges.
constexpr std::array<int, 4> kTetra4{1, 3, 2, 4};
constexpr std::array<int, 10> kTetra10{1, 3, 2, 4, 7, 6, 5, 8, 10, 9};
constexpr std::array<int, 5> kPyra5{1, 4, 3, 2, 5};
constexpr std::array<int, 13> kPyra13{1, 4, 3, 2, 5, 9, 8, 7, 6, 10, 13, 12, 11};
constexpr std::array<int, 6> kPenta6{1, 3, 2, 4, 6, 5};
constexpr std::array<int, 15> kPenta15{1, 3, 2, 4, 6, 5, 9, 8, 7, 13, 15, 14, 12, 11, 10};
// PENTA18 is absent from the lrmtyp version we read: derived from PENTA15 plus the quadrangle
// face centres, MED faces (1,2,5,4) (2,3,6,5) (3,1,4,6) -> internal faces in the same edge
// order after the vertex swap 2<->3, 5<->6 (see docs/med.md).
constexpr std::array<int, 18> kPenta18{1, 3, 2, 4, 6, 5, 9, 8, 7, 13, 15, 14, 12, 11, 10, 18, 17, 16};
constexpr std::array<int, 8> kHexa8{1, 4, 3, 2, 5, 8, 7, 6};
constexpr std::array<int, 20> kHexa20{1, 4, 3, 2, 5, 8, 7, 6, 12, 11, 10, 9, 17, 20, 19, 18, 16, 15, 14, 13};
constexpr std::array<int, 27> kHexa27{1,  4,  3,  2,  5,  8,  7,  6,  12, 11, 10, 9,  17, 20,
                                      19, 18, 16, 15, 14, 13, 21, 25, 24, 23, 22, 26, 27};

struct Table {
    CellType type;
    std::vector<int> order;  // 0-based
};

std::vector<Table> buildTables() {
    auto make = [](CellType t, std::span<const int> oneBased) {
        Table tab{t, {}};
        for (int v : oneBased) tab.order.push_back(v - 1);
        return tab;
    };
    return {make(CellType::TETRA4, kTetra4),   make(CellType::TETRA10, kTetra10), make(CellType::PYRA5, kPyra5),
            make(CellType::PYRA13, kPyra13),   make(CellType::PENTA6, kPenta6),   make(CellType::PENTA15, kPenta15),
            make(CellType::PENTA18, kPenta18), make(CellType::HEXA8, kHexa8),     make(CellType::HEXA20, kHexa20),
            make(CellType::HEXA27, kHexa27)};
}

const std::vector<Table>& tables() {
    static const std::vector<Table> t = buildTables();
    return t;
}
}  // namespace

std::span<const int> medNodeOf(CellType t) {
    for (const auto& tab : tables())
        if (tab.type == t) return tab.order;
    return {};
}

void medToInternal(CellType t, std::span<const int> med, std::span<int> internal) {
    auto order = medNodeOf(t);
    if (order.empty()) {
        std::copy(med.begin(), med.end(), internal.begin());
        return;
    }
    for (size_t j = 0; j < order.size(); ++j) internal[j] = med[order[j]];
}

void internalToMed(CellType t, std::span<const int> internal, std::span<int> med) {
    auto order = medNodeOf(t);
    if (order.empty()) {
        std::copy(internal.begin(), internal.end(), med.begin());
        return;
    }
    for (size_t j = 0; j < order.size(); ++j) med[order[j]] = internal[j];
}

}  // namespace ma::med
