#pragma once
// DEFI_MATERIAU (mater_sdaster) and AFFE_MATERIAU (cham_mater): isotropic linear elasticity.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/Concept.hpp"
#include "core/Message.hpp"
#include "mesh/Mesh.hpp"

namespace ma {

class Model;
class MaterialField;

class Material : public Concept {
public:
    std::string typeName() const override { return "mater_sdaster"; }
    double E = 0.0;
    double nu = 0.0;
    bool hasRho = false;
    double rho = 0.0;
};

// Nothing for an ordinary material; else why Hooke's law is near its limit (NU close to 0.5:
// nearly incompressible, or to -1), which makes the stiffness matrix singular to working precision.
// `where` heads the text: the keyword path, or "material M".
std::optional<FormattedMessage> nearlyDegenerateElasticity(const Material& m, const std::string& where);
// The materials of `field` that are nearly degenerate, as the likely cause of a singular system ("" when none).
std::string degenerateMaterialCause(const MaterialField& field);

class MaterialField : public Concept {
public:
    std::string typeName() const override { return "cham_mater"; }
    std::shared_ptr<const Mesh> mesh;
    std::shared_ptr<const Model> model;  // when MODELE was given
    // Material of each mesh cell (null where AFFE assigned none).
    std::vector<std::shared_ptr<const Material>> cellMaterial;

    // Material of `cell`; UserError naming the cell when none was assigned.
    const Material& at(int cell) const;
};

}  // namespace ma
