// DEFI_FONCTION: a piecewise-linear function of one parameter (commands_spec §7.5).
#include "core/Function.hpp"
#include "core/Messages.hpp"
#include "parser/CommandRegistry.hpp"

namespace ma {
namespace {

char extension(const std::string& prol) { return prol == "CONSTANT" ? 'C' : prol == "LINEAIRE" ? 'L' : 'E'; }

ConceptPtr defiFonction(const KeywordSet& kw, CommandContext&) {
    auto f = std::make_shared<TabulatedFunction>();
    f->parameter_ = {kw.text("NOM_PARA")};
    const auto vale = kw.reals("VALE");
    if (vale.size() < 2 || vale.size() % 2 != 0)
        throw UserError("DEFI_FONCTION: VALE must hold pairs x1, y1, x2, y2, ... (got " + std::to_string(vale.size()) +
                        " numbers)");
    for (size_t i = 0; i < vale.size(); i += 2) {
        f->x.push_back(vale[i]);
        f->y.push_back(vale[i + 1]);
    }
    for (size_t i = 1; i < f->x.size(); ++i)
        if (!(f->x[i] > f->x[i - 1]))
            throw UserError("DEFI_FONCTION: the abscissas of VALE must be strictly increasing");
    if (kw.text("INTERPOL") != "LIN")
        throw NotImplemented("DEFI_FONCTION: INTERPOL other than 'LIN' is not supported by miniaster");
    f->leftExtension = extension(kw.text("PROL_GAUCHE"));
    f->rightExtension = extension(kw.text("PROL_DROITE"));
    msg().infof("    function of {} with {} points", f->parameter_[0], f->x.size());
    return f;
}

MA_REGISTER_COMMAND("DEFI_FONCTION", defiFonction);

}  // namespace
}  // namespace ma
