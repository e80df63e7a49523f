#include "xfem/TipEnrichment.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <span>

#include "core/Error.hpp"
#include "mesh/ElementGeometry.hpp"
#include "mesh/PointLocation.hpp"
#include "mesh/ShapeFunctions.hpp"

namespace ma::xfem {

namespace {

// Nearest point of the segment [a, b] to x.
Vec3 nearestOnSegment(const Vec3& a, const Vec3& b, const Vec3& x) {
    const Vec3 ab = difference(b, a);
    const double l2 = dot(ab, ab);
    const double t = l2 > 0 ? std::clamp(dot(difference(x, a), ab) / l2, 0.0, 1.0) : 0.0;
    return {a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2]};
}

Vec3 nearestOnFronts(const Crack& crack, const Vec3& x) {
    Vec3 best{};
    double bestDistance = std::numeric_limits<double>::infinity();
    auto consider = [&](const Vec3& p) {
        if (const double d = distance(p, x); d < bestDistance) bestDistance = d, best = p;
    };
    for (const auto& f : crack.fronts) {
        if (f.points.size() == 1) consider(f.points[0]);
        for (size_t i = 0; i + 1 < f.points.size(); ++i) consider(nearestOnSegment(f.points[i], f.points[i + 1], x));
    }
    return best;
}

// sqrt(r / 2 pi) h(theta) and its derivatives along x1, x2 for h and h' given.
void polar(double r, double theta, double h, double dh, double& value, double d[2]) {
    const double s = std::sqrt(r / (2.0 * std::numbers::pi));
    value = s * h;
    const double dr = value / (2.0 * r), dt = s * dh;
    d[0] = dr * std::cos(theta) - dt * std::sin(theta) / r;
    d[1] = dr * std::sin(theta) + dt * std::cos(theta) / r;
}

}  // namespace

namespace {

FrontBasis orthonormalBasis(const Vec3& origin, const Vec3& gn, const Vec3& gt) {
    FrontBasis b;
    b.origin = origin;
    b.e2 = unit(gn);
    const double c = dot(gt, b.e2);
    b.e1 = unit({gt[0] - c * b.e2[0], gt[1] - c * b.e2[1], gt[2] - c * b.e2[2]});
    return b;
}

// 2D (code_aster's xptfon / intfac then xbaslo): the basis of each front point from the nodal
// gradients interpolated at the point. A node's own averaged gradient would not do: LST =
// |s.(x - M)| - a of a SEGMENT crack has none on the perpendicular bisector, which the front's
// point never lies on.
std::vector<FrontBasis> frontPointBases2D(const Mesh& mesh, const Crack& crack, const std::vector<Vec3>& gn,
                                          const std::vector<Vec3>& gt) {
    std::vector<FrontBasis> tips;
    std::vector<double> component(gn.size());
    auto interpolate = [&](const std::vector<Vec3>& g, const PointInCell& at) {
        Vec3 v{};
        for (int c = 0; c < 2; ++c) {
            for (size_t n = 0; n < g.size(); ++n) component[n] = g[n][size_t(c)];
            v[size_t(c)] = interpolateAt(mesh, at, component);
        }
        return v;
    };
    for (const auto& f : crack.fronts)
        for (const Vec3& p : f.points) {
            const PointInCell at = locatePoint(mesh, p);
            if (at.cell < 0) throw InternalError("crack " + crack.name + ": a front point lies in no cell");
            tips.push_back(orthonormalBasis(p, interpolate(gn, at), interpolate(gt, at)));
            if (norm(tips.back().e1) == 0.0 || norm(tips.back().e2) == 0.0)
                throw UserError("crack " + crack.name +
                                ": the level sets have no gradient at a front point, so the local front basis "
                                "(BASLOC) is undefined there");
        }
    return tips;
}

}  // namespace

std::vector<FrontBasis> frontPointBases(const Mesh& mesh, const Crack& crack) {
    return frontPointBases2D(mesh, crack, nodalLevelSetGradient(mesh, crack.lsn),
                             nodalLevelSetGradient(mesh, crack.lst));
}

