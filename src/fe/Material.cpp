#include "fe/Material.hpp"

#include <fmt/format.h>

#include <set>

#include "core/Error.hpp"

namespace ma {

namespace {
// Beyond this ratio of the Lame coefficients (lambda/mu = 2 NU/(1-2NU), or mu's blow-up at NU -> -1)
// the elasticity equations lose about six digits of the sixteen a double has.
constexpr double kDegenerateGap = 1e-6;
}  // namespace

std::string nearlyDegenerateElasticity(const Material& m) {
    if (1.0 - 2.0 * m.nu < kDegenerateGap && m.nu < 0.5)
        return fmt::format("NU = {} is nearly incompressible in 3D and plane strain (1 - 2 NU = {:.1e}, "
                           "lambda/mu = {:.1e}): the stiffness matrix is singular to working precision "
                           "(displacement elements lock); use NU <= 0.4999",
                           m.nu, 1.0 - 2.0 * m.nu, 2.0 * m.nu / (1.0 - 2.0 * m.nu));
    if (1.0 + m.nu < kDegenerateGap)
        return fmt::format("NU = {} is close to -1 (1 + NU = {:.1e}): the shear modulus E/(2(1+NU)) is nearly "
                           "infinite and the stiffness matrix singular to working precision",
                           m.nu, 1.0 + m.nu);
    return {};
}

std::string degenerateMaterialCause(const MaterialField& field) {
    std::set<const Material*> seen;
    std::string out;
    for (const auto& m : field.cellMaterial) {
        if (!m || !seen.insert(m.get()).second) continue;
        const std::string near = nearlyDegenerateElasticity(*m);
        if (!near.empty()) out += (out.empty() ? "" : "; ") + fmt::format("material {}: {}", m->name, near);
    }
    return out;
}

const Material& MaterialField::at(int cell) const {
    if (cell < 0 || cell >= static_cast<int>(cellMaterial.size()) || !cellMaterial[cell]) {
        const std::string cellName = mesh && cell >= 0 && cell < mesh->cellCount() ? mesh->cellNames[cell] : std::to_string(cell);
        throw UserError("the material field " + name + " assigns no material to cell " + cellName +
                        ", which carries a finite element of the model (AFFE_MATERIAU/AFFE)");
    }
    return *cellMaterial[cell];
}

}  // namespace ma
