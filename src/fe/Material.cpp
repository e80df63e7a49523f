#include "fe/Material.hpp"
#include "fe/FeMessages.hpp"

#include <fmt/format.h>

#include <set>

#include "core/Error.hpp"

namespace ma {

namespace {
// Beyond this ratio of the Lame coefficients (lambda/mu = 2 NU/(1-2NU), or mu's blow-up at NU -> -1)
// the elasticity equations lose about six digits of the sixteen a double has.
constexpr double kDegenerateGap = 1e-6;
}  // namespace

std::optional<FormattedMessage> nearlyDegenerateElasticity(const Material& m, const std::string& where) {
    if (1.0 - 2.0 * m.nu < kDegenerateGap && m.nu < 0.5)
        return formatted(MATERIAL_1_INCOMPRESSIBLE, where, m.nu, 1.0 - 2.0 * m.nu, 2.0 * m.nu / (1.0 - 2.0 * m.nu));
    if (1.0 + m.nu < kDegenerateGap) return formatted(MATERIAL_1_SHEAR_INFINITE, where, m.nu, 1.0 + m.nu);
    return std::nullopt;
}

std::string degenerateMaterialCause(const MaterialField& field) {
    std::set<const Material*> seen;
    std::string out;
    for (const auto& m : field.cellMaterial) {
        if (!m || !seen.insert(m.get()).second) continue;
        if (const auto near = nearlyDegenerateElasticity(*m, "material " + m->name))
            out += (out.empty() ? "" : "; ") + near->text;
    }
    return out;
}

const Material& MaterialField::at(int cell) const {
    if (cell < 0 || cell >= static_cast<int>(cellMaterial.size()) || !cellMaterial[cell]) {
        const std::string cellName =
            mesh && cell >= 0 && cell < mesh->cellCount() ? mesh->cellNames[cell] : std::to_string(cell);
        throw UserError("the material field " + name + " assigns no material to cell " + cellName +
                        ", which carries a finite element of the model (AFFE_MATERIAU/AFFE)");
    }
    return *cellMaterial[cell];
}

}  // namespace ma