size_t nearestFrontPoint(const std::vector<FrontBasis>& points, const Vec3& x) {
    size_t best = 0;
    for (size_t t = 1; t < points.size(); ++t)
        if (distance(points[t].origin, x) < distance(points[best].origin, x)) best = t;
    return best;
}

std::vector<FrontBasis> frontBases(const Mesh& mesh, const Crack& crack, const std::vector<char>& nodes) {
    std::vector<FrontBasis> out(size_t(mesh.nodeCount()));
    if (mesh.maxCellDimension() == 2) {  // the basis of the nearest front point
        const auto points = frontPointBases(mesh, crack);
        for (int n = 0; n < mesh.nodeCount(); ++n)
            if (nodes[size_t(n)] && !points.empty())
                out[size_t(n)] = points[nearestFrontPoint(points, mesh.coords[size_t(n)])];
        return out;
    }
    const auto gn = nodalLevelSetGradient(mesh, crack.lsn);
    const auto gt = nodalLevelSetGradient(mesh, crack.lst);
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        if (!nodes[size_t(n)]) continue;
        FrontBasis& b = out[size_t(n)];
        b = orthonormalBasis(nearestOnFronts(crack, mesh.coords[size_t(n)]), gn[size_t(n)], gt[size_t(n)]);
        if (norm(b.e1) == 0.0 || norm(b.e2) == 0.0)
            throw UserError("crack " + crack.name + ": the level sets have no gradient at node " +
                            mesh.nodeNames[size_t(n)] + ", so the local front basis (BASLOC) is undefined there");
    }
    return out;
}

AsymptoticFields asymptoticFields(double r, double theta, int dim) {
    AsymptoticFields f;
    const double c2 = std::cos(theta / 2), s2 = std::sin(theta / 2), c = std::cos(theta), s = std::sin(theta);
    // h and h' of the kappa part (a) and the rest (b), per mode m and local component k.
    struct Term {
        int m, k;
        double a, da, b, db;
    };
    const Term terms[] = {
        {0, 0, c2, -0.5 * s2, -c * c2, s * c2 + 0.5 * c * s2},
        {0, 1, s2, 0.5 * c2, -c * s2, s * s2 - 0.5 * c * c2},
        {1, 0, s2, 0.5 * c2, (2 + c) * s2, -s * s2 + 0.5 * (2 + c) * c2},
        {1, 1, -c2, 0.5 * s2, (2 - c) * c2, s * c2 - 0.5 * (2 - c) * s2},
        {2, 2, 0.0, 0.0, 4 * s2, 2 * c2},
    };
    for (const Term& t : terms) {
        if (t.m == 2 && dim < 3) continue;
        polar(r, theta, t.a, t.da, f.A[t.m][t.k], f.dA[t.m][t.k]);
        polar(r, theta, t.b, t.db, f.B[t.m][t.k], f.dB[t.m][t.k]);
    }
    return f;
}

void gaussLegendre01(int n, std::vector<double>& x, std::vector<double>& w) {
    x.assign(size_t(n), 0.0);
    w.assign(size_t(n), 0.0);
    for (int i = 0; i < n; ++i) {
        double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), dp = 1.0;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1.0, p1 = z;
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
                p0 = p1, p1 = p2;
            }
            if (n == 1) p1 = z, p0 = 1.0;
            dp = n * (z * p1 - p0) / (z * z - 1.0);
            const double dz = p1 / dp;
            z -= dz;
            if (std::abs(dz) < 1e-16) break;
        }
        x[size_t(i)] = 0.5 * (1.0 - z);
        w[size_t(i)] = 1.0 / ((1.0 - z * z) * dp * dp);
    }
}

