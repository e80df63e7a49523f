#include "contact/ActiveSetHistory.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "contact/ContactTerms.hpp"
#include "mesh/Mesh.hpp"
#include "xfem/Crack.hpp"
#include "xfem/XfemModel.hpp"

namespace ma::contact {

ActiveSetHistory::ActiveSetHistory(std::vector<char> initial)
    : changes_(initial.size(), 0), changedLast_(initial.size(), 0) {
    sets_.push_back(std::move(initial));
}

ActiveSetHistory::Step ActiveSetHistory::record(const std::vector<char>& statuses) {
    Step step;
    const std::vector<char>& previous = sets_.back();
    for (size_t p = 0; p < statuses.size(); ++p) {
        changedLast_[p] = statuses[p] != previous[p];
        if (!changedLast_[p]) continue;
        ++changes_[p];
        (statuses[p] ? step.activated : step.released) += 1;
    }
    if (step.activated + step.released > 0)
        for (size_t k = 0; k < sets_.size(); ++k)
            if (sets_[k] == statuses) step.repeats = static_cast<int>(k);
    sets_.push_back(statuses);
    return step;
}

std::string ActiveSetHistory::flippingPoints(const ContactTerms& terms, const std::vector<double>& u, int limit) const {
    std::vector<int> points;
    for (size_t p = 0; p < changes_.size(); ++p)
        if (changes_[p] > 1) points.push_back(static_cast<int>(p));
    std::string out = " Points whose status changed more than once:";
    if (points.empty()) {
        out = " Points whose status changed at the last update:";
        for (size_t p = 0; p < changes_.size(); ++p)
            if (changedLast_[p]) points.push_back(static_cast<int>(p));
    }
    std::stable_sort(points.begin(), points.end(),
                     [&](int a, int b) { return changes_[size_t(a)] > changes_[size_t(b)]; });

    const auto& xm = terms.definition().xfemModel();
    const Mesh& mesh = xm.mesh();
    const int shown = std::min<int>(limit, static_cast<int>(points.size()));
    for (int i = 0; i < shown; ++i) {
        const int p = points[size_t(i)];
        const ContactPoint& cp = terms.points()[size_t(p)];
        const ContactFacet& facet = terms.facets()[size_t(cp.facet)];
        std::string cells = mesh.cellNames[size_t(facet.minus.cell)];
        if (facet.plus.cell != facet.minus.cell) cells += " / " + mesh.cellNames[size_t(facet.plus.cell)];
        const StatusFunction f = terms.statusFunction(p, u);
        out += fmt::format(
            "\n  {} point at ({:.6g}, {:.6g}, {:.6g}), facet in cell {}: {} status change(s), now {}, gap "
            "{:.3e}, contact function {:.3e} (sum of its terms' magnitudes {:.3e}), block fractions {:.3g} / {:.3g}",
            xm.cracks()[size_t(facet.crack)]->name, cp.xyz[0], cp.xyz[1], cp.xyz[2], cells, changes_[size_t(p)],
            terms.active()[size_t(p)] ? "active" : "inactive", terms.gap(p, u), f.value, f.magnitude,
            facet.minus.blockMeasure / facet.minus.cellMeasure, facet.plus.blockMeasure / facet.plus.cellMeasure);
    }
    if (static_cast<int>(points.size()) > shown)
        out += fmt::format("\n  ... and {} other point(s)", static_cast<int>(points.size()) - shown);
    return out;
}

}  // namespace ma::contact
