#include "contact/ContactIntegration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "fe/Quadrature.hpp"

namespace ma::contact {

std::string facetFamily(int dim, const ContactIntegration& in) {
    const int n = in.order;
    if (in.scheme == "NOEUD") return "NOEU";
    if (dim == 2) {
        if (in.scheme == "GAUSS") return n <= 2 ? "FPG2" : n == 3 ? "FPG3" : "FPG4";
        if (in.scheme == "SIMPSON") return n == 1 ? "SIMP" : "SIMP1";
        if (in.scheme == "NCOTES") return n == 3 ? "COTES" : n <= 5 ? "COTES1" : "COTES2";
        return {};
    }
    // 3D: GAUSS order 6 is the family code_aster's X-FEM contact elements call 'GAUSS' on their TR3
    // facets, FPG12.
    if (in.scheme == "GAUSS") {
        static const char* const byOrder[] = {"FPG3", "FPG3", "FPG4", "FPG6", "FPG7", "FPG12"};
        return n >= 1 && n <= 6 ? byOrder[n - 1] : "";
    }
    if (in.scheme == "SIMPSON" && n == 1) return "SIMP";
    return {};
}

std::string missingRuleReason(int dim, const ContactIntegration& in) {
    if (!facetFamily(dim, in).empty()) return {};
    if (in.scheme == "NCOTES" && in.order > 5)
        return "code_aster's X-FEM contact (xminte) selects no integration family for it in 3D";
    const char* family = in.scheme == "SIMPSON" ? "SIMP1" : "COTES";
    return fmt::format(
        "code_aster's X-FEM contact (xminte) selects for it the family {}, which is defined on "
        "segment facets only (elraga has no {} for triangles)",
        family, family);
}

int facetTraceDegree(CellType parent, const std::vector<std::array<double, 3>>& ref) {
    if (parent != CellType::QUAD4 && parent != CellType::HEXA8) return 1;
    const int dim = parent == CellType::QUAD4 ? 2 : 3;
    // A coordinate that varies by less than this over the facet adds a non-linear part of that
    // relative size only: round-off of the cut's vertices, not a slanted facet.
    constexpr double kTolerance = 1e-9;
    int varying = 0;
    for (int k = 0; k < dim; ++k) {
        const auto [lo, hi] =
            std::minmax_element(ref.begin(), ref.end(), [k](const auto& a, const auto& b) { return a[k] < b[k]; });
        if ((*hi)[k] - (*lo)[k] > kTolerance) ++varying;
    }
    return std::max(varying, 1);
}

bool positiveWeights(const QuadratureRule& rule) {
    return std::all_of(rule.weights.begin(), rule.weights.end(), [](double w) { return w > 0.0; });
}

int gaussOrderFor(int dim, int degree) {
    for (int n = 1; n <= 6; ++n) {
        const auto& rule = quadratureRule(dim == 2 ? CellType::SEG2 : CellType::TRIA3, facetFamily(dim, {"GAUSS", n}));
        if (rule.degree >= degree && positiveWeights(rule)) return n;
    }
    return 6;
}

std::string describe(int dim, const ContactIntegration& in) {
    if (in.scheme == "NOEUD") return "INTEGRATION='NOEUD' (facet vertices)";
    return fmt::format("INTEGRATION='{}', ORDRE_INT={} ({} {})", in.scheme, in.order, dim == 2 ? "SE2" : "TR3",
                       facetFamily(dim, in));
}

}  // namespace ma::contact
