#pragma once
// The engine's small 3-vector: a point or a direction in space (2D models: z = 0), the type of
// Mesh::coords. Plain std::array, so that it converts to nothing and costs nothing.
#include <array>
#include <cmath>

namespace ma {

using Vec3 = std::array<double, 3>;

inline Vec3 difference(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 scaled(const Vec3& v, double s) { return {s * v[0], s * v[1], s * v[2]}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline double distance(const Vec3& a, const Vec3& b) { return norm(difference(a, b)); }
// v / |v|; the zero vector for a zero v.
inline Vec3 unit(const Vec3& v) {
    const double l = norm(v);
    return l > 0 ? Vec3{v[0] / l, v[1] / l, v[2] / l} : Vec3{};
}

}  // namespace ma
