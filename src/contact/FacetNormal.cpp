#include "contact/FacetNormal.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace ma::contact {

namespace {

double det3(const std::array<std::array<double, 3>, 3>& m) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// Reference gradient of the linear interpolant of the values `l` at the sub-cell's vertices `r`
// (dim + 1 of them), by Cramer's rule on (r_v - r_0) . g = l_v - l_0; false when the sub-cell is
// flat in reference coordinates.
bool linearGradient(int dim, const std::array<std::array<double, 3>, 4>& r, const std::array<double, 4>& l, Vec3& g) {
    std::array<std::array<double, 3>, 3> m{};
    std::array<double, 3> rhs{};
    for (int v = 1; v <= dim; ++v) {
        for (int c = 0; c < dim; ++c) m[size_t(v - 1)][size_t(c)] = r[size_t(v)][size_t(c)] - r[0][size_t(c)];
        rhs[size_t(v - 1)] = l[size_t(v)] - l[0];
    }
    if (dim == 2) m[2][2] = 1.0;
    const double d = det3(m);
    double scale = 1.0;
    for (const auto& row : m) scale *= std::max({std::abs(row[0]), std::abs(row[1]), std::abs(row[2]), 1e-300});
    if (!(std::abs(d) > 1e-14 * scale)) return false;
    for (int c = 0; c < dim; ++c) {
        auto mc = m;
        for (int v = 0; v < dim; ++v) mc[size_t(v)][size_t(c)] = rhs[size_t(v)];
        g[size_t(c)] = det3(mc) / d;
    }
    return true;
}

// sum_a f(ref_a) grad N_a for the linear function f(xi) = g . xi: the physical gradient J^-T g
// (QUAD4/HEXA8 and the simplices reproduce linear functions of xi exactly).
Vec3 physicalGradient(const xfem::CellCut& cut, const Vec3& gRef, int nodeCount, const std::vector<double>& gradN) {
    Vec3 out{};
    for (int a = 0; a < nodeCount; ++a) {
        const auto& xi = cut.points[size_t(a)].ref;
        const double f = gRef[0] * xi[0] + gRef[1] * xi[1] + gRef[2] * xi[2];
        for (int c = 0; c < 3; ++c) out[size_t(c)] += f * gradN[size_t(a) * 3 + size_t(c)];
    }
    return out;
}

Vec3 oriented(Vec3 g, const ContactFacet& facet) {
    const double len = norm(g);
    if (!(len > 0.0)) return facet.normal;
    const double sign = dot(g, facet.normal) < 0.0 ? -1.0 : 1.0;
    for (auto& v : g) v *= sign / len;
    return g;
}

}  // namespace

Vec3 facetNormal(const xfem::CellCut& cut, const ContactFacet& facet, int subcell, int nodeCount,
                 const std::vector<double>& gradN) {
    const auto it = std::find(cut.cracks.begin(), cut.cracks.end(), facet.crack);
    if (it == cut.cracks.end()) return facet.normal;
    const size_t j = static_cast<size_t>(it - cut.cracks.begin());
    if (subcell >= 0 && subcell < static_cast<int>(cut.subcells.size())) {
        const auto& sub = cut.subcells[size_t(subcell)];
        std::array<std::array<double, 3>, 4> r{};
        std::array<double, 4> l{};
        for (int v = 0; v <= cut.dim; ++v) {
            r[size_t(v)] = cut.points[size_t(sub.vertices[size_t(v)])].ref;
            l[size_t(v)] = cut.points[size_t(sub.vertices[size_t(v)])].lsn[j];
        }
        Vec3 gRef{};
        if (linearGradient(cut.dim, r, l, gRef)) {
            const Vec3 g = physicalGradient(cut, gRef, nodeCount, gradN);
            if (norm(g) > 0.0) return oriented(g, facet);
        }
    }
    // The level set's own gradient at the point.
    Vec3 g{};
    for (int a = 0; a < nodeCount; ++a)
        for (int c = 0; c < 3; ++c) g[size_t(c)] += cut.points[size_t(a)].lsn[j] * gradN[size_t(a) * 3 + size_t(c)];
    return oriented(g, facet);
}

}  // namespace ma::contact
