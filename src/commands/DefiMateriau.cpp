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
    if (!(m->E >= 0.0)) throw UserError(fmt::format("{} = {} must be >= 0", e.pathOf("E"), m->E));
    if (!(m->nu >= -1.0 && m->nu <= 0.5))
        throw UserError(fmt::format("{} = {} must lie in [-1, 0.5]", e.pathOf("NU"), m->nu));
    if (e.has("RHO")) m->hasRho = true, m->rho = e.real("RHO");
    msg().infof("    ELAS: E = {}, NU = {}{}", m->E, m->nu, m->hasRho ? fmt::format(", RHO = {}", m->rho) : "");
    return m;
}

MA_REGISTER_COMMAND("DEFI_MATERIAU", defiMateriau);

}  // namespace
}  // namespace ma