void collapsedTriangleRule(const std::array<double, 3>& P0, const std::array<double, 3>& P1,
                           const std::array<double, 3>& P2, int n, bool singular,
                           std::vector<std::array<double, 3>>& points, std::vector<double>& weights) {
    std::vector<double> g, gw;
    gaussLegendre01(n, g, gw);
    Vec3 u{}, v{};
    for (int j = 0; j < 3; ++j)
        u[size_t(j)] = P1[size_t(j)] - P0[size_t(j)], v[size_t(j)] = P2[size_t(j)] - P0[size_t(j)];
    const double det = std::abs(u[0] * v[1] - u[1] * v[0]);
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < n; ++k) {
            const double s = g[size_t(i)], t = g[size_t(k)];
            const double rho = singular ? s * s : s;
            const double jac = singular ? 2.0 * s * rho : rho;  // d(rho) = 2 s ds; area element rho
            std::array<double, 3> x{};
            for (int j = 0; j < 3; ++j)
                x[size_t(j)] = P0[size_t(j)] + rho * ((1 - t) * u[size_t(j)] + t * v[size_t(j)]);
            points.push_back(x);
            weights.push_back(gw[size_t(i)] * gw[size_t(k)] * jac * det);
        }
}

namespace {

double area2d(const std::array<double, 3>& a, const std::array<double, 3>& b, const std::array<double, 3>& c) {
    return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

// Splits V towards the nearest front point while it is closer than the piece's size.
void refinedRule(const std::array<std::array<double, 3>, 3>& V,
                 const std::function<Vec3(const std::array<double, 3>&)>& toPhysical, const std::vector<Vec3>& tips,
                 int n, int levels, std::vector<std::array<double, 3>>& points, std::vector<double>& weights) {
    const Vec3 P[3] = {toPhysical(V[0]), toPhysical(V[1]), toPhysical(V[2])};
    const double diameter = std::max({distance(P[0], P[1]), distance(P[1], P[2]), distance(P[2], P[0])});
    double near = std::numeric_limits<double>::infinity();
    for (const Vec3& t : tips)
        for (int e = 0; e < 3; ++e) near = std::min(near, distance(t, nearestOnSegment(P[e], P[(e + 1) % 3], t)));
    if (levels == 0 || near >= diameter) return collapsedTriangleRule(V[0], V[1], V[2], n, false, points, weights);
    std::array<std::array<double, 3>, 3> M;
    for (int e = 0; e < 3; ++e)
        for (int j = 0; j < 3; ++j)
            M[size_t(e)][size_t(j)] = 0.5 * (V[size_t(e)][size_t(j)] + V[size_t((e + 1) % 3)][size_t(j)]);
    for (const auto& piece : {std::array{V[0], M[0], M[2]}, std::array{M[0], V[1], M[1]}, std::array{M[2], M[1], V[2]},
                              std::array{M[0], M[1], M[2]}})
        refinedRule(piece, toPhysical, tips, n, levels - 1, points, weights);
}

}  // namespace

void tipTriangleRule(const std::array<std::array<double, 3>, 3>& V, const std::optional<std::array<double, 3>>& tipRef,
                     const std::function<Vec3(const std::array<double, 3>&)>& toPhysical, const std::vector<Vec3>& tips,
                     int n, int levels, std::vector<std::array<double, 3>>& points, std::vector<double>& weights) {
    const double signedWhole = area2d(V[0], V[1], V[2]), whole = std::abs(signedWhole);
    // The cut computes its points to round-off of the parent only (a point of the front on a cut
    // edge may be 1e-10 of the cell off), so "contains" has a slack: a front point just outside is
    // still the fan's apex, the fan piece on the far side then has a negative weight.
    bool inside = tipRef.has_value();
    for (int v = 0; v < 3 && inside; ++v)
        inside = area2d(*tipRef, V[size_t(v)], V[size_t((v + 1) % 3)]) * signedWhole >= -1e-8 * whole * whole;
    if (!inside) return refinedRule(V, toPhysical, tips, n, levels, points, weights);
    for (int v = 0; v < 3; ++v) {  // fan from the front point: it is a vertex of every piece
        const auto& a = V[size_t(v)];
        const auto& b = V[size_t((v + 1) % 3)];
        const double piece = area2d(*tipRef, a, b);
        if (std::abs(piece) <= 1e-14 * whole) continue;
        const size_t first = weights.size();
        collapsedTriangleRule(*tipRef, a, b, 4 * n, true, points, weights);
        if (piece * signedWhole < 0)
            for (size_t q = first; q < weights.size(); ++q) weights[q] = -weights[q];
    }
}

std::optional<std::array<double, 3>> referencePointIn(const Mesh& mesh, int cell, const Vec3& x) {
    const CellType type = mesh.cellTypes[size_t(cell)];
    const auto nodes = mesh.cellNodes(cell);
    const bool quad = type == CellType::QUAD4;
    std::array<double, 3> xi = quad ? std::array<double, 3>{0, 0, 0} : std::array<double, 3>{1.0 / 3, 1.0 / 3, 0};
    std::vector<double> N(nodes.size());
    std::array<double, 24> dN{};
    for (int it = 0; it < 50; ++it) {
        shapeValues(type, xi, N);
        shapeDerivatives(type, xi, dN);
        double r[2] = {-x[0], -x[1]}, J[2][2] = {{0, 0}, {0, 0}};
        for (size_t a = 0; a < nodes.size(); ++a)
            for (int i = 0; i < 2; ++i) {
                r[i] += N[a] * mesh.coords[size_t(nodes[a])][size_t(i)];
                for (int j = 0; j < 2; ++j) J[i][j] += mesh.coords[size_t(nodes[a])][size_t(i)] * dN[3 * a + size_t(j)];
            }
        const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
        if (det == 0.0) return std::nullopt;
        const double d0 = (J[1][1] * r[0] - J[0][1] * r[1]) / det, d1 = (-J[1][0] * r[0] + J[0][0] * r[1]) / det;
        xi[0] -= d0, xi[1] -= d1;
        if (std::abs(d0) + std::abs(d1) < 1e-15) break;
    }
    const double tol = 1e-10;
    const bool inside = quad ? std::abs(xi[0]) <= 1 + tol && std::abs(xi[1]) <= 1 + tol
                             : xi[0] >= -tol && xi[1] >= -tol && xi[0] + xi[1] <= 1 + tol;
    if (!inside) return std::nullopt;
    return xi;
}

}  // namespace ma::xfem

