#include "contact/ContactTerms.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "contact/FacetNormal.hpp"
#include "core/Error.hpp"
#include "core/Vec3.hpp"
#include "fe/ElasticityKernels.hpp"
#include "fe/ElementKinematics.hpp"
#include "fe/Material.hpp"
#include "fe/Quadrature.hpp"
#include "mesh/ShapeFunctions.hpp"
#include "xfem/XfemModel.hpp"

namespace ma::contact {

namespace {

// Rule of the facets of a zone (ZONE/INTEGRATION, ORDRE_INT; DEFI_CONTACT has refused the schemes
// without a family). Whatever the rule, the point terms are consistent (docs/contact.md).
const QuadratureRule& facetRule(int dim, const ContactIntegration& integration) {
    const std::string family = facetFamily(dim, integration);
    if (family.empty()) throw InternalError("contact: no facet family for INTEGRATION='" + integration.scheme + "'");
    return quadratureRule(dim == 2 ? CellType::SEG2 : CellType::TRIA3, family);
}

// Weights of a point of the reference facet on its vertices (SEG2 on [-1,1], TRIA3 unit triangle).
std::array<double, 3> facetBarycentric(int dim, const Vec3& xi) {
    if (dim == 2) return {0.5 * (1.0 - xi[0]), 0.5 * (1.0 + xi[0]), 0.0};
    return {1.0 - xi[0] - xi[1], xi[0], xi[1]};
}

// Penalty points of the constructor by gap functional: (zone, first unknown) -> (point, sorted
// nonzero gap coefficients), so that a point with the same gap as an earlier one is found.
class PenaltyPointIndex {
public:
    using Key = std::vector<std::pair<int, double>>;

