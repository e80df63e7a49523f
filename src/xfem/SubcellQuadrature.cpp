#include "xfem/SubcellQuadrature.hpp"

#include <fmt/format.h>

#include <array>

#include "core/Error.hpp"
#include "fe/Quadrature.hpp"

namespace ma::xfem {

std::string catalogueSubcellRule(const SubcellKind& kind) {
    if (kind.skin) {
        if (kind.dim == 1) return kind.severalCracks ? "FPG2" : "FPG4";
        return "FPG12";
    }
    if (kind.dim == 2) return kind.severalCracks ? "FPG4" : "FPG12";
    return kind.severalCracks ? "FPG5" : "FPG15";
}

std::string lowestRuleOfDegree(CellType simplex, int degree) {
    if (degree < 1 || degree > kMaxSubcellDegree)
        throw UserError(fmt::format("sub-cell quadrature degree {} is outside 1..{}", degree, kMaxSubcellDegree));
    // code_aster's families of the simplex that miniaster has, in increasing degree.
    static const std::array<const char*, 6> triangle{"FPG1", "FPG3", "FPG4", "FPG6", "FPG7", "FPG12"};
    static const std::array<const char*, 5> tetrahedron{"FPG1", "FPG4", "FPG5", "FPG15", "FPG24"};
    auto pick = [&](const auto& families) -> std::string {
        for (const char* f : families)
            if (quadratureRule(simplex, f).degree >= degree) return f;
        throw UserError(fmt::format("no {} integration rule of degree {} in miniaster", cellTypeName(simplex), degree));
    };
    if (simplex == CellType::TRIA3) return pick(triangle);
    if (simplex == CellType::TETRA4) return pick(tetrahedron);
    throw InternalError("lowestRuleOfDegree: " + cellTypeName(simplex) + " is not a volume sub-cell");
}

std::string subcellRule(const SubcellKind& kind, int degree) {
    if (degree == 0 || kind.skin) return catalogueSubcellRule(kind);
    return lowestRuleOfDegree(subcellType(kind), degree);
}

int strainDegree(CellType parent) {
    switch (parent) {
        case CellType::QUAD4: return 1;  // dN/dx: linear
        case CellType::HEXA8: return 2;  // dN/dx: bilinear
        default: return 0;               // simplices: constant
    }
}

CellType subcellType(const SubcellKind& kind) {
    return kind.dim == 1 ? CellType::SEG2 : (kind.dim == 2 ? CellType::TRIA3 : CellType::TETRA4);
}

}  // namespace ma::xfem
