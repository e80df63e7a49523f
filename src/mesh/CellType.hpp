#pragma once
// Cell types, numbered with MED's geometry codes (so that sorting by code gives code_aster's
// cell numbering). Node order inside a cell is code_aster's internal order (= VTK/gmsh for the
// linear 3D cells); med_io converts from/to MED's order.
#include <string>

namespace ma {

enum class CellType : int {
    POI1 = 1,
    SEG2 = 102,
    SEG3 = 103,
    SEG4 = 104,
    TRIA3 = 203,
    QUAD4 = 204,
    TRIA6 = 206,
    TRIA7 = 207,
    QUAD8 = 208,
    QUAD9 = 209,
    TETRA4 = 304,
    PYRA5 = 305,
    PENTA6 = 306,
    HEXA8 = 308,
    TETRA10 = 310,
    PYRA13 = 313,
    PENTA15 = 315,
    PENTA18 = 318,
    HEXA20 = 320,
    HEXA27 = 327,
};

inline int nodeCount(CellType t) { return static_cast<int>(t) % 100; }
// Topological dimension: 0 point, 1 segment, 2 face, 3 volume.
inline int cellDimension(CellType t) { return static_cast<int>(t) / 100; }
// code_aster's name: "QUAD4", "PYRAM5" ...
std::string cellTypeName(CellType t);
// Parse a code_aster or MED short name ("QUAD4", "QU4"); returns false when unknown.
bool cellTypeFromName(const std::string& name, CellType& out);

}  // namespace ma
