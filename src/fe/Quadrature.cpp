#include "fe/Quadrature.hpp"

#include <cmath>
#include <map>
#include <mutex>

#include "core/Error.hpp"
#include "mesh/ShapeFunctions.hpp"

namespace ma {

namespace {

using Point = std::array<double, 3>;

// Gauss-Legendre on [-1, 1].
void gaussLegendre(int n, std::vector<double>& x, std::vector<double>& w) {
    switch (n) {
        case 1:
            x = {0.0};
            w = {2.0};
            return;
        case 2: {
            const double a = 1.0 / std::sqrt(3.0);
            x = {-a, a};
            w = {1.0, 1.0};
            return;
        }
        case 3: {
            const double a = std::sqrt(0.6);
            x = {-a, 0.0, a};
            w = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
            return;
        }
        case 4: {
            const double s = 2.0 * std::sqrt(1.2);
            const double a = std::sqrt((3.0 - s) / 7.0), b = std::sqrt((3.0 + s) / 7.0);
            const double wa = (18.0 + std::sqrt(30.0)) / 36.0, wb = (18.0 - std::sqrt(30.0)) / 36.0;
            x = {-b, -a, a, b};
            w = {wb, wa, wa, wb};
            return;
        }
        default: throw NotImplemented("Gauss-Legendre rule with " + std::to_string(n) + " points");
    }
}

QuadratureRule segment(int n) {
    QuadratureRule r;
    r.family = "FPG" + std::to_string(n);
    r.cell = CellType::SEG2;
    r.degree = 2 * n - 1;
    std::vector<double> x, w;
    gaussLegendre(n, x, w);
    for (int i = 0; i < n; ++i) {
        r.points.push_back({x[i], 0, 0});
        r.weights.push_back(w[i]);
    }
    return r;
}

QuadratureRule quadrangle(int n) {
    QuadratureRule r;
    r.family = "FPG" + std::to_string(n * n);
    r.cell = CellType::QUAD4;
    r.degree = 2 * n - 1;
    std::vector<double> x, w;
    gaussLegendre(n, x, w);
    if (n == 2) {  // code_aster's order: counter-clockwise from (-a, -a)
        const double a = x[1];
        r.points = {{-a, -a, 0}, {a, -a, 0}, {a, a, 0}, {-a, a, 0}};
        r.weights = {1, 1, 1, 1};
        return r;
    }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            r.points.push_back({x[i], x[j], 0});
            r.weights.push_back(w[i] * w[j]);
        }
    return r;
}

QuadratureRule hexahedron(int n) {
    QuadratureRule r;
    r.family = "FPG" + std::to_string(n * n * n);
    r.cell = CellType::HEXA8;
    r.degree = 2 * n - 1;
    std::vector<double> x, w;
    gaussLegendre(n, x, w);
    for (int i = 0; i < n; ++i)  // code_aster's order: z fastest
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                r.points.push_back({x[i], x[j], x[k]});
                r.weights.push_back(w[i] * w[j] * w[k]);
            }
    return r;
}

// Symmetric orbits on the triangle, barycentric (a, a, 1-2a) and (a, b, 1-a-b).
void triangleOrbit3(QuadratureRule& r, double a, double w) {
    const double b = 1.0 - 2.0 * a;
    r.points.push_back({a, a, 0});
    r.points.push_back({b, a, 0});
    r.points.push_back({a, b, 0});
    r.weights.insert(r.weights.end(), 3, w);
}
void triangleOrbit6(QuadratureRule& r, double a, double b, double w) {
    const double c = 1.0 - a - b;
    for (const auto& p : std::array<Point, 6>{{{a, b, 0}, {b, a, 0}, {a, c, 0}, {c, a, 0}, {b, c, 0}, {c, b, 0}}})
        r.points.push_back(p);
    r.weights.insert(r.weights.end(), 6, w);
}

