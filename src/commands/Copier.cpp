// COPIER: a copy of a mesh, a table, a function, a list of reals, a model or a result (every
// concept of code_aster's COPIER list that miniaster has). Later commands on the copy (DEFI_GROUP
// reuse, CALC_TABLE reuse, CALC_CHAMP reuse) leave the original as it was, as in code_aster; a
// model or result copy refers to the same mesh, model and material as the original, as there.
#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/Function.hpp"
#include "core/Messages.hpp"
#include "fe/Model.hpp"
#include "fe/Result.hpp"
#include "mesh/Mesh.hpp"
#include "parser/CommandRegistry.hpp"
#include "post/Table.hpp"

namespace ma {
namespace {

template <class T>
ConceptPtr copyAs(const ConceptPtr& original) {
    auto typed = std::dynamic_pointer_cast<const T>(original);
    return typed ? std::make_shared<T>(*typed) : nullptr;
}

ConceptPtr copier(const KeywordSet& kw, CommandContext&) {
    const ConceptPtr original = kw.rawObject("CONCEPT");
    ConceptPtr copy;
    for (auto make : {copyAs<Mesh>, copyAs<Table>, copyAs<TabulatedFunction>, copyAs<ConstantFunction>,
                      copyAs<RealList>, copyAs<Model>, copyAs<Result>})
        if (!copy) copy = make(original);
    if (!copy)
        throw NotImplemented(fmt::format("{}: COPIER of a {} ({}) is not supported", kw.pathOf("CONCEPT"),
                                         original->typeName(), original->name));
    copy->name.clear();
    msg().infof("    copy of {} ({})", original->name, original->typeName());
    return copy;
}

MA_REGISTER_COMMAND("COPIER", copier);

}  // namespace
}  // namespace ma
