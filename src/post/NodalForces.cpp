#include "post/NodalForces.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/Error.hpp"
#include "fe/ExternalForces.hpp"
#include "fe/InternalForces.hpp"
#include "fe/MechanicalLoad.hpp"

namespace ma::post {

namespace {

const Result& checked(const Result& result) {
    if (!result.model || !result.material)
        throw UserError(
            fmt::format("result {} has no model and material to compute nodal forces on (CALC_CHAMP "
                        "FORCE needs the result of MECA_STATIQUE or STAT_NON_LINE)",
                        result.name));
    return result;
}

std::vector<int> flaggedOnly(const std::vector<int>& cells, const std::vector<char>& flags) {
    std::vector<int> out;
    std::copy_if(cells.begin(), cells.end(), std::back_inserter(out), [&](int c) { return flags[size_t(c)] != 0; });
    return out;
}

// Each load with its pressures and forces on the flagged cells only.
std::vector<LoadCase> restrictLoads(const std::vector<LoadCase>& loads, const std::vector<char>& cells) {
    if (std::all_of(cells.begin(), cells.end(), [](char c) { return c != 0; })) return loads;
    std::vector<LoadCase> out;
    for (const auto& lc : loads) {
        auto load = std::make_shared<MechanicalLoad>(*lc.load);
        for (auto& p : load->pressures) p.cells = flaggedOnly(p.cells, cells);
        for (auto& v : load->volumeForces) v.cells = flaggedOnly(v.cells, cells);
        for (auto& f : load->surfaceForces) f.cells = flaggedOnly(f.cells, cells);
        for (auto& l : load->lipPressures) l.onlyCells = cells;
        out.push_back({std::move(load), lc.multiplier});
    }
    return out;
}

}  // namespace

NodalForces::NodalForces(const Result& result, const std::vector<LoadCase>& loads, const std::vector<char>& cells)
    : result_(checked(result)),
      space_(result.model, result.material, ExtraUnknowns{}),
      cells_(cells),
      loads_(restrictLoads(loads, cells)) {}

std::vector<double> NodalForces::elementForces(const ResultStep& step) const {
    const auto depl = step.nodal("DEPL");
    if (!depl)
        throw UserError(
            fmt::format("result {} has no DEPL at NUME_ORDRE {} (the displacement the nodal forces "
                        "are computed from)",
                        result_.name, step.order));
    std::vector<double> f;
    assembleInternalForces(space_, space_.numbering().fromNodalField(*depl), f, &cells_);
    return f;
}

std::shared_ptr<NodalField> NodalForces::toField(const std::vector<double>& f) const {
    auto field = space_.numbering().toNodalField(f, result_.mesh);
    field->quantity = "DEPL_R";  // code_aster's FORC_NODA and REAC_NODA are DEPL_R fields
    return field;
}

std::shared_ptr<NodalField> NodalForces::internalForces(const ResultStep& step) const {
    return toField(elementForces(step));
}

std::shared_ptr<NodalField> NodalForces::reactions(const ResultStep& step) const {
    auto f = elementForces(step);
    std::vector<double> fext;
    assembleExternalForces(space_, loads_, step.inst, fext);
    for (size_t i = 0; i < f.size(); ++i) f[i] -= fext[i];
    return toField(f);
}

}  // namespace ma::post
