#include "fe/ClassicalElement.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"

namespace ma::classical {

const Tria3& tria3() {
    static const Tria3 ref(CellType::TRIA3);
    return ref;
}

const Quad4& quad4() {
    static const Quad4 ref(CellType::QUAD4);
    return ref;
}

const Tetra4& tetra4() {
    static const Tetra4 ref(CellType::TETRA4);
    return ref;
}

const Hexa8& hexa8() {
    static const Hexa8 ref(CellType::HEXA8);
    return ref;
}

void badJacobian(const Mesh& mesh, int cell, double det) {
    throw NumericalError(fmt::format(
        "cell {} ({}) is degenerate: its Jacobian ({:.3e}) is round-off for its size (coincident or aligned nodes, "
        "or non-finite coordinates)",
        mesh.cellNames[cell], cellTypeName(mesh.cellTypes[cell]), det));
}

}  // namespace ma::classical
