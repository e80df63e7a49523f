// ZONE/INTEGRATION and ORDRE_INT of DEFI_CONTACT (src/contact/ContactIntegration, ContactTerms):
// the facet family of every scheme is code_aster's (xminte.F90), the points of each facet integrate
// the polynomials of their rule's degree and sum to the facet measure, 'NOEUD' puts them on the facet
// vertices, each zone keeps its own rule, and the command refuses what code_aster does not define
// (3D SIMPSON of order > 1 and NCOTES) and orders out of the catalogue's ranges (those through the
// binary: tests/cli/contact_integration_runs.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "contact/ContactIntegration.hpp"
#include "contact_test_scene.hpp"
#include "fe/Quadrature.hpp"

namespace {

using namespace ma;
using namespace ma::contact;
using Vec = std::array<double, 3>;

struct Expected {
    const char* scheme;
    int order;
    const char* family2d;
    const char* family3d;  // "" where code_aster defines no TR3 rule
};

// bibfor/elements/xminte.F90 for INTEG = 10 ORDRE_INT + (1 NOEUD, 2 GAUSS, 3 SIMPSON, 4 NCOTES), and
// the X-FEM contact elements' TR3 'GAUSS' = FPG12.
const Expected kTable[] = {
    {"NOEUD", 0, "NOEU", "NOEU"},  {"GAUSS", 1, "FPG2", "FPG3"},   {"GAUSS", 2, "FPG2", "FPG3"},
    {"GAUSS", 3, "FPG3", "FPG4"},  {"GAUSS", 4, "FPG4", "FPG6"},   {"GAUSS", 5, "FPG4", "FPG7"},
    {"GAUSS", 6, "FPG4", "FPG12"}, {"SIMPSON", 1, "SIMP", "SIMP"}, {"SIMPSON", 2, "SIMP1", ""},
    {"SIMPSON", 3, "SIMP1", ""},   {"SIMPSON", 4, "SIMP1", ""},    {"NCOTES", 3, "COTES", ""},
    {"NCOTES", 4, "COTES1", ""},   {"NCOTES", 5, "COTES1", ""},    {"NCOTES", 6, "COTES2", ""},
    {"NCOTES", 7, "COTES2", ""},   {"NCOTES", 8, "COTES2", ""},
};

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Barycentric coordinates (l1, l2) of x on the facet (segment: l1 only), from the physical vertices.
std::array<double, 2> barycentric(const std::vector<Vec>& v, const Vec& x) {
    const Vec e1 = sub(v[1], v[0]), d = sub(x, v[0]);
    if (v.size() == 2) return {dot(d, e1) / dot(e1, e1), 0.0};
    const Vec e2 = sub(v[2], v[0]);
    const double a = dot(e1, e1), b = dot(e1, e2), c = dot(e2, e2), p = dot(d, e1), q = dot(d, e2);
    const double det = a * c - b * b;
    return {(p * c - q * b) / det, (q * a - p * b) / det};
}

// Checks every facet's points of scene s against its rule: count, sum of weights = facet measure,
// exact on l1^i l2^j (i + j <= degree), and with NOEU the points are the facet vertices.
void expectFacetRule(const contacttest::Scene& s, const QuadratureRule& rule, const std::string& what) {
    const auto& terms = *s.terms;
    std::vector<std::vector<int>> byFacet(terms.facets().size());
    for (size_t p = 0; p < terms.points().size(); ++p) byFacet[terms.points()[p].facet].push_back(int(p));
    const int dim = s.model->dim;
    int checked = 0;
    for (size_t f = 0; f < byFacet.size(); ++f) {
        const auto& facet = terms.facets()[f];
        ASSERT_EQ(int(byFacet[f].size()), rule.size()) << what << " facet " << f;
        double sum = 0.0;
        for (int p : byFacet[f]) sum += terms.points()[p].weight;
        EXPECT_NEAR(sum, facet.measure, 1e-14 * facet.measure) << what;
        for (int i = 0; i <= rule.degree; ++i)
            for (int j = 0; j <= (dim == 3 ? rule.degree - i : 0); ++j) {
                double q = 0.0;
                for (int p : byFacet[f]) {
                    const auto l = barycentric(facet.vertices, terms.points()[p].xyz);
                    q += terms.points()[p].weight * std::pow(l[0], i) * std::pow(l[1], j);
                }
                // Segment: L i! / (i + 1)!; triangle: 2 A i! j! / (i + j + 2)!.
                const double exact = dim == 2
                                         ? facet.measure / (i + 1)
                                         : 2.0 * facet.measure * factorial(i) * factorial(j) / factorial(i + j + 2);
                EXPECT_NEAR(q, exact, 1e-12 * facet.measure) << what << " l1^" << i << " l2^" << j;
            }
        if (rule.family == "NOEU") {
            for (size_t k = 0; k < byFacet[f].size(); ++k)
                for (int c = 0; c < 3; ++c)
                    EXPECT_EQ(terms.points()[byFacet[f][k]].xyz[c], facet.vertices[k][c]) << what << " vertex " << k;
        }
        ++checked;
    }
    EXPECT_GT(checked, 0) << what;
}

}  // namespace