namespace ma::xfem {

namespace {

double det3(const Vec3& a, const Vec3& b, const Vec3& c) { return dot(a, cross(b, c)); }

Vec3 combine(const Vec3& a, double s, const Vec3& b) { return {a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]}; }

// The cones from the line to the oriented triangle (Q, B, C), collapsed at Q in the face.
void fannedFacePiece(const Vec3& Q, const Vec3& B, const Vec3& C, const Vec3& O, const Vec3& t,
                     const std::vector<double>& g, const std::vector<double>& gw, const std::vector<double>& a,
                     const std::vector<double>& aw, std::vector<std::array<double, 3>>& points,
                     std::vector<double>& weights) {
    const Vec3 qb = difference(B, Q), bc = difference(C, B);
    auto normalPart = [&](const Vec3& v) { return combine(v, -dot(v, t), t); };
    for (size_t k = 0; k < a.size(); ++k) {
        const Vec3 dir = combine(qb, a[k], bc);  // y = Q + u dir, dy/dtau = u (C - B)
        for (size_t j = 0; j < g.size(); ++j) {
            const double u = g[j] * g[j];
            const Vec3 y = combine(Q, u, dir);
            const Vec3 d = normalPart(difference(y, O));
            const Vec3 yu = dir, yt{u * bc[0], u * bc[1], u * bc[2]};
            for (size_t i = 0; i < g.size(); ++i) {
                const double rho = g[i] * g[i];
                // x = y - (1 - rho) d; dx/drho = d, dx/du = yu - (1 - rho) normal(yu), same for tau.
                const Vec3 xu = combine(yu, rho - 1.0, normalPart(yu)), xt = combine(yt, rho - 1.0, normalPart(yt));
                const double jac = det3(d, xu, xt) * 2.0 * g[i] * 2.0 * g[j];
                const Vec3 x = combine(y, rho - 1.0, d);
                points.push_back({x[0], x[1], x[2]});
                weights.push_back(gw[i] * gw[j] * aw[k] * jac);
            }
        }
    }
}

// A face (nearly) parallel to the line, fanned from it: the face as (tau, z), z along the line's
// direction in the face plane and tau across it, so that the distance to the line, |d|, and the
// polar angle depend on tau only (exactly when the face is parallel): tau takes the angular
// points, z and rho = s^2 the radial ones (the integrand is polynomial in them). The face (F
// outward) is split at its middle vertex in tau into two pieces bounded by lines z(tau).
void fannedParallelFace(const Vec3 F[3], const Vec3& nOut, const Vec3& O, const Vec3& t, const std::vector<double>& g,
                        const std::vector<double>& gw, const std::vector<double>& a, const std::vector<double>& aw,
                        std::vector<std::array<double, 3>>& points, std::vector<double>& weights) {
    auto normalPart = [&](const Vec3& v) { return combine(v, -dot(v, t), t); };
    const Vec3 n = unit(nOut);
    const Vec3 tf = unit(combine(t, -dot(t, n), n));
    const Vec3 w = cross(tf, n);  // w x tf = n: (tau, z) oriented like the outward face
    std::array<std::array<double, 2>, 3> P;
    for (int i = 0; i < 3; ++i) P[size_t(i)] = {dot(difference(F[i], F[0]), w), dot(difference(F[i], F[0]), tf)};
    std::sort(P.begin(), P.end());
    auto zOn = [&](int i, int j, double tau) {  // z of the edge P_i P_j at tau
        const double span = P[size_t(j)][0] - P[size_t(i)][0];
        return span == 0.0 ? P[size_t(i)][1]
                           : P[size_t(i)][1] + (tau - P[size_t(i)][0]) / span * (P[size_t(j)][1] - P[size_t(i)][1]);
    };
    const Vec3 xt0 = normalPart(w), xz0 = normalPart(tf);
    for (int piece = 0; piece < 2; ++piece) {
        const double ta = P[size_t(piece)][0], tb = P[size_t(piece + 1)][0];
        if (tb - ta <= 0.0) continue;
        for (size_t k = 0; k < a.size(); ++k) {
            const double tau = ta + a[k] * (tb - ta);
            const double z0 = zOn(0, 2, tau), z1 = piece == 0 ? zOn(0, 1, tau) : zOn(1, 2, tau);
            for (size_t j = 0; j < g.size(); ++j) {
                const double z = z0 + g[j] * (z1 - z0);
                const Vec3 y = combine(combine(F[0], tau, w), z, tf);
                const Vec3 d = normalPart(difference(y, O));
                for (size_t i = 0; i < g.size(); ++i) {
                    const double rho = g[i] * g[i];
                    const Vec3 xt = combine(w, rho - 1.0, xt0), xz = combine(tf, rho - 1.0, xz0);
                    const Vec3 x = combine(y, rho - 1.0, d);
                    points.push_back({x[0], x[1], x[2]});
                    weights.push_back(gw[i] * gw[j] * aw[k] * (tb - ta) * std::abs(z1 - z0) * 2.0 * g[i] *
                                      det3(d, xt, xz));
                }
            }
        }
    }
}

}  // namespace

