#include "contact/ContactIntegration.hpp"

#include <fmt/format.h>

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

std::string describe(int dim, const ContactIntegration& in) {
    if (in.scheme == "NOEUD") return "INTEGRATION='NOEUD' (facet vertices)";
    return fmt::format("INTEGRATION='{}', ORDRE_INT={} ({} {})", in.scheme, in.order, dim == 2 ? "SE2" : "TR3",
                       facetFamily(dim, in));
}

}  // namespace ma::contact
