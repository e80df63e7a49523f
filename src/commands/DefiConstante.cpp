// DEFI_CONSTANTE: a constant function (code_aster: NOM_PARA 'TOUTPARA', any parameter).
#include "core/Function.hpp"
#include "core/Messages.hpp"
#include "parser/CommandRegistry.hpp"

namespace ma {
namespace {

ConceptPtr defiConstante(const KeywordSet& kw, CommandContext&) {
    auto f = std::make_shared<ConstantFunction>();
    f->value = kw.real("VALE");
    msg().infof("    constant function, value {}", f->value);
    return f;
}

MA_REGISTER_COMMAND("DEFI_CONSTANTE", defiConstante);

}  // namespace
}  // namespace ma