void fannedTetrahedronRule(const std::array<std::array<double, 3>, 4>& V, const Vec3& O, const Vec3& t, int nRadial,
                           int nAngular, std::vector<std::array<double, 3>>& points, std::vector<double>& weights) {
    std::vector<double> g, gw, a, aw;
    gaussLegendre01(nRadial, g, gw);
    gaussLegendre01(nAngular, a, aw);
    Vec3 P[4];
    for (int v = 0; v < 4; ++v) P[v] = {V[size_t(v)][0], V[size_t(v)][1], V[size_t(v)][2]};
    const double size = std::max({distance(P[0], P[1]), distance(P[0], P[2]), distance(P[0], P[3])});
    for (int f = 0; f < 4; ++f) {  // face opposite vertex f, oriented outwards
        Vec3 F[3];
        for (int v = 0, k = 0; v < 4; ++v)
            if (v != f) F[k++] = P[v];
        Vec3 n = cross(difference(F[1], F[0]), difference(F[2], F[0]));
        if (dot(n, difference(F[0], P[f])) < 0) std::swap(F[1], F[2]), n = Vec3{-n[0], -n[1], -n[2]};
        const double area2 = norm(n);
        if (area2 <= 0) continue;
        // A face in a plane holding the line adds nothing (its cones are flat).
        const double along = dot(n, t) / area2, offset = dot(n, difference(O, F[0])) / area2;
        if (std::abs(along) < 1e-12 && std::abs(offset) < 1e-12 * size) continue;
        // Where the line crosses the face's plane: the apex of the face's Duffy pieces, signed when it
        // lies outside the face, so that the distance to the line is u |g(angle)| on every piece.
        // Only within a cell size of the face's centre: farther, the signed pieces reach far outside the element, where
        // a curved front's fields are not the same smooth function (a penny crack's opening came
        // out 5 times too large with 10 sizes); such faces, nearly parallel to the line, are
        // parametrised across and along it (exact when parallel).
        std::optional<Vec3> pierce;
        if (std::abs(along) > 1e-12) {
            const Vec3 q = combine(O, -offset / along, t);
            const Vec3 centre{(F[0][0] + F[1][0] + F[2][0]) / 3, (F[0][1] + F[1][1] + F[2][1]) / 3,
                              (F[0][2] + F[1][2] + F[2][2]) / 3};
            if (distance(q, centre) <= size) pierce = q;
        }
        if (!pierce) {
            fannedParallelFace(F, n, O, t, g, gw, a, aw, points, weights);
            continue;
        }
        for (int e = 0; e < 3; ++e) {
            const double piece = norm(cross(difference(F[e], *pierce), difference(F[(e + 1) % 3], *pierce)));
            if (piece > 1e-14 * area2)
                fannedFacePiece(*pierce, F[e], F[(e + 1) % 3], O, t, g, gw, a, aw, points, weights);
        }
    }
}

