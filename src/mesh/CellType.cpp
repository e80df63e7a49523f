#include "mesh/CellType.hpp"

#include <array>
#include <utility>

namespace ma {

namespace {
struct Names {
    CellType type;
    const char* aster;
    const char* med;
};
constexpr std::array<Names, 20> kNames{{
    {CellType::POI1, "POI1", "PO1"},      {CellType::SEG2, "SEG2", "SE2"},       {CellType::SEG3, "SEG3", "SE3"},
    {CellType::SEG4, "SEG4", "SE4"},      {CellType::TRIA3, "TRIA3", "TR3"},     {CellType::QUAD4, "QUAD4", "QU4"},
    {CellType::TRIA6, "TRIA6", "TR6"},    {CellType::TRIA7, "TRIA7", "TR7"},     {CellType::QUAD8, "QUAD8", "QU8"},
    {CellType::QUAD9, "QUAD9", "QU9"},    {CellType::TETRA4, "TETRA4", "TE4"},   {CellType::PYRA5, "PYRAM5", "PY5"},
    {CellType::PENTA6, "PENTA6", "PE6"},  {CellType::HEXA8, "HEXA8", "HE8"},     {CellType::TETRA10, "TETRA10", "T10"},
    {CellType::PYRA13, "PYRAM13", "P13"}, {CellType::PENTA15, "PENTA15", "P15"}, {CellType::PENTA18, "PENTA18", "P18"},
    {CellType::HEXA20, "HEXA20", "H20"},  {CellType::HEXA27, "HEXA27", "H27"},
}};
}  // namespace

std::string cellTypeName(CellType t) {
    for (const auto& n : kNames)
        if (n.type == t) return n.aster;
    return "UNKNOWN" + std::to_string(static_cast<int>(t));
}

bool cellTypeFromName(const std::string& name, CellType& out) {
    for (const auto& n : kNames) {
        if (name == n.aster || name == n.med) {
            out = n.type;
            return true;
        }
    }
    return false;
}

}  // namespace ma