    // The earlier point of `points` with cp's zone and gap (coefficients equal to 1e-12 of the
    // largest), or nullptr; then cp is recorded as the next point appended to `points`.
    ContactPoint* find(const ContactPoint& cp, std::vector<ContactPoint>& points) {
        Key key;
        double scale = 0.0;
        for (size_t i = 0; i < cp.dofs.size(); ++i)
            if (cp.gap[i] != 0.0) {
                key.emplace_back(cp.dofs[i], cp.gap[i]);
                scale = std::max(scale, std::abs(cp.gap[i]));
            }
        std::sort(key.begin(), key.end());
        auto& candidates = byFirstDof_[{cp.zone, key.empty() ? -1 : key.front().first}];
        for (const auto& [p, other] : candidates) {
            if (other.size() != key.size()) continue;
            bool same = true;
            for (size_t i = 0; same && i < key.size(); ++i)
                same = other[i].first == key[i].first && std::abs(other[i].second - key[i].second) <= 1e-12 * scale;
            if (same) return &points[p];
        }
        candidates.emplace_back(points.size(), std::move(key));
        return nullptr;
    }

private:
    std::map<std::pair<int, int>, std::vector<std::pair<size_t, Key>>> byFirstDof_;
};

// The rule of a facet's points: its zone's, unless that rule has a negative weight or is too weak
// for the traces of the parent shape functions on the facet (counted in `shortfall`).
const QuadratureRule* facetPointRule(const Mesh& mesh, int dim, const ContactFacet& facet,
                                     const ContactIntegration& integration, RuleShortfall& shortfall) {
    const QuadratureRule* rule = &facetRule(dim, integration);
    ++shortfall.facets;
    shortfall.ruleDegree = rule->degree;
    if (!positiveWeights(*rule)) {
        // A point of negative weight would make the stabilisation indefinite and its status
        // decision a non-descent (ssnv513g with FPG4: MUMPS negative pivot, the active set cycled):
        // the lowest positive rule of at least the zone's degree instead (alarm CONTACT_INTEGRATION).
        shortfall.negativeWeight = true;
        shortfall.negativeWeightOrder = gaussOrderFor(dim, rule->degree);
        rule = &facetRule(dim, ContactIntegration{"GAUSS", shortfall.negativeWeightOrder});
    }
    int traceDegree = 1;
    for (const FacetSide* side : {&facet.minus, &facet.plus})
        traceDegree = std::max(traceDegree, facetTraceDegree(mesh.cellTypes[size_t(side->cell)], side->ref));
    if (traceDegree > rule->degree) {
        // The zone's rule would integrate g(v) only approximately on this facet and lose the
        // solutions the elements represent exactly (ssnv511g with the vertex rule: energy error
        // 5.8e-4): the facet takes the lowest Gauss rule exact for its traces instead, announced by
        // the alarm CONTACT_INTEGRATION (ContactLoop).
        const int order = gaussOrderFor(dim, traceDegree);
        ++shortfall.replaced;
        shortfall.traceDegree = std::max(shortfall.traceDegree, traceDegree);
        shortfall.replacementOrder = std::max(shortfall.replacementOrder, order);
        rule = &facetRule(dim, ContactIntegration{"GAUSS", order});
    }
    return rule;
}

// Gap and normal-stress coefficients of side s (0: -, 1: +) of a contact point at facet point
// `bary`; the - side also gives the normal nv (contact/FacetNormal).
void addSideTerms(const xfem::XfemModel& xm, const Model& model, const DofNumbering& numbering,
                  const MaterialField& material, const ContactFacet& facet, int s, const std::array<double, 3>& bary,
                  double wMinus, ElementIntegration& ei, PointGeometry& geo, Vec3& nv, ContactPoint& cp) {
    const Mesh& mesh = *model.mesh;
    const int dim = model.dim;
    const FacetSide& side = s == 0 ? facet.minus : facet.plus;
    const double sign = s == 0 ? -1.0 : 1.0;
    const double weight = s == 0 ? wMinus : 1.0 - wMinus;
    const auto* cut = xm.cut(side.cell);
    Vec3 ref{};
    for (int v = 0; v < dim; ++v)
        for (int j = 0; j < 3; ++j) ref[j] += bary[v] * side.ref[v][j];
    const auto nodes = mesh.cellNodes(side.cell);
    const int n = static_cast<int>(nodes.size());
    ei = ElementIntegration{};
    ei.cell = side.cell;
    ei.nodeCount = n;
    ei.refPoints = {ref};
    ei.refWeights = {1.0};
    ei.pointSubcell = {side.subcell};
    ei.slots.assign(n, 1);
    computePointGeometry(mesh, side.cell, dim, false, ei, geo);
    if (s == 0) nv = facetNormal(*cut, facet, side.subcell, n, geo.gradN);
    const Material& mat = material.at(side.cell);
    const IsotropicLaw law = IsotropicLaw::from(mat, model.modelisation, mat.name);
    for (int a = 0; a < n; ++a) {
        const double Na = geo.N[a];
        const double* g = &geo.gradN[size_t(a) * 3];
        const double dn = g[0] * nv[0] + g[1] * nv[1] + g[2] * nv[2];
        const int slots = 1 + xm.activeSlots(nodes[a]);
        for (int k = 0; k < slots; ++k) {
            const double psi = k == 0 ? 1.0 : xm.psi(nodes[a], k, *cut, side.subcell);
            if (psi == 0.0) continue;
            for (int c = 0; c < dim; ++c) {
                const int d = numbering.dof(nodes[a], k, c);
                if (d < 0)
                    throw InternalError(fmt::format("contact: node {} has no slot {}", mesh.nodeNames[nodes[a]], k));
                auto it = std::find(cp.dofs.begin(), cp.dofs.end(), d);
                size_t i = static_cast<size_t>(it - cp.dofs.begin());
                if (it == cp.dofs.end()) {
                    cp.dofs.push_back(d);
                    cp.gap.push_back(0.0);
                    cp.stress.push_back(0.0);
                }
                cp.gap[i] += sign * psi * Na * nv[c];
                cp.stress[i] += weight * psi * (law.lambdaEff * g[c] + 2.0 * law.mu * nv[c] * dn);
            }
        }
    }
}

}  // namespace

ContactTerms::ContactTerms(const MechanicalProblem& problem, const MaterialField& material,
                           std::shared_ptr<const ContactDefinition> definition, std::vector<ContactFacet> facets)
    : definition_(std::move(definition)), facets_(std::move(facets)) {
    const Model& model = problem.model();
    const Mesh& mesh = *model.mesh;
    const auto& xm = definition_->xfemModel();
    const DofNumbering& numbering = problem.numbering();
    const int dim = model.dim;
    const double refMeasure = dim == 2 ? 2.0 : 0.5;

    ElementIntegration ei;
    PointGeometry geo;
    PenaltyPointIndex penaltyPoints;
    shortfalls_.assign(definition_->zones.size(), {});
    for (size_t f = 0; f < facets_.size(); ++f) {
        const ContactFacet& facet = facets_[f];
        const int zone = definition_->zoneOfCrack(facet.crack);
        if (zone < 0) continue;
        const QuadratureRule* rule =
            facetPointRule(mesh, dim, facet, definition_->zones[zone].integration, shortfalls_[zone]);
        // Nitsche parameter on the stiffest normal response of the two sides, the P-wave modulus
        // lambda + 2 mu (E (1 - nu) / ((1 + nu)(1 - 2 nu)) in 3D / D_PLAN): sigma_n(v) is bounded by it,
        // not by E. With E the symmetric Nitsche matrix lost positive definiteness near
        // incompressibility (MUMPS negative pivots from NU = 0.49, docs/study/stability.md).
        double youngMax = 0.0, modulusMax = 0.0;
        for (const FacetSide* side : {&facet.minus, &facet.plus}) {
            const Material& mat = material.at(side->cell);
            const IsotropicLaw law = IsotropicLaw::from(mat, model.modelisation, mat.name);
            youngMax = std::max(youngMax, mat.E);
            modulusMax = std::max(modulusMax, law.lambdaEff + 2.0 * law.mu);
        }
        const double gamma = definition_->nitsche.gammaZero * modulusMax * facet.pairMeasure /
                             (facet.minus.blockMeasure + facet.plus.blockMeasure);
        const double wMinus = facet.minus.blockMeasure / (facet.minus.blockMeasure + facet.plus.blockMeasure);
        for (int q = 0; q < rule->size(); ++q) {
            ContactPoint cp;
            cp.facet = static_cast<int>(f);
            cp.zone = zone;
            cp.gamma = gamma;
            cp.weight = rule->weights[q] / refMeasure * facet.measure;
            const auto bary = facetBarycentric(dim, rule->points[q]);
            for (int v = 0; v < dim; ++v)
                for (int j = 0; j < 3; ++j) cp.xyz[j] += bary[v] * facet.vertices[v][j];
            // Normal: the level-set gradient of the facet's interface at the point (docs/contact.md),
            // from the - side's parent; the facet's own vertices can be off the interface by CellCut's
            // merge tolerance (1e-9 h), which tilts a sliver facet (length 1e-5 h) by 1e-5 rad: then
            // the exact uniform stress has a shear on it and frictionless contact is no longer exact.
            Vec3 nv = facet.normal;
            for (int s = 0; s < 2; ++s)
                addSideTerms(xm, model, numbering, material, facet, s, bary, wMinus, ei, geo, nv, cp);
            if (definition_->zones[zone].algorithm == ContactAlgorithm::Penalty) {
                cp.scale = youngMax;
                if (ContactPoint* same = penaltyPoints.find(cp, points_)) {
                    // Same gap as an earlier point (a facet vertex shared by facets between the same
                    // blocks, INTEGRATION='NOEUD'): with one pressure unknown each their equations
                    // lambda_i = kappa g(u) are dependent as kappa grows (MUMPS null pivots from
                    // COEF_PENA_CONT * h / E ~ 1e13, TETRA4 at 1e22); one point with the summed weight
                    // is the same discrete problem.
                    same->weight += cp.weight;
                    same->scale = std::max(same->scale, cp.scale);
                    ++mergedPenaltyPoints_;
                    continue;
                }
                cp.multiplier = numbering.size() + extraUnknowns_++;
            }
            points_.push_back(std::move(cp));
        }
    }
    active_.assign(points_.size(), 0);
    everActive_.assign(points_.size(), 0);
    // Distributed (docs/mpi.md): a point's matrix and residual terms are computed by the process of
    // its facet's - side cell; statuses are decided on every process from the whole state.
    owned_.resize(points_.size());
    for (size_t p = 0; p < points_.size(); ++p)
        owned_[p] = problem.ownsCell(facets_[size_t(points_[p].facet)].minus.cell);
}

double ContactTerms::gap(int p, const std::vector<double>& u) const {
    const auto& cp = points_[p];
    double g = 0.0;
    for (size_t i = 0; i < cp.dofs.size(); ++i) g += cp.gap[i] * u[cp.dofs[i]];
    return g;
}

double ContactTerms::normalStress(int p, const std::vector<double>& u) const {
    const auto& cp = points_[p];
    double s = 0.0;
    for (size_t i = 0; i < cp.dofs.size(); ++i) s += cp.stress[i] * u[cp.dofs[i]];
    return s;
}

double ContactTerms::pressure(int p, const std::vector<double>& u) const {
    if (!active_[p]) return 0.0;
    if (nitsche(p)) return normalStress(p, u) + points_[p].gamma * gap(p, u);
    return points_[p].scale * u[points_[p].multiplier];
}

void ContactTerms::couplings(std::vector<std::pair<int, int>>& pairs) const {
    // Points of one facet share their unknowns: the pairs of the first point of each facet
    // (plus any extra unknown of the others).
    int lastFacet = -1;
    std::vector<int> dofs;
    auto flush = [&] {
        for (int i : dofs)
            for (int j : dofs)
                if (i < j) pairs.emplace_back(i, j);
        dofs.clear();
    };
    for (const auto& cp : points_) {
        if (cp.facet != lastFacet) flush(), lastFacet = cp.facet;
        for (int d : cp.dofs)
            if (std::find(dofs.begin(), dofs.end(), d) == dofs.end()) dofs.push_back(d);
        if (cp.multiplier >= 0) {
            pairs.emplace_back(cp.multiplier, cp.multiplier);
            for (int d : cp.dofs) pairs.emplace_back(d, cp.multiplier);
        }
    }
    flush();
}

void ContactTerms::tangent(const std::vector<double>& u, const std::function<void(int, int, double)>& add) const {
    (void)u;
    const double theta = definition_->nitsche.theta;
    for (size_t p = 0; p < points_.size(); ++p) {
        if (!owned_[p]) continue;
        const auto& cp = points_[p];
        const size_t m = cp.dofs.size();
        if (nitsche(int(p))) {
            const double w = cp.weight, gm = cp.gamma;
            for (size_t i = 0; i < m; ++i)
                for (size_t j = 0; j < m; ++j) {
                    double v = -theta / gm * cp.stress[i] * cp.stress[j];
                    if (active_[p]) v += (theta * cp.stress[i] + gm * cp.gap[i]) * (cp.stress[j] + gm * cp.gap[j]) / gm;
                    if (v != 0.0) add(cp.dofs[i], cp.dofs[j], w * v);
                }
        } else {
            const double kappa = definition_->zones[cp.zone].penalty;
            add(cp.multiplier, cp.multiplier, -cp.weight * cp.scale * cp.scale / kappa);
            if (active_[p])
                for (size_t i = 0; i < m; ++i)
                    if (cp.gap[i] != 0.0) {
                        add(cp.dofs[i], cp.multiplier, cp.weight * cp.scale * cp.gap[i]);
                        add(cp.multiplier, cp.dofs[i], cp.weight * cp.scale * cp.gap[i]);
                    }
        }
    }
}

void ContactTerms::residual(const std::vector<double>& u, std::vector<double>& R) const {
    const double theta = definition_->nitsche.theta;
    for (size_t p = 0; p < points_.size(); ++p) {
        if (!owned_[p]) continue;
        const auto& cp = points_[p];
        const double lambda = pressure(int(p), u);
        if (nitsche(int(p))) {
            const double sn = normalStress(int(p), u);
            for (size_t i = 0; i < cp.dofs.size(); ++i)
                R[cp.dofs[i]] += cp.weight * (-theta / cp.gamma * sn * cp.stress[i] +
                                              lambda / cp.gamma * (theta * cp.stress[i] + cp.gamma * cp.gap[i]));
        } else {
            const double kappa = definition_->zones[cp.zone].penalty;
            const double own = cp.scale * u[cp.multiplier];  // the unknown, whatever the status
            R[cp.multiplier] += cp.weight * cp.scale * ((active_[p] ? gap(int(p), u) : 0.0) - own / kappa);
            if (active_[p])
                for (size_t i = 0; i < cp.dofs.size(); ++i) R[cp.dofs[i]] += cp.weight * lambda * cp.gap[i];
        }
    }
}

void ContactTerms::initialiseStatus() {
    for (size_t p = 0; p < points_.size(); ++p) {
        active_[p] = definition_->zones[points_[p].zone].initiallyActive ? 1 : 0;
        everActive_[p] = active_[p];
    }
}

StatusFunction ContactTerms::statusFunction(int p, const std::vector<double>& u) const {
    const auto& cp = points_[p];
    const bool withStress = nitsche(p);
    const double gapFactor = withStress ? cp.gamma : 1.0;
    StatusFunction f;
    for (size_t i = 0; i < cp.dofs.size(); ++i) {
        const double ui = u[cp.dofs[i]];
        const double stressTerm = withStress ? cp.stress[i] * ui : 0.0, gapTerm = gapFactor * cp.gap[i] * ui;
        f.value += stressTerm + gapTerm;
        f.magnitude += std::abs(stressTerm) + std::abs(gapTerm);
    }
    return f;
}

bool ContactTerms::wantsActive(int p, const std::vector<double>& u) const {
    const auto& zone = definition_->zones[points_[p].zone];
    if (zone.bilateral && everActive_[p]) return true;
    // The sign of a value that cancels to below kStatusRoundOff of its terms is round-off, not
    // contact or separation: the point keeps its status (either one gives the same equations to
    // that relative size), so no status can flip back and forth on round-off.
    const StatusFunction f = statusFunction(p, u);
    if (std::abs(f.value) <= kStatusRoundOff * f.magnitude) return active_[p] != 0;
    return f.value < 0.0;
}

StatusReport ContactTerms::inspect(const std::vector<double>& u) const {
    StatusReport r;
    r.points = static_cast<int>(points_.size());
    for (size_t p = 0; p < points_.size(); ++p) {
        const double g = gap(int(p), u);
        r.active += active_[p];
        r.maxPenetration = std::max(r.maxPenetration, -g);
        if (active_[p]) r.maxGap = std::max(r.maxGap, g);
        r.maxPressure = std::max(r.maxPressure, std::abs(pressure(int(p), u)));
        // Complementarity violation: what the status would change.
        const bool want = wantsActive(int(p), u);
        if (want != bool(active_[p])) {
            const double P =
                nitsche(int(p)) ? statusFunction(int(p), u).value : definition_->zones[points_[p].zone].penalty * g;
            r.contactResidual = std::max(r.contactResidual, std::abs(P));
        }
    }
    r.maxPenetration = std::max(r.maxPenetration, 0.0);
    return r;
}

StatusReport ContactTerms::updateStatus(const std::vector<double>& u) {
    StatusReport r = inspect(u);
    std::vector<char> next(points_.size());
    for (size_t p = 0; p < points_.size(); ++p) next[p] = wantsActive(int(p), u) ? 1 : 0;
    r.changed = 0;
    r.active = 0;
    for (size_t p = 0; p < points_.size(); ++p) {
        r.changed += next[p] != active_[p];
        active_[p] = next[p];
        everActive_[p] = everActive_[p] || next[p];
        r.active += next[p];
    }
    return r;
}

}  // namespace ma::contact
