#include "contact/FaceClipping.hpp"

#include <algorithm>
#include <cmath>

namespace ma::contact {

double orient(const Point2& o, const Point2& a, const Point2& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

double polygonArea(const std::vector<Point2>& p) {
    double a = 0.0;
    for (size_t i = 0; i < p.size(); ++i) {
        const Point2& q = p[i];
        const Point2& r = p[(i + 1) % p.size()];
        a += q[0] * r[1] - q[1] * r[0];
    }
    return 0.5 * a;
}

std::vector<Point2> clipConvex(std::vector<Point2> subject, const std::vector<Point2>& clip) {
    for (size_t e = 0; e < clip.size() && !subject.empty(); ++e) {
        const Point2& a = clip[e];
        const Point2& b = clip[(e + 1) % clip.size()];
        std::vector<Point2> out;
        for (size_t i = 0; i < subject.size(); ++i) {
            const Point2& p = subject[i];
            const Point2& q = subject[(i + 1) % subject.size()];
            const double dp = orient(a, b, p), dq = orient(a, b, q);
            if (dp >= 0.0) out.push_back(p);
            if ((dp >= 0.0) != (dq >= 0.0)) {
                const double t = dp / (dp - dq);
                out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
            }
        }
        subject = std::move(out);
    }
    return subject;
}

std::vector<std::array<Vec3, 3>> triangleIntersection(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b,
                                                      double negligible) {
    // Project on the two coordinates most parallel to the plane of a.
    const Vec3 n = cross(difference(a[1], a[0]), difference(a[2], a[0]));
    int k = 0;
    for (int i = 1; i < 3; ++i)
        if (std::abs(n[i]) > std::abs(n[k])) k = i;
    const int u = (k + 1) % 3, v = (k + 2) % 3;
    auto project = [&](const std::array<Vec3, 3>& t) {
        std::vector<Point2> p{{t[0][u], t[0][v]}, {t[1][u], t[1][v]}, {t[2][u], t[2][v]}};
        if (polygonArea(p) < 0.0) std::swap(p[1], p[2]);
        return p;
    };
    const auto pa = project(a), pb = project(b);
    const double areaA = polygonArea(pa);
    if (areaA <= 0.0 || polygonArea(pb) <= 0.0) return {};
    const auto poly = clipConvex(pa, pb);
    if (poly.size() < 3 || polygonArea(poly) <= negligible) return {};
    // Back to 3D on the plane of a, through the barycentric coordinates in its projection.
    const std::array<Vec3, 3> ta = polygonArea({{a[0][u], a[0][v]}, {a[1][u], a[1][v]}, {a[2][u], a[2][v]}}) > 0.0
                                       ? a
                                       : std::array<Vec3, 3>{a[0], a[2], a[1]};
    auto lift = [&](const Point2& p) {
        const double l1 = orient(pa[2], pa[0], p) / areaA / 2.0;
        const double l2 = orient(pa[0], pa[1], p) / areaA / 2.0;
        const double l0 = 1.0 - l1 - l2;
        Vec3 r{};
        for (int j = 0; j < 3; ++j) r[j] = l0 * ta[0][j] + l1 * ta[1][j] + l2 * ta[2][j];
        return r;
    };
    std::vector<std::array<Vec3, 3>> out;
    const double total = polygonArea(poly);
    for (size_t i = 1; i + 1 < poly.size(); ++i)
        if (orient(poly[0], poly[i], poly[i + 1]) > 1e-12 * total)
            out.push_back({lift(poly[0]), lift(poly[i]), lift(poly[i + 1])});
    return out;
}

std::vector<std::vector<Vec3>> segmentIntersection(const std::array<Vec3, 2>& a, const std::array<Vec3, 2>& b,
                                                   double negligible) {
    const Vec3 e = difference(a[1], a[0]);
    const double ee = dot(e, e);
    if (!(ee > 0.0)) return {};
    const double t0 = dot(difference(b[0], a[0]), e) / ee, t1 = dot(difference(b[1], a[0]), e) / ee;
    const double lo = std::max(0.0, std::min(t0, t1)), hi = std::min(1.0, std::max(t0, t1));
    if ((hi - lo) * std::sqrt(ee) <= negligible) return {};
    auto at = [&](double t) { return Vec3{a[0][0] + t * e[0], a[0][1] + t * e[1], a[0][2] + t * e[2]}; };
    return {{at(lo), at(hi)}};
}

}  // namespace ma::contact
