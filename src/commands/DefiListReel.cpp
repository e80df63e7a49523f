// DEFI_LIST_REEL: VALE=list, or DEBUT + INTERVALLE=_F(JUSQU_A, NOMBRE | PAS) (commands_spec §7.6).
#include <cmath>

#include "core/Function.hpp"
#include "core/MemoryLimit.hpp"
#include "core/Messages.hpp"
#include "parser/CommandRegistry.hpp"

namespace ma {
namespace {

ConceptPtr defiListReel(const KeywordSet& kw, CommandContext&) {
    auto list = std::make_shared<RealList>();
    if (kw.has("VALE")) {
        list->values = kw.reals("VALE");
    } else {
        double current = kw.real("DEBUT");
        list->values.push_back(current);
        for (const auto& interval : kw.factor("INTERVALLE")) {
            const double end = interval.real("JUSQU_A");
            long long steps = 0;
            if (interval.has("NOMBRE")) {
                steps = interval.integer("NOMBRE");
            } else {
                const double pas = interval.real("PAS");
                steps = std::llround((end - current) / pas);
                if (steps <= 0 || std::abs(current + static_cast<double>(steps) * pas - end) > 1e-6 * std::abs(pas))
                    throw UserError(interval.pathOf("PAS") + ": the interval is not a whole number of steps");
            }
            if (steps <= 0) throw UserError(interval.pathOf("NOMBRE") + " must be positive");
            checkAllocation(double(list->values.size() + size_t(steps)) * sizeof(double),
                            fmt::format("{} ({} instants)", interval.pathOf(interval.has("NOMBRE") ? "NOMBRE" : "PAS"),
                                        steps));
            list->values.reserve(list->values.size() + size_t(steps));
            const double start = current;
            for (long long i = 1; i <= steps; ++i)
                list->values.push_back(i == steps ? end : start + (end - start) * double(i) / double(steps));
            current = end;
        }
    }
    for (size_t i = 1; i < list->values.size(); ++i)
        if (!(list->values[i] > list->values[i - 1]))
            throw UserError("DEFI_LIST_REEL: the values must be strictly increasing");
    msg().infof("    {} instants from {} to {}", list->values.size(), list->values.front(), list->values.back());
    return list;
}

MA_REGISTER_COMMAND("DEFI_LIST_REEL", defiListReel);

}  // namespace
}  // namespace ma