TEST(ContactIntegration, FacetFamiliesAreCodeAsters) {
    for (const auto& e : kTable) {
        const ContactIntegration in{e.scheme, e.order};
        EXPECT_EQ(facetFamily(2, in), e.family2d) << e.scheme << " " << e.order;
        EXPECT_EQ(facetFamily(3, in), e.family3d) << e.scheme << " " << e.order;
        EXPECT_TRUE(missingRuleReason(2, in).empty());
        EXPECT_EQ(missingRuleReason(3, in).empty(), std::string(e.family3d) != "") << e.scheme << " " << e.order;
    }
    EXPECT_NE(missingRuleReason(3, {"SIMPSON", 2}).find("SIMP1"), std::string::npos);
    EXPECT_NE(missingRuleReason(3, {"NCOTES", 4}).find("COTES"), std::string::npos);
    EXPECT_NE(missingRuleReason(3, {"NCOTES", 7}).find("no integration family"), std::string::npos);
    EXPECT_EQ(describe(2, {"NOEUD", 0}), "INTEGRATION='NOEUD' (facet vertices)");
    EXPECT_EQ(describe(2, {}), "INTEGRATION='GAUSS', ORDRE_INT=6 (SE2 FPG4)");
    EXPECT_EQ(describe(3, {}), "INTEGRATION='GAUSS', ORDRE_INT=6 (TR3 FPG12)");
}

TEST(ContactIntegration, FacetPointsIntegrateTheirDegreeAndSumToTheFacetMeasure) {
    for (CellType type : {CellType::QUAD4, CellType::TRIA3, CellType::TETRA4, CellType::HEXA8}) {
        const int dim = type == CellType::QUAD4 || type == CellType::TRIA3 ? 2 : 3;
        for (const auto& e : kTable) {
            const ContactIntegration in{e.scheme, e.order};
            const std::string family = dim == 2 ? e.family2d : e.family3d;
            if (family.empty()) continue;
            const auto s = contacttest::scene(type, 3, ContactAlgorithm::Nitsche, false, in);
            const QuadratureRule& asked = quadratureRule(dim == 2 ? CellType::SEG2 : CellType::TRIA3, family);
            // HEXA8 facets have bilinear traces: a degree-1 rule is replaced by TR3 FPG3; TR3 FPG4 has a
            // negative weight and is replaced by FPG6 everywhere.
            const bool replaced = type == CellType::HEXA8 && asked.degree < 2;
            const QuadratureRule& used = !positiveWeights(asked) ? quadratureRule(CellType::TRIA3, "FPG6")
                                         : replaced              ? quadratureRule(CellType::TRIA3, "FPG3")
                                                                 : asked;
            expectFacetRule(s, used, cellTypeName(type) + " " + describe(dim, in));
        }
    }
}

TEST(ContactIntegration, EachZoneKeepsItsRule) {
    auto s = contacttest::scene(CellType::QUAD4, 5, ContactAlgorithm::Nitsche);
    s.definition->zones[0].integration = {"NOEUD", 0};
    s.definition->zones[1].integration = {"NCOTES", 8};
    s.definition->zones[2].integration = {"SIMPSON", 1};
    s.terms = attachContact(*s.problem, *s.material, s.definition);
    const int expected[] = {2, 10, 3};  // NOEU, COTES2, SIMP points per segment
    std::vector<int> perFacet(s.terms->facets().size(), 0);
    for (const auto& cp : s.terms->points()) ++perFacet[cp.facet];
    int seen[3] = {0, 0, 0};
    for (size_t f = 0; f < perFacet.size(); ++f) {
        const int zone = s.definition->zoneOfCrack(s.terms->facets()[f].crack);
        EXPECT_EQ(perFacet[f], expected[zone]) << "facet " << f;
        ++seen[zone];
    }
    for (int n : seen) EXPECT_GT(n, 0);
}