QuadratureRule triangle(int n) {
    QuadratureRule r;
    r.family = "FPG" + std::to_string(n);
    r.cell = CellType::TRIA3;
    switch (n) {
        case 1:
            r.degree = 1;
            r.points = {{1.0 / 3, 1.0 / 3, 0}};
            r.weights = {0.5};
            break;
        case 3:
            r.degree = 2;
            triangleOrbit3(r, 1.0 / 6, 1.0 / 6);
            break;
        case 4:
            r.degree = 3;
            r.points = {{1.0 / 3, 1.0 / 3, 0}};
            r.weights = {-27.0 / 96};
            r.points.push_back({0.2, 0.2, 0});
            r.points.push_back({0.6, 0.2, 0});
            r.points.push_back({0.2, 0.6, 0});
            r.weights.insert(r.weights.end(), 3, 25.0 / 96);
            break;
        case 6:  // Strang-Fix / Dunavant degree 4
            r.degree = 4;
            triangleOrbit3(r, 0.445948490915965, 0.111690794839005);
            triangleOrbit3(r, 0.091576213509771, 0.054975871827661);
            break;
        case 7: {  // Radon's degree-5 rule, closed form
            r.degree = 5;
            const double s = std::sqrt(15.0);
            r.points = {{1.0 / 3, 1.0 / 3, 0}};
            r.weights = {9.0 / 80};
            triangleOrbit3(r, (6.0 - s) / 21.0, (155.0 - s) / 2400.0);
            triangleOrbit3(r, (6.0 + s) / 21.0, (155.0 + s) / 2400.0);
            break;
        }
        case 12:  // Dunavant degree 6 (values of code_aster's elraga, xfem_spec §3.6)
            r.degree = 6;
            triangleOrbit3(r, 0.063089014491502, 0.025422453185103);
            triangleOrbit3(r, 0.249286745170910, 0.058393137863189);
            triangleOrbit6(r, 0.310352451033785, 0.053145049844816, 0.041425537809187);
            break;
        default: throw NotImplemented("triangle rule FPG" + std::to_string(n));
    }
    return r;
}

// Tetrahedron orbits, barycentric (a,a,a,1-3a) and (a,a,b,b) with b = 1/2 - a.
void tetraOrbit4(QuadratureRule& r, double a, double w) {
    const double b = 1.0 - 3.0 * a;
    for (const auto& p : std::array<Point, 4>{{{a, a, a}, {b, a, a}, {a, b, a}, {a, a, b}}}) r.points.push_back(p);
    r.weights.insert(r.weights.end(), 4, w);
}
void tetraOrbit6(QuadratureRule& r, double a, double w) {
    const double b = 0.5 - a;
    for (const auto& p : std::array<Point, 6>{{{a, a, b}, {a, b, a}, {b, a, a}, {a, b, b}, {b, a, b}, {b, b, a}}})
        r.points.push_back(p);
    r.weights.insert(r.weights.end(), 6, w);
}
// The 12 distinct permutations of barycentric (a, a, b, c), c = 1 - 2a - b.
void tetraOrbit12(QuadratureRule& r, double a, double b, double w) {
    const double c = 1.0 - 2.0 * a - b;
    for (int i = 0; i < 4; ++i)        // position of b
        for (int j = 0; j < 4; ++j) {  // position of c
            if (j == i) continue;
            std::array<double, 4> l{a, a, a, a};
            l[i] = b;
            l[j] = c;
            r.points.push_back({l[1], l[2], l[3]});
        }
    r.weights.insert(r.weights.end(), 12, w);
}

