#pragma once
// The contact terms added to the mechanical problem (fe::AdditionalTerms), frictionless and
// unilateral, on the facets of ContactFacets (docs/contact.md).
//
// Notation at a facet point: n from the - side to the + side, gap g(u) = (u+ - u-).n (> 0 open,
// < 0 interpenetration), sigma_n(u) = w- n.sigma-(u).n + w+ n.sigma+(u).n (weights = block
// measures of the two sides), P(u) = sigma_n(u) + gamma g(u). Contact pressure (code_aster's
// LAGS_C sign, <= 0 in compression):
//   Nitsche (ALGO_CONT='STANDARD'):  lambda = min(P(u), 0)
//   penalty ('PENALISATION'):         lambda = kappa min(g(u), 0)
// Penalty points carry lambda as an unknown (equation g - lambda/kappa = 0, see ContactPoint).
// Weak form (theta = 1, symmetric Nitsche):
//   a(u,v) - (theta/gamma) int sigma_n(u) sigma_n(v) + (1/gamma) int lambda(u) (theta sigma_n(v) + gamma g(v)) = L(v)
// which the exact solution satisfies (lambda = sigma_n, sigma_n g = 0): the method is consistent.
// The min is resolved by an active set frozen during each Newton solve (active: lambda = P,
// inactive: lambda = 0) and updated by the contact loop (ContactLoop.hpp).
// The integrals are sums over the points of each facet's rule, the one of its zone
// (ZONE/INTEGRATION, ContactIntegration.hpp): with 'NOEUD' the points are the facet vertices, so a
// vertex shared by several facets (the junction point among them) carries one point per facet,
// each with the stresses of its own facet's two sides.
#include <array>
#include <memory>
#include <vector>

#include "contact/ContactDefinition.hpp"
#include "contact/ContactFacets.hpp"
#include "fe/MechanicalProblem.hpp"

namespace ma::contact {

struct ContactPoint {
    int facet = -1;
    int zone = -1;
    double weight = 0.0;  // physical quadrature weight
    std::array<double, 3> xyz{};
    std::vector<int> dofs;       // unknowns the point depends on
    std::vector<double> gap;     // g(u) = sum gap[i] u[dofs[i]]
    std::vector<double> stress;  // sigma_n(u) = sum stress[i] u[dofs[i]] (weighted average)
    double gamma = 0.0;          // Nitsche parameter (Pa/m)
    // Penalty: the pressure is an unknown of the point, lambda = scale * u[multiplier], with the
    // equation g - lambda/kappa = 0 (mixed form: the displacement rows carry lambda, not
    // kappa*g, so that their residual is not amplified by kappa; code_aster's form).
    int multiplier = -1;
    double scale = 1.0;
};

// Facets of a zone whose rule would integrate the traces of their parents' shape functions only
// approximately (rule degree < facetTraceDegree: the exact solution of a uniform stress per block
// would no longer solve the discrete equations); those facets are integrated with the lowest Gauss
// rule exact for their traces instead (docs/contact.md).
// A zone rule with a negative weight (3D ORDRE_INT=3, TR3 FPG4) is replaced on every facet by the
// lowest Gauss rule of positive weights and at least its degree (positiveWeights()).
struct RuleShortfall {
    int facets = 0;    // facets of the zone
    int replaced = 0;  // of which the zone's rule is too weak for: integrated with a Gauss rule instead
    int ruleDegree = 0;
    int traceDegree = 0;       // largest trace degree among them
    int replacementOrder = 0;  // largest ORDRE_INT of INTEGRATION='GAUSS' used instead
    bool negativeWeight =
        false;  // the zone's rule has a negative weight: every facet takes ORDRE_INT=negativeWeightOrder
    int negativeWeightOrder = 0;
};

// The function whose sign decides a point's status, Nitsche P(u) = sigma_n(u) + gamma g(u), penalty
// g(u), at the state u, with the sum of the absolute values of its terms (its round-off scale).
struct StatusFunction {
    double value = 0.0;
    double magnitude = 0.0;
};

// Relative size below which the sign of a StatusFunction is not trusted (its value cancels to that
// fraction of its terms): 1e-9, far above the cancellation round-off of the sum (~1e-15) and of the
// MUMPS solutions' relative accuracy, far below any contact pressure that matters.
constexpr double kStatusRoundOff = 1e-9;

struct StatusReport {
    int changed = 0;
    int active = 0;
    int points = 0;
    double maxPenetration = 0.0;   // max(-g, 0)
    double maxGap = 0.0;           // max(g, 0) over active points of bilateral zones
    double contactResidual = 0.0;  // complementarity violation: |P| at points whose status is wrong
    double maxPressure = 0.0;      // max |lambda|
};

class ContactTerms : public AdditionalTerms {
public:
    ContactTerms(const MechanicalProblem& problem, const MaterialField& material,
                 std::shared_ptr<const ContactDefinition> definition, std::vector<ContactFacet> facets);

    void couplings(std::vector<std::pair<int, int>>& pairs) const override;
    void tangent(const std::vector<double>& u, const std::function<void(int, int, double)>& add) const override;
    void residual(const std::vector<double>& u, std::vector<double>& R) const override;
    int extraUnknowns() const override { return extraUnknowns_; }
    // Penalty points merged into an earlier point with the same gap (a shared facet vertex).
    int mergedPenaltyPoints() const { return mergedPenaltyPoints_; }

    // Initial statuses: CONTACT_INIT='OUI' zones all active, others inactive.
    void initialiseStatus();
    // New statuses from the state u (semi-smooth Newton / active set step).
    StatusReport updateStatus(const std::vector<double>& u);
    // Current statistics without changing anything.
    StatusReport inspect(const std::vector<double>& u) const;

    const std::vector<ContactPoint>& points() const { return points_; }
    // Per zone (definition().zones order).
    const std::vector<RuleShortfall>& ruleShortfalls() const { return shortfalls_; }
    const std::vector<ContactFacet>& facets() const { return facets_; }
    const std::vector<char>& active() const { return active_; }
    const ContactDefinition& definition() const { return *definition_; }
    double gap(int p, const std::vector<double>& u) const;
    double normalStress(int p, const std::vector<double>& u) const;
    // Contact pressure lambda at point p with the current statuses (<= 0 in compression).
    double pressure(int p, const std::vector<double>& u) const;
    StatusFunction statusFunction(int p, const std::vector<double>& u) const;

private:
    bool nitsche(int p) const { return definition_->zones[points_[p].zone].algorithm == ContactAlgorithm::Nitsche; }
    bool wantsActive(int p, const std::vector<double>& u) const;

    std::shared_ptr<const ContactDefinition> definition_;
    std::vector<ContactFacet> facets_;
    std::vector<ContactPoint> points_;
    std::vector<char> active_, everActive_;
    std::vector<char> owned_;  // points whose terms this process computes (all on one process)
    std::vector<RuleShortfall> shortfalls_;
    int extraUnknowns_ = 0;
    int mergedPenaltyPoints_ = 0;
};

}  // namespace ma::contact