TEST(ContactIntegration, NodalPointsAtTheJunctionUseTheirOwnFacet) {
    // The junction point (0, 0) is a vertex of facets of the three interfaces: one point per facet
    // there, each with the unknowns of its own facet's two sides only.
    const auto s = contacttest::scene(CellType::QUAD4, 5, ContactAlgorithm::Nitsche, false, {"NOEUD", 0});
    const auto& terms = *s.terms;
    int atJunction = 0;
    for (const auto& cp : terms.points()) {
        if (std::abs(cp.xyz[0]) > 1e-12 || std::abs(cp.xyz[1]) > 1e-12) continue;
        ++atJunction;
        const auto& facet = terms.facets()[cp.facet];
        const auto& num = s.problem->numbering();
        const Mesh& mesh = *s.model->mesh;
        std::vector<int> allowed;
        for (int cell : {facet.minus.cell, facet.plus.cell})
            for (int node : mesh.cellNodes(cell))
                for (int k = 0; k < 8; ++k)
                    for (int c = 0; c < 2; ++c)
                        if (const int d = num.dof(node, k, c); d >= 0) allowed.push_back(d);
        for (int d : cp.dofs) EXPECT_NE(std::find(allowed.begin(), allowed.end(), d), allowed.end());
    }
    // FISS1 on both sides of x = 0 (2 pieces), FISS2 above and FISS3 below: 4 facets end there.
    EXPECT_EQ(atJunction, 4);
}

TEST(ContactIntegration, NodalPenaltyPointsAtASharedVertexShareTheirPressure) {
    // PENALISATION with INTEGRATION='NOEUD': two points per segment facet, but the two points that
    // neighbouring facets of one interface and one pair of blocks put at their shared vertex have the
    // same gap: they are one point (summed weight, one pressure unknown), else their equations
    // lambda = kappa g become dependent for large COEF_PENA_CONT. QUAD4 N = 5 (facets are sub-cell
    // segments, two per cut cell): FISS1 is two chains of 5 facets (x < 0 and x > 0 of the junction),
    // FISS2 and FISS3 one chain of 6 each: 22 facets, 44 vertex points, 26 distinct ones (facets + 1 per
    // chain).
    const auto s = contacttest::scene(CellType::QUAD4, 5, ContactAlgorithm::Penalty, false, {"NOEUD", 0});
    const int facets = int(s.terms->facets().size());
    EXPECT_EQ(facets, 22);
    EXPECT_EQ(int(s.terms->points().size()), 26);
    EXPECT_EQ(s.terms->mergedPenaltyPoints(), 18);
    EXPECT_EQ(s.terms->extraUnknowns(), 26);
    std::vector<int> multipliers;
    std::map<int, double> weightByZone, measureByZone;
    for (const auto& cp : s.terms->points()) {
        multipliers.push_back(cp.multiplier);
        weightByZone[cp.zone] += cp.weight;
    }
    for (const auto& f : s.terms->facets()) measureByZone[s.definition->zoneOfCrack(f.crack)] += f.measure;
    for (const auto& [zone, w] : weightByZone) EXPECT_NEAR(w, measureByZone[zone], 1e-14 * w) << zone;
    std::sort(multipliers.begin(), multipliers.end());
    EXPECT_EQ(std::adjacent_find(multipliers.begin(), multipliers.end()), multipliers.end());
    EXPECT_EQ(multipliers.front(), s.problem->numbering().size());
    EXPECT_EQ(multipliers.back(), s.problem->numbering().size() + 25);
    // With the vertex points kept apart the 3D slab was singular from COEF_PENA_CONT = 1e22 (TETRA4);
    // Nitsche points are never merged (each carries its own facet's stresses).
    const auto n = contacttest::scene(CellType::QUAD4, 5, ContactAlgorithm::Nitsche, false, {"NOEUD", 0});
    EXPECT_EQ(int(n.terms->points().size()), 2 * int(n.terms->facets().size()));
    EXPECT_EQ(n.terms->mergedPenaltyPoints(), 0);
}