QuadratureRule tetrahedron(int n) {
    QuadratureRule r;
    r.family = "FPG" + std::to_string(n);
    r.cell = CellType::TETRA4;
    switch (n) {
        case 1:
            r.degree = 1;
            r.points = {{0.25, 0.25, 0.25}};
            r.weights = {1.0 / 6};
            break;
        case 4:
            r.degree = 2;
            tetraOrbit4(r, (5.0 - std::sqrt(5.0)) / 20.0, 1.0 / 24);
            break;
        case 5:
            r.degree = 3;
            r.points = {{0.25, 0.25, 0.25}};
            r.weights = {-2.0 / 15};
            tetraOrbit4(r, 1.0 / 6, 3.0 / 40);
            break;
        case 15: {  // Keast's degree-5 rule, closed form
            r.degree = 5;
            const double s = std::sqrt(15.0);
            r.points = {{0.25, 0.25, 0.25}};
            r.weights = {8.0 / 405};
            tetraOrbit4(r, (7.0 - s) / 34.0, (2665.0 + 14.0 * s) / 226800.0);
            tetraOrbit4(r, (7.0 + s) / 34.0, (2665.0 - 14.0 * s) / 226800.0);
            tetraOrbit6(r, (5.0 - s) / 20.0, 5.0 / 567);
            break;
        }
        case 24:  // degree 6, Witherden & Vincent (2015), the values of code_aster's elraga FPG24
            r.degree = 6;
            tetraOrbit4(r, 0.040673958534611353, 0.001679535175886774);
            tetraOrbit4(r, 0.322337890142275510, 0.009226196923942455);
            tetraOrbit4(r, 0.214602871259152029, 0.006653791709694583);
            tetraOrbit12(r, 0.063661001875017525, 0.269672331458315808, 9.0 / 1120);
            break;
        default: throw NotImplemented("tetrahedron rule FPG" + std::to_string(n));
    }
    return r;
}

// Rules from explicit points and weights (1D: x only).
QuadratureRule listed(CellType cell, std::string family, int degree, std::vector<double> x, std::vector<double> w) {
    QuadratureRule r;
    r.family = std::move(family);
    r.cell = cell;
    r.degree = degree;
    for (double v : x) r.points.push_back({v, 0, 0});
    r.weights = std::move(w);
    return r;
}

double referenceMeasure(CellType cell) {
    switch (cell) {
        case CellType::SEG2: return 2.0;
        case CellType::TRIA3: return 0.5;
        case CellType::QUAD4: return 4.0;
        case CellType::TETRA4: return 1.0 / 6.0;
        case CellType::HEXA8: return 8.0;
        default: throw NotImplemented("integration family NOEU on " + cellTypeName(cell));
    }
}

// code_aster's named families that are not Gauss rules (elraga): NOEU on every cell (the vertices,
// each weighted by measure / vertex count: exact for the multilinear functions of the cell), and
// the closed Newton-Cotes families of the X-FEM contact facets. Their degrees were checked on the
// monomials (tests/unit/fe_quadrature.cpp); TRIA3 SIMP (vertices 1/30, edge midpoints 4/30) is exact
// for degree 1 only, as written in elraga.
bool buildNamed(CellType cell, const std::string& family, QuadratureRule& r) {
    if (family == "NOEU") {
        r.family = family;
        r.cell = cell;
        r.degree = 1;
        const auto nodes = referenceNodes(cell);
        const double w = referenceMeasure(cell) / double(nodes.size());
        for (const auto& p : nodes) {
            r.points.push_back(p);
            r.weights.push_back(w);
        }
        return true;
    }
    if (cell == CellType::SEG2) {
        const double t = 1.0 / 3.0, s = 1.0 / 9.0;
        if (family == "SIMP")  // Simpson
            r = listed(cell, family, 3, {-1, 0, 1}, {t, 4 * t, t});
        else if (family == "SIMP1")  // Simpson on the two halves
            r = listed(cell, family, 3, {-1, -0.5, 0, 0.5, 1}, {1.0 / 6, 2 * t, t, 2 * t, 1.0 / 6});
        else if (family == "COTES")  // Simpson's 3/8 rule
            r = listed(cell, family, 3, {-1, -t, t, 1}, {0.25, 0.75, 0.75, 0.25});
        else if (family == "COTES1")  // Boole's rule
            r = listed(cell, family, 5, {-1, -0.5, 0, 0.5, 1}, {7.0 / 45, 32.0 / 45, 12.0 / 45, 32.0 / 45, 7.0 / 45});
        else if (family == "COTES2")  // the 3/8 rule on three thirds
            r = listed(cell, family, 3, {-1, -7 * s, -5 * s, -3 * s, -s, s, 3 * s, 5 * s, 7 * s, 1},
                       {1.0 / 12, 0.25, 0.25, 1.0 / 6, 0.25, 0.25, 1.0 / 6, 0.25, 0.25, 1.0 / 12});
        else return false;
        return true;
    }
    if (cell == CellType::TRIA3 && family == "SIMP") {
        r.family = family;
        r.cell = cell;
        r.degree = 1;
        r.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0, 0}, {0.5, 0.5, 0}, {0, 0.5, 0}};
        r.weights = {1.0 / 30, 1.0 / 30, 1.0 / 30, 4.0 / 30, 4.0 / 30, 4.0 / 30};
        return true;
    }
    return false;
}

