#pragma once
// Overlap of two faces of sub-cells that lie on the same interface, in the reference coordinates
// of their parent cell (where the sub-cells are flat): the two sides of an interface may split it
// differently (a branch joined to it cuts its own side at the junction, the other side stays
// whole), so the contact facets there are the pieces the faces share.
#include <array>
#include <vector>

#include "core/Vec3.hpp"

namespace ma::contact {

using Point2 = std::array<double, 2>;

// Twice the signed area of the triangle (o, a, b): > 0 counter-clockwise.
double orient(const Point2& o, const Point2& a, const Point2& b);
// Signed area of a polygon (> 0 counter-clockwise).
double polygonArea(const std::vector<Point2>& p);
// Sutherland-Hodgman: the part of `subject` inside the convex counter-clockwise polygon `clip`.
std::vector<Point2> clipConvex(std::vector<Point2> subject, const std::vector<Point2>& clip);

// Triangles (on the plane of `a`) covering the intersection of the nearly coplanar triangles a
// and b; `negligible` is the smallest area kept.
std::vector<std::array<Vec3, 3>> triangleIntersection(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b,
                                                      double negligible);

// Part of segment b on segment a (on the line of a; none or one segment); `negligible` is the
// smallest length kept.
std::vector<std::vector<Vec3>> segmentIntersection(const std::array<Vec3, 2>& a, const std::array<Vec3, 2>& b,
                                                   double negligible);

}  // namespace ma::contact
