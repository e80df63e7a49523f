#include "fe/DirichletConstraints.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"
#include "fe/Enrichment.hpp"

namespace ma {

bool DirichletConstraints::sameStructure(const DirichletConstraints& o) const {
    if (fixed != o.fixed || multi.size() != o.multi.size()) return false;
    for (size_t m = 0; m < multi.size(); ++m) {
        if (multi[m].terms.size() != o.multi[m].terms.size()) return false;
        for (size_t t = 0; t < multi[m].terms.size(); ++t)
            if (multi[m].terms[t] != o.multi[m].terms[t]) return false;
    }
    return true;
}

namespace {

// Builds the constraints step by step; `multiTerm`/`multiTerms` hold the relations with several
// terms (on dofs, merged and sorted) until the eliminated values are substituted.
class ConstraintsBuilder {
public:
    ConstraintsBuilder(const Discretisation& space, int total) : space_(space), mesh_(space.mesh()) {
        out_.fixed.assign(total, 0);
        out_.fixedValue.assign(total, 0.0);
    }

    // Inactive Heaviside slots (Enrichment::inactiveSlots, xfem_spec §3.9): fixed to 0 first, so
    // that a user condition giving them another value is reported as a conflict.
    void fixInactiveSlots() {
        const Model& model = space_.model();
        if (!model.enrichment) return;
        for (const auto& [node, slot] : model.enrichment->inactiveSlots())
            for (int comp = 0; comp < space_.dim(); ++comp) {
                const int d = space_.numbering().dof(node, slot, comp);
                if (d >= 0) out_.fixed[d] = 1, out_.fixedValue[d] = 0.0;
            }
    }

    void add(const LinearRelation& rel) {
        const auto terms = dofTerms(rel);
        if (terms.empty()) return;
        if (terms.size() == 1) {
            fix(terms[0].first, rel.value / terms[0].second);
        } else {
            multiTerm_.push_back(&rel);
            multiTerms_.push_back(terms);
        }
    }

    // Enriched dofs no element uses: neutralised (value 0), as code_aster's xteddl.
    void neutraliseUnattached() {
        const DofNumbering& numbering = space_.numbering();
        out_.unattached = 0;
        for (int d = 0; d < numbering.size(); ++d)
            if (!space_.attached(d) && !out_.fixed[d]) {
                int slot = 0, comp = 0;
                if (parseDisplacementComponent(numbering.componentOf(d), slot, comp) && slot > 0) {
                    out_.fixed[d] = 1;
                    ++out_.unattached;
                }
            }
    }

    DirichletConstraints finish() {
        const int total = static_cast<int>(out_.fixed.size());
        out_.eq.assign(total, -1);
        out_.freeCount = 0;
        for (int d = 0; d < total; ++d)
            if (!out_.fixed[d]) out_.eq[d] = out_.freeCount++;
        for (size_t m = 0; m < multiTerm_.size(); ++m) substituteFixed(*multiTerm_[m], multiTerms_[m]);
        return std::move(out_);
    }

private:
    std::string describe(int dof) const {
        const DofNumbering& numbering = space_.numbering();
        return fmt::format("{} of node {}", numbering.componentOf(dof), mesh_.nodeNames[numbering.nodeOf(dof)]);
    }

    // The relation's terms on dofs, equal dofs merged, zero coefficients dropped, sorted.
    std::vector<std::pair<int, double>> dofTerms(const LinearRelation& rel) const {
        std::vector<std::pair<int, double>> terms;
        for (const auto& t : rel.terms) {
            const int d = space_.numbering().dofOf(t.node, t.component);
            if (d < 0)
                throw UserError(fmt::format("a linear relation uses {} of node {}, which the model {} does not carry",
                                            t.component, mesh_.nodeNames[t.node], space_.model().name));
            auto it = std::find_if(terms.begin(), terms.end(), [&](const auto& p) { return p.first == d; });
            if (it == terms.end()) terms.emplace_back(d, t.coef);
            else it->second += t.coef;
        }
        std::erase_if(terms, [](const auto& p) { return p.second == 0.0; });
        if (terms.size() > 1) std::sort(terms.begin(), terms.end());
        return terms;
    }

    void fix(int d, double v) {
        if (out_.fixed[d] &&
            std::abs(out_.fixedValue[d] - v) > 1e-12 * std::max(std::abs(v), std::abs(out_.fixedValue[d])))
            throw UserError(fmt::format("conflicting Dirichlet conditions: {} is imposed to {} and to {}", describe(d),
                                        out_.fixedValue[d], v));
        out_.fixed[d] = 1;
        out_.fixedValue[d] = v;
    }

    // Values of eliminated dofs move to the right-hand side; a relation left without free dof must
    // hold already.
    void substituteFixed(const LinearRelation& rel, const std::vector<std::pair<int, double>>& terms) {
        DirichletConstraints::Relation r;
        r.value = rel.value;
        for (const auto& [d, c] : terms) {
            if (out_.fixed[d]) r.value -= c * out_.fixedValue[d];
            else r.terms.emplace_back(d, c);
        }
        if (r.terms.empty()) {
            if (std::abs(r.value) > 1e-10 * std::max(1.0, std::abs(rel.value)))
                throw UserError(fmt::format("a linear relation on {} contradicts the imposed values of its dofs",
                                            describe(terms[0].first)));
            return;
        }
        out_.multi.push_back(std::move(r));
    }

    const Discretisation& space_;
    const Mesh& mesh_;
    DirichletConstraints out_;
    std::vector<const LinearRelation*> multiTerm_;
    std::vector<std::vector<std::pair<int, double>>> multiTerms_;
};

}  // namespace

DirichletConstraints buildDirichletConstraints(const Discretisation& space, const std::vector<LoadCase>& loads,
                                               double inst, int extraUnknowns) {
    std::vector<LinearRelation> relations;
    for (const auto& lc : loads) {
        const size_t before = relations.size();
        lc.load->appendRelations(inst, relations);
        const double factor = lc.factor(inst);
        for (size_t r = before; r < relations.size(); ++r) relations[r].value *= factor;
    }
    ConstraintsBuilder builder(space, space.numbering().size() + extraUnknowns);
    builder.fixInactiveSlots();
    for (const auto& rel : relations) builder.add(rel);
    builder.neutraliseUnattached();
    return builder.finish();
}

}  // namespace ma
