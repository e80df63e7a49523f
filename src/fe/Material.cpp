#include "fe/Material.hpp"

#include "core/Error.hpp"

namespace ma {

const Material& MaterialField::at(int cell) const {
    if (cell < 0 || cell >= static_cast<int>(cellMaterial.size()) || !cellMaterial[cell]) {
        const std::string cellName = mesh && cell >= 0 && cell < mesh->cellCount() ? mesh->cellNames[cell] : std::to_string(cell);
        throw UserError("the material field " + name + " assigns no material to cell " + cellName +
                        ", which carries a finite element of the model (AFFE_MATERIAU/AFFE)");
    }
    return *cellMaterial[cell];
}

}  // namespace ma
