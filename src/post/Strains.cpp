#include "post/Strains.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"
#include "fe/ResultFields.hpp"

namespace ma::post {

namespace {

const Result& checked(const Result& result, const MaterialField* material) {
    if (!result.model) throw UserError(fmt::format("result {} has no model to compute strains on", result.name));
    if (!material)
        throw UserError(
            fmt::format("result {} has no material field to compute strains with: give CHAM_MATER "
                        "(a material field on the result's mesh {})",
                        result.name, result.mesh ? result.mesh->name : std::string("?")));
    if (material->mesh != result.mesh)
        throw UserError(fmt::format("CHAM_MATER {} is not defined on the mesh {} of result {}", material->name,
                                    result.mesh ? result.mesh->name : std::string("?"), result.name));
    return result;
}

}  // namespace

Strains::Strains(const Result& result, std::shared_ptr<const MaterialField> material)
    : result_(checked(result, material.get())), space_(result.model, std::move(material), {}) {}

std::shared_ptr<GaussField> Strains::atPoints(const ResultStep& step) const {
    const auto depl = step.nodal("DEPL");
    if (!depl)
        throw UserError(
            fmt::format("result {} has no DEPL at NUME_ORDRE {} (the displacement the strains are "
                        "computed from)",
                        result_.name, step.order));
    return strainField(space_, space_.numbering().fromNodalField(*depl));
}

}  // namespace ma::post
