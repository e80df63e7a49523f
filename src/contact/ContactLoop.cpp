#include "contact/ContactLoop.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "contact/ActiveSetHistory.hpp"
#include "contact/ContactIntegration.hpp"
#include "contact/ContactMessages.hpp"
#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "xfem/Crack.hpp"
#include "xfem/XfemModel.hpp"

namespace ma::contact {

namespace {

// The facets whose zone rule ContactTerms replaced (RuleShortfall), one alarm CONTACT_INTEGRATION per
// cause: the user asked for another rule.
void announceReplacedRules(const ContactTerms& terms, const ContactDefinition& definition) {
    const auto& xm = definition.xfemModel();
    // A rule of lower degree than the traces of the shape functions on the facets (the vertex rule
    // on HEXA8 cells, or on QUAD4 cells cut off their grid lines) would integrate the contact terms
    // only approximately: consistent point by point, but a solution the elements represent exactly
    // would no longer be reproduced. ContactTerms integrates those facets with the lowest exact Gauss
    // rule instead; the user asked for another rule, so say it (docs/contact.md).
    // One alarm per rule and trace degree, naming the zones.
    std::map<std::pair<std::string, int>, std::vector<std::string>> weak;
    std::map<std::pair<std::string, int>, int> orders;
    for (size_t z = 0; z < definition.zones.size(); ++z) {
        const RuleShortfall& s = terms.ruleShortfalls()[z];
        if (s.replaced == 0) continue;
        const std::pair<std::string, int> key{describe(xm.dim(), definition.zones[z].integration), s.traceDegree};
        weak[key].push_back(fmt::format("{} ({} of {} facets)", definition.zones[z].crack->name, s.replaced, s.facets));
        orders[key] = std::max(orders[key], s.replacementOrder);
    }
    for (const auto& [key, zones] : weak) {
        const auto& [rule, traceDegree] = key;
        const int order = orders[key];
        msg().alarm(CONTACT_INTEGRATION_DEGREE, fmt::format("{}", fmt::join(zones, ", ")), traceDegree, rule, order,
                    xm.dim() == 2 ? "SE2" : "TR3", facetFamily(xm.dim(), ContactIntegration{"GAUSS", order}));
    }
    // A rule with a negative weight (3D ORDRE_INT=3, TR3 FPG4, centre weight -27/96) would give its
    // contact point a term concave in the point's pressure and an indefinite stabilisation on traces it
    // does not integrate exactly (the slanted HEXA8 facets of ssnv513g: one negative MUMPS pivot and an
    // active set cycling between 397 and 417 points; docs/contact.md).
    for (size_t z = 0; z < definition.zones.size(); ++z) {
        const RuleShortfall& s = terms.ruleShortfalls()[z];
        if (!s.negativeWeight) continue;
        const ContactIntegration replacement{"GAUSS", s.negativeWeightOrder};
        msg().alarm(CONTACT_INTEGRATION_NEGATIVE_WEIGHT, definition.zones[z].crack->name,
                    describe(xm.dim(), definition.zones[z].integration), s.facets, describe(xm.dim(), replacement));
    }
}

}  // namespace

std::shared_ptr<ContactTerms> attachContact(MechanicalProblem& problem, const MaterialField& material,
                                            std::shared_ptr<const ContactDefinition> definition) {
    if (definition->model.get() != &problem.model() && definition->model->enrichment != problem.model().enrichment)
        throw UserError(fmt::format("CONTACT: {} was defined on model {}, STAT_NON_LINE runs on model {}",
                                    definition->name, definition->model->name, problem.model().name));
    const auto& xm = definition->xfemModel();
    std::vector<char> withContact(xm.cracks().size(), 0);
    for (const auto& z : definition->zones) withContact[z.crackIndex] = 1;
    FacetStatistics stats;
    auto facets = buildContactFacets(xm, withContact, &stats);
    for (const auto& z : definition->zones) {
        int count = 0;
        double measure = 0.0;
        for (const auto& f : facets)
            if (f.crack == z.crackIndex) ++count, measure += f.measure;
        if (count == 0)
            throw UserError(
                fmt::format("DEFI_CONTACT zone on {}: the interface has no contact facet in the model "
                            "(it cuts no element of the model)",
                            z.crack->name));
        msg().infof("    contact zone {}: {} facets, interface {} {:.6g} ({})", z.crack->name, count,
                    xm.dim() == 2 ? "length" : "area", measure,
                    z.algorithm == ContactAlgorithm::Nitsche ? "Nitsche" : fmt::format("penalty {:.3e}", z.penalty));
    }
    msg().infof(
        "    contact facets: {} ({} touching a junction, {} between two parent cells, {} where the two sides' "
        "faces in a cell differ, {} facing a piece the cut dropped)",
        stats.facets, stats.atJunction, stats.acrossParentFaces, stats.clipped, stats.acrossDropped);
    // Interface faces that no face of the other side covers, even after ContactFacets' clipping and
    // block-across pairing (the two sides split the interface differently at a branch joined to it,
    // or the cut dropped a flat piece there; those pairings cover every face measured). No contact
    // term is written on what stays and the weak form misses that piece of interface: when the cut
    // still dropped real slivers the study (docs/study/stability.md) measured relative errors of 1 to
    // 100 times the missing fraction of the interface, hence the alarm from a fraction of 1e-11 on.
    double smallest = 1.0;
    for (const auto& f : facets)
        for (const FacetSide* side : {&f.minus, &f.plus})
            smallest = std::min(smallest, side->blockMeasure / std::max(side->cellMeasure, 1e-300));
    msg().infof("    contact facets: smallest block fraction of a cell next to a facet {:.3e}", smallest);
    const double missing = stats.unmatchedMeasure / std::max(stats.totalMeasure + stats.unmatchedMeasure, 1e-300);
    if (stats.unmatched > 0)
        msg().infof(
            "    contact facets: {} sub-cell face(s) on an interface inside their cell ({} {:.3e}, {:.1e} of the "
            "interfaces) have no sub-cell of the other side: no contact term on them",
            stats.unmatched, xm.dim() == 2 ? "length" : "area", stats.unmatchedMeasure, missing);
    constexpr double kMissingFraction = 1e-11;
    if (missing > kMissingFraction)
        msg().alarm(CONTACT_SLIVER, stats.unmatched, xm.dim() == 2 ? "total length" : "total area",
                    stats.unmatchedMeasure, missing);
    auto terms = std::make_shared<ContactTerms>(problem, material, definition, std::move(facets));
    if (terms->mergedPenaltyPoints() > 0)
        msg().infof(
            "    penalised contact: {} contact points ({} merged with a point of the same gap at a shared facet "
            "vertex), one pressure unknown each",
            terms->points().size(), terms->mergedPenaltyPoints());
    announceReplacedRules(*terms, *definition);
    terms->initialiseStatus();
    problem.setAdditionalTerms(terms);
    return terms;
}

namespace {

// COEF_PENA_CONT x facet size / E beyond which the penalised equations dominate the elastic ones
// by more digits than a Newton residual can resolve.
constexpr double kPenaltyRoundOffRatio = 1e12;

// Points named in a "contact did not converge" error (the others are counted).
constexpr int kListedPoints = 10;

// Largest COEF_PENA_CONT of the contact points and largest COEF_PENA_CONT x facet size / E (how far
// the penalty is from the stiffness: beyond ~1e12 its equations near double precision).
std::pair<double, double> penaltyStrength(const ContactTerms& terms) {
    const int dim = terms.definition().xfemModel().dim();
    double kappa = 0.0, ratio = 0.0;
    for (const auto& cp : terms.points()) {
        if (cp.multiplier < 0) continue;
        const double k = terms.definition().zones[cp.zone].penalty;
        const double h = dim == 2 ? terms.facets()[cp.facet].measure : std::sqrt(terms.facets()[cp.facet].measure);
        kappa = std::max(kappa, k);
        ratio = std::max(ratio, k * h / cp.scale);
    }
    return {kappa, ratio};
}

// Cause of a singular system with penalised contact: the pressure unknowns (one per contact point)
// are regularised by 1/COEF_PENA_CONT only; when the coefficient is huge next to E/h the points of
// one facet act as exact constraints, more of them than the gap can follow, and their pressures
// become numerically dependent (measured on the 3D slab h = 2, E = 1e8: HEXA8 singular from 1e22,
// TETRA4 and 2D at 1e24, docs/contact.md).
std::string penaltySingularHint(const ContactTerms& terms) {
    const auto [kappa, ratio] = penaltyStrength(terms);
    if (kappa == 0.0) return {};
    return fmt::format(
        "The contact uses ALGO_CONT='PENALISATION' with COEF_PENA_CONT up to {:.3e} (COEF_PENA_CONT x "
        "facet size / E up to {:.1e}): the contact pressures are regularised by 1/COEF_PENA_CONT only, "
        "and so large a coefficient turns the penalty into exact constraints at more contact points "
        "than the gap can follow, whose pressures are then numerically dependent. Lower "
        "COEF_PENA_CONT (its error, interpenetration = pressure/COEF_PENA_CONT, is logged) or use "
        "ALGO_CONT='STANDARD' (exact contact).",
        kappa, ratio);
}

// One Newton solve of the increment; a numerical failure gets the likely contact cause added.
IncrementReport solveExplainingFailure(MechanicalProblem& problem, ContactTerms& terms, double inst,
                                       const ConvergenceOptions& options, int activePoints) {
    try {
        return problem.solveIncrement(inst, options);
    } catch (const NumericalError& e) {
        if (activePoints > 0) {
            const std::string hint = penaltySingularHint(terms);
            // A penalty far above the stiffness shows as a singular system or as a Newton loop that
            // cannot reduce its residual below the round-off of the penalised terms.
            const bool singular = dynamic_cast<const SingularSystemError*>(&e) != nullptr;
            const bool stalled = dynamic_cast<const NonConvergenceError*>(&e) != nullptr &&
                                 penaltyStrength(terms).second > kPenaltyRoundOffRatio;
            if (hint.empty() || (!singular && !stalled)) throw;
            throw NumericalError(fmt::format("{}\n{}", e.what(), hint));
        }
        throw NumericalError(
            fmt::format("{}\nNo contact point is active (CONTACT_INIT='NON'): a block held only by the "
                        "contact floats then; if that is the cause, start with CONTACT_INIT='OUI' or hold "
                        "every block by boundary conditions",
                        e.what()));
    }
}

}  // namespace

ContactIncrementReport solveIncrementWithContact(MechanicalProblem& problem, ContactTerms& terms, double inst,
                                                 const ConvergenceOptions& options) {
    ContactIncrementReport out;
    const int maxIter = terms.definition().maxContactIterations;
    ActiveSetHistory history(terms.active());
    for (int it = 1; it <= maxIter; ++it) {
        const auto before = terms.inspect(problem.state());
        msg().infof("    INST {:g} contact iteration {}: {} active contact points of {}", inst, it, before.active,
                    before.points);
        const IncrementReport report = solveExplainingFailure(problem, terms, inst, options, before.active);
        out.newtonIterations += report.iterations;
        out.lastNewton = report;
        const StatusReport st = terms.updateStatus(problem.state());
        out.contactIterations = it;
        out.last = st;
        const ActiveSetHistory::Step step = history.record(terms.active());
        msg().infof(
            "    INST {:g} contact iteration {}: {} status change(s) ({} activated, {} released), {} active, "
            "largest penetration {:.6e}, contact residual {:.6e}, largest contact pressure {:.6e}",
            inst, it, st.changed, step.activated, step.released, st.active, st.maxPenetration, st.contactResidual,
            st.maxPressure);
        if (step.repeats >= 0)
            throw NumericalError(fmt::format(
                "contact did not converge at INST {}: the statuses after contact iteration {} repeat those {} "
                "(the loop would cycle between them whatever ITER_CONT_MAXI); {} active points of {}, contact "
                "residual {:.3e}.{}",
                inst, it,
                step.repeats == 0 ? std::string("it started from") : fmt::format("after iteration {}", step.repeats),
                st.active, st.points, st.contactResidual,
                history.flippingPoints(terms, problem.state(), kListedPoints)));
        if (st.changed == 0) {
            bool penalty = false;
            for (const auto& z : terms.definition().zones)
                penalty = penalty || z.algorithm == ContactAlgorithm::Penalty;
            if (penalty)
                msg().infof(
                    "    penalised contact (PENALISATION): largest interpenetration {:.6e} at convergence "
                    "(error of the method ~ pressure / COEF_PENA_CONT)",
                    st.maxPenetration);
            return out;
        }
        problem.invalidateMatrix();
    }
    std::string message = fmt::format(
        "contact did not converge at INST {} in {} contact iterations (ITER_CONT_MAXI): "
        "{} status change(s) at the last one, {} active points, contact residual {:.3e}.{}",
        inst, maxIter, out.last.changed, out.last.active, out.last.contactResidual,
        history.flippingPoints(terms, problem.state(), kListedPoints));
    // With a huge penalty the interpenetration of the active points, pressure / COEF_PENA_CONT, can
    // sink below the round-off of the displacements: their gaps then change sign by round-off and the
    // statuses cannot settle (measured: TRIA3 N = 41 at COEF_PENA_CONT = 1e24, p/k = 2e-18 m against
    // displacements of 0.16 m).
    const auto [kappa, ratio] = penaltyStrength(terms);
    double umax = 0.0;
    for (double v : problem.state()) umax = std::max(umax, std::abs(v));
    if (kappa > 0.0 && out.last.maxPressure / kappa < 1e-12 * umax)
        message += fmt::format(
            "\nPossible cause: ALGO_CONT='PENALISATION' with COEF_PENA_CONT up to {:.3e} "
            "(COEF_PENA_CONT x facet size / E up to {:.1e}): the interpenetration of the active "
            "points, contact pressure / COEF_PENA_CONT (at most {:.1e}), is below the round-off of "
            "the displacements (largest {:.3e}), so their gaps change sign by round-off and the "
            "contact statuses cannot settle. Lower COEF_PENA_CONT or use ALGO_CONT='STANDARD' "
            "(exact contact).",
            kappa, ratio, out.last.maxPressure / kappa, umax);
    throw NumericalError(message);
}

}  // namespace ma::contact