void tetrahedronGaussRule(const std::array<std::array<double, 3>, 4>& V, int n,
                          std::vector<std::array<double, 3>>& points, std::vector<double>& weights) {
    std::vector<double> g, gw;
    gaussLegendre01(n, g, gw);
    Vec3 e[3];
    for (int v = 0; v < 3; ++v)
        for (int j = 0; j < 3; ++j) e[v][size_t(j)] = V[size_t(v + 1)][size_t(j)] - V[0][size_t(j)];
    const double volume6 = std::abs(det3(e[0], e[1], e[2]));
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                const double a = g[size_t(i)], b = g[size_t(j)], c = g[size_t(k)];
                const double l1 = a, l2 = b * (1 - a), l3 = c * (1 - a) * (1 - b);
                std::array<double, 3> x{};
                for (int m = 0; m < 3; ++m)
                    x[size_t(m)] = V[0][size_t(m)] + l1 * e[0][size_t(m)] + l2 * e[1][size_t(m)] + l3 * e[2][size_t(m)];
                points.push_back(x);
                weights.push_back(gw[size_t(i)] * gw[size_t(j)] * gw[size_t(k)] * (1 - a) * (1 - a) * (1 - b) *
                                  volume6);
            }
}

std::array<double, 3> referenceCoordinates(const Mesh& mesh, int cell, const Vec3& x) {
    const CellType type = mesh.cellTypes[size_t(cell)];
    const auto nodes = mesh.cellNodes(cell);
    const int dim = cellDimension(type);
    std::array<double, 3> xi{0, 0, 0};
    std::vector<double> N(nodes.size());
    std::array<double, 24> dN{};
    auto X = [&](int a) -> const Vec3& { return mesh.coords[size_t(nodes[size_t(a)])]; };
    for (int it = 0; it < 50; ++it) {
        shapeValues(type, xi, N);
        shapeDerivatives(type, xi, dN);
        double J[3][3] = {}, inv[3][3] = {}, r[3] = {-x[0], -x[1], -x[2]};
        jacobian(
            dim, dim, int(nodes.size()), X, [&](int a, int j) { return dN[size_t(3 * a + j)]; }, J);
        if (invertJacobian(dim, J, inv) == 0.0) break;
        for (size_t a = 0; a < nodes.size(); ++a)
            for (int i = 0; i < 3; ++i) r[i] += N[a] * X(int(a))[size_t(i)];
        double step = 0.0;
        for (int i = 0; i < dim; ++i) {
            double d = 0.0;
            for (int j = 0; j < dim; ++j) d += inv[i][j] * r[j];
            xi[size_t(i)] -= d, step += std::abs(d);
        }
        if (step < 1e-15) break;
    }
    return xi;
}

}  // namespace ma::xfem