QuadratureRule build(CellType cell, int n) {
    switch (cell) {
        case CellType::SEG2: return segment(n);
        case CellType::TRIA3: return triangle(n);
        case CellType::QUAD4: {
            const int m = static_cast<int>(std::lround(std::sqrt(double(n))));
            if (m * m != n) break;
            return quadrangle(m);
        }
        case CellType::TETRA4: return tetrahedron(n);
        case CellType::HEXA8: {
            const int m = static_cast<int>(std::lround(std::cbrt(double(n))));
            if (m * m * m != n) break;
            return hexahedron(m);
        }
        default: break;
    }
    throw NotImplemented("integration family FPG" + std::to_string(n) + " on " + cellTypeName(cell));
}

}  // namespace

const QuadratureRule& quadratureRule(CellType cell, const std::string& family) {
    static std::mutex mutex;
    static std::map<std::pair<int, std::string>, QuadratureRule> cache;
    std::lock_guard<std::mutex> lock(mutex);
    auto key = std::make_pair(static_cast<int>(cell), family);
    auto it = cache.find(key);
    if (it != cache.end()) return it->second;
    if (QuadratureRule named; buildNamed(cell, family, named))
        return cache.emplace(key, std::move(named)).first->second;
    if (family.rfind("FPG", 0) != 0 || family.size() == 3 ||
        family.find_first_not_of("0123456789", 3) != std::string::npos)
        throw NotImplemented("integration family " + family + " on " + cellTypeName(cell));
    const int n = std::stoi(family.substr(3));
    return cache.emplace(key, build(cell, n)).first->second;
}

const QuadratureRule& stiffnessRule(CellType cell, bool boundary) {
    // Called once per element: resolved once, without the string lookup of quadratureRule.
    static const QuadratureRule& seg2 = quadratureRule(CellType::SEG2, "FPG2");
    static const QuadratureRule& tria1 = quadratureRule(CellType::TRIA3, "FPG1");
    static const QuadratureRule& tria3 = quadratureRule(CellType::TRIA3, "FPG3");
    static const QuadratureRule& quad4 = quadratureRule(CellType::QUAD4, "FPG4");
    static const QuadratureRule& tetra1 = quadratureRule(CellType::TETRA4, "FPG1");
    static const QuadratureRule& hexa8 = quadratureRule(CellType::HEXA8, "FPG8");
    switch (cell) {
        case CellType::SEG2: return seg2;
        case CellType::TRIA3: return boundary ? tria3 : tria1;
        case CellType::QUAD4: return quad4;
        case CellType::TETRA4: return tetra1;
        case CellType::HEXA8: return hexa8;
        default: throw NotImplemented("no mechanical element for cell type " + cellTypeName(cell));
    }
}

}  // namespace ma
