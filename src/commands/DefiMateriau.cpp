// DEFI_MATERIAU: isotropic linear elasticity ELAS (E, NU, RHO) (commands_spec §8.4).
#include <fmt/format.h>

#include "core/Messages.hpp"
#include "fe/Material.hpp"
#include "parser/CommandRegistry.hpp"

namespace ma {
namespace {

ConceptPtr defiMateriau(const KeywordSet& kw, CommandContext&) {
    const auto& elas = kw.factor("ELAS");
    if (elas.empty()) throw NotImplemented("DEFI_MATERIAU: miniaster needs ELAS (linear isotropic elasticity)");
    const KeywordSet& e = elas.front();
    auto m = std::make_shared<Material>();
    m->E = e.real("E");
    m->nu = e.real("NU");
    // code_aster's catalogue admits the bounds E = 0 and NU = -1, where Hooke's law has no stiffness
    // or an infinite shear modulus: refused here with that cause, rather than as a singular system.
    // NU = 0.5 is valid in plane stress (C_PLAN); the 3D and D_PLAN laws refuse it (IsotropicLaw).
    if (!(m->E > 0.0))
        throw UserError(
            fmt::format("{} = {}: Young's modulus must be > 0 (a material without stiffness makes the "
                        "stiffness matrix singular)",
                        e.pathOf("E"), m->E));
    if (!(m->nu > -1.0 && m->nu <= 0.5))
        throw UserError(
            fmt::format("{} = {}: Poisson's ratio must lie in ]-1, 0.5] (at NU = -1 the shear modulus "
                        "E/(2(1+NU)) is infinite)",
                        e.pathOf("NU"), m->nu));
    if (const auto near = nearlyDegenerateElasticity(*m, e.pathOf("NU"))) msg().alarm(*near);
    if (e.has("RHO")) m->hasRho = true, m->rho = e.real("RHO");
    msg().infof("    ELAS: E = {}, NU = {}{}", m->E, m->nu, m->hasRho ? fmt::format(", RHO = {}", m->rho) : "");
    return m;
}

MA_REGISTER_COMMAND("DEFI_MATERIAU", defiMateriau);

}  // namespace
}  // namespace ma