TEST(ContactIntegration, TraceDegreeOfTheParentShapeFunctions) {
    using P = std::vector<Vec>;
    EXPECT_EQ(facetTraceDegree(CellType::TRIA3, P{{0.1, 0.2, 0}, {0.7, 0.3, 0}}), 1);
    EXPECT_EQ(facetTraceDegree(CellType::TETRA4, P{{0.1, 0.2, 0.1}, {0.7, 0.1, 0.2}, {0.1, 0.1, 0.6}}), 1);
    EXPECT_EQ(facetTraceDegree(CellType::QUAD4, P{{-1, 0.2, 0}, {1, 0.2, 0}}), 1);                 // along eta = 0.2
    EXPECT_EQ(facetTraceDegree(CellType::QUAD4, P{{-1, -1, 0}, {1, 1, 0}}), 2);                    // slanted: xi eta
    EXPECT_EQ(facetTraceDegree(CellType::QUAD4, P{{-1, 0.2, 0}, {1, 0.2 + 1e-12, 0}}), 1);         // round-off
    EXPECT_EQ(facetTraceDegree(CellType::HEXA8, P{{0.3, -1, -1}, {0.3, 1, -1}, {0.3, 1, 1}}), 2);  // eta zeta
    EXPECT_EQ(facetTraceDegree(CellType::HEXA8, P{{1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}), 3);
    EXPECT_EQ(gaussOrderFor(2, 2), 1);  // SE2 FPG2, degree 3
    EXPECT_EQ(gaussOrderFor(3, 2), 1);  // TR3 FPG3, degree 2
    EXPECT_EQ(gaussOrderFor(3, 3), 4);  // TR3 FPG6, degree 4 (FPG4, degree 3, has a negative weight)
    EXPECT_FALSE(positiveWeights(quadratureRule(CellType::TRIA3, "FPG4")));
    for (const char* family : {"FPG3", "FPG6", "FPG7", "FPG12", "NOEU", "SIMP"})
        EXPECT_TRUE(positiveWeights(quadratureRule(CellType::TRIA3, family))) << family;
    for (const char* family : {"FPG2", "FPG3", "FPG4", "NOEU", "SIMP", "SIMP1", "COTES", "COTES1", "COTES2"})
        EXPECT_TRUE(positiveWeights(quadratureRule(CellType::SEG2, family))) << family;
}

TEST(ContactIntegration, RulesTooWeakForTheTracesAreCounted) {
    // ssnv511 cut along grid lines: linear traces except on HEXA8 (bilinear on every facet).
    const auto hexa = contacttest::scene(CellType::HEXA8, 5, ContactAlgorithm::Nitsche, false, {"NOEUD", 0});
    ASSERT_FALSE(hexa.definition->zones.empty());
    ASSERT_EQ(hexa.terms->ruleShortfalls().size(), hexa.definition->zones.size());  // one per zone
    ASSERT_FALSE(hexa.terms->points().empty());
    for (const auto& s : hexa.terms->ruleShortfalls()) {
        EXPECT_GT(s.facets, 0);
        EXPECT_EQ(s.replaced, s.facets);
        EXPECT_EQ(s.ruleDegree, 1);
        EXPECT_EQ(s.traceDegree, 2);
        EXPECT_EQ(s.replacementOrder, 1);  // TR3 FPG3, degree 2
    }
    // The replaced facets carry the 3 points of TR3 FPG3, not the 3 vertices.
    for (const auto& p : hexa.terms->points()) {
        const auto& f = hexa.terms->facets()[size_t(p.facet)];
        for (const auto& v : f.vertices) {
            const double d = std::hypot(p.xyz[0] - v[0], p.xyz[1] - v[1], p.xyz[2] - v[2]);
            EXPECT_GT(d, 1e-6 * std::sqrt(f.measure));
        }
    }
    const auto gauss = contacttest::scene(CellType::HEXA8, 5, ContactAlgorithm::Nitsche, false, {"GAUSS", 1});
    ASSERT_EQ(gauss.terms->ruleShortfalls().size(), gauss.definition->zones.size());
    for (const auto& s : gauss.terms->ruleShortfalls()) {
        EXPECT_GT(s.facets, 0);
        EXPECT_EQ(s.replaced, 0);
    }
    for (CellType type : {CellType::QUAD4, CellType::TRIA3, CellType::TETRA4}) {
        const auto s = contacttest::scene(type, 5, ContactAlgorithm::Nitsche, false, {"NOEUD", 0});
        ASSERT_FALSE(s.definition->zones.empty()) << cellTypeName(type);
        ASSERT_EQ(s.terms->ruleShortfalls().size(), s.definition->zones.size()) << cellTypeName(type);
        for (const auto& r : s.terms->ruleShortfalls()) {
            EXPECT_GT(r.facets, 0) << cellTypeName(type);
            EXPECT_EQ(r.replaced, 0) << cellTypeName(type);
        }
    }
}

namespace {

// Per facet and unknown: the rule's value of int_facet g(v) for v = that unknown's shape function (the
// traction term of a unit normal stress, which the exact uniform-stress solution needs exactly).
std::map<std::pair<int, int>, double> tractionTerms(const ContactTerms& terms) {
    std::map<std::pair<int, int>, double> out;
    for (const auto& cp : terms.points())
        for (size_t i = 0; i < cp.dofs.size(); ++i) out[{cp.facet, cp.dofs[i]}] += cp.weight * cp.gap[i];
    return out;
}

// Largest difference between two rules' traction terms, relative to the largest term.
double tractionDifference(CellType type, const ContactIntegration& a, const ContactIntegration& b) {
    const auto sa = contacttest::scene(type, 5, ContactAlgorithm::Nitsche, false, a);
    const auto sb = contacttest::scene(type, 5, ContactAlgorithm::Nitsche, false, b);
    const auto ta = tractionTerms(*sa.terms), tb = tractionTerms(*sb.terms);
    double scale = 0.0, diff = 0.0;
    for (const auto& [key, v] : tb) {
        scale = std::max(scale, std::abs(v));
        const auto it = ta.find(key);
        diff = std::max(diff, std::abs(v - (it == ta.end() ? 0.0 : it->second)));
    }
    return diff / scale;
}

}  // namespace

TEST(ContactIntegration, DegreeOneRulesAreExactOnLinearFacetTracesOnly) {
    // The exact uniform-stress answer needs int sigma_n g(v) exactly for every test function v: the
    // traces of v on the facets are linear for TRIA3, TETRA4 and QUAD4 cut along a grid line, which
    // the vertex rule integrates exactly; on the triangular facets of a HEXA8 cut by x = 0 they are
    // bilinear (y z), which needs degree 2 (FPG3) and which NOEU and SIMP miss: there ContactTerms
    // takes TR3 FPG3 instead, so the terms are exact with every scheme.
    const ContactIntegration noeud{"NOEUD", 0}, reference{"GAUSS", 6};
    for (CellType type : {CellType::QUAD4, CellType::TRIA3, CellType::TETRA4})
        EXPECT_LT(tractionDifference(type, noeud, reference), 1e-13) << cellTypeName(type);
    EXPECT_LT(tractionDifference(CellType::TETRA4, {"SIMPSON", 1}, reference), 1e-13);
    EXPECT_LT(tractionDifference(CellType::HEXA8, {"GAUSS", 1}, reference), 1e-13);
    EXPECT_LT(tractionDifference(CellType::HEXA8, noeud, reference), 1e-13);
    EXPECT_LT(tractionDifference(CellType::HEXA8, {"SIMPSON", 1}, reference), 1e-13);
    // What the replacement avoids: the degree-1 TR3 rules miss the bilinear monomial l1 l2 (exact
    // integral 1/24 on the unit triangle) by far more than round-off.
    for (const char* family : {"NOEU", "SIMP"}) {
        const QuadratureRule& rule = quadratureRule(CellType::TRIA3, family);
        double q = 0.0;
        for (int i = 0; i < rule.size(); ++i) q += rule.weights[i] * rule.points[i][0] * rule.points[i][1];
        EXPECT_GT(std::abs(q - 1.0 / 24.0), 1e-3) << family;
    }
}
