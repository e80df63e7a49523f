#include "xfem/CrackShapes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/Error.hpp"

namespace ma::xfem {

namespace {

// The root s of (r0 z0 / (s + r0))² + (z1 / (s + 1))² = 1 on [z1 - 1, |(r0 z0, z1)| - 1] (the
// foot-point equation of an ellipse scaled to semi-minor axis 1), by bisection to the last bit.
double footRoot(double r0, double z0, double z1, double g) {
    const double n0 = r0 * z0;
    double s0 = z1 - 1.0;
    double s1 = g < 0.0 ? 0.0 : std::hypot(n0, z1) - 1.0;
    double s = 0.0;
    for (int i = 0; i < 2100; ++i) {
        s = 0.5 * (s0 + s1);
        if (s == s0 || s == s1) break;
        const double ratio0 = n0 / (s + r0), ratio1 = z1 / (s + 1.0);
        const double value = ratio0 * ratio0 + ratio1 * ratio1 - 1.0;
        if (value > 0.0) {
            s0 = s;
        } else if (value < 0.0) {
            s1 = s;
        } else {
            break;
        }
    }
    return s;
}

// Unsigned distance from (y0, y1), both >= 0, to the ellipse of semi-axes e0 >= e1 > 0.
double quadrantDistance(double e0, double e1, double y0, double y1) {
    if (y1 > 0.0) {
        if (y0 > 0.0) {
            const double z0 = y0 / e0, z1 = y1 / e1;
            const double g = z0 * z0 + z1 * z1 - 1.0;
            if (g == 0.0) return 0.0;
            const double r0 = (e0 / e1) * (e0 / e1);
            const double s = footRoot(r0, z0, z1, g);
            const double x0 = r0 * y0 / (s + r0), x1 = y1 / (s + 1.0);
            return std::hypot(x0 - y0, x1 - y1);
        }
        return std::abs(y1 - e1);
    }
    const double numer0 = e0 * y0, denom0 = e0 * e0 - e1 * e1;
    if (numer0 < denom0) {
        const double xde0 = numer0 / denom0;
        const double x0 = e0 * xde0, x1 = e1 * std::sqrt(1.0 - xde0 * xde0);
        return std::hypot(x0 - y0, x1);
    }
    return std::abs(y0 - e0);
}

Vec3 nonZeroUnit(const Vec3& v, const char* keyword) {
    const double n = norm(v);
    if (!(n > 0.0)) throw UserError(fmt::format("DEFI_FISS/{}: the vector is null", keyword));
    return {v[0] / n, v[1] / n, v[2] / n};
}

bool isOneOf(const std::string& s, std::initializer_list<const char*> list) {
    return std::any_of(list.begin(), list.end(), [&](const char* t) { return s == t; });
}

// code_aster's XFEM_23 (the form does not fit TYPE_DISCONTINUITE) and the dimension the form is
// defined in (code_aster reads undefined coordinates there).
void checkForm(const CrackShape& shape, bool isCrack, int dim) {
    const std::string& f = shape.form;
    const bool crackOnly = isOneOf(f, {"CYLINDRE", "DEMI_PLAN", "SEGMENT", "DEMI_DROITE"});
    const bool interfaceOnly = isOneOf(f, {"DROITE", "ENTAILLE"});
    if ((crackOnly && !isCrack) || (interfaceOnly && isCrack))
        throw UserError(fmt::format(
            "DEFI_FISS/FORM_FISS='{}' does not define a {}: use TYPE_DISCONTINUITE='{}' (code_aster's XFEM_23)", f,
            isCrack ? "crack (it has no front)" : "closed interface (it has a front)",
            isCrack ? "INTERFACE" : "FISSURE"));
    const bool only3d = isOneOf(f, {"DEMI_PLAN", "CYLINDRE"}) || (isCrack && isOneOf(f, {"ELLIPSE", "RECTANGLE"}));
    const bool only2d = isOneOf(f, {"SEGMENT", "DEMI_DROITE", "DROITE"});
    if ((only3d && dim != 3) || (only2d && dim != 2))
        throw UserError(fmt::format("DEFI_FISS/FORM_FISS='{}'{} is defined on a {} mesh; this mesh is {}D", f,
                                    isCrack ? " (TYPE_DISCONTINUITE='FISSURE')" : "", only3d ? "3D" : "2D", dim));
}

// The local frame (VECT_X, VECT_Y, VECT_X x VECT_Y) of the planar shapes, VECT_X ⊥ VECT_Y.
std::array<Vec3, 3> planarFrame(const CrackShape& shape) {
    const Vec3 x = nonZeroUnit(shape.vectX, "VECT_X"), y = nonZeroUnit(shape.vectY, "VECT_Y");
    if (std::abs(dot(x, y)) > 1e-6)
        throw UserError(fmt::format(
            "DEFI_FISS/VECT_X=({:g}, {:g}, {:g}) and VECT_Y=({:g}, {:g}, {:g}) are not orthogonal (cosine {:g}); "
            "the shape's frame would be skewed",
            shape.vectX[0], shape.vectX[1], shape.vectX[2], shape.vectY[0], shape.vectY[1], shape.vectY[2], dot(x, y)));
    return {x, y, cross(x, y)};
}

void closedShape(const Mesh& mesh, const CrackShape& shape, bool isCrack, ShapeLevelSets& out) {
    const auto frame = planarFrame(shape);
    const std::string& f = shape.form;
    const double a = shape.semiMajor, b = f == "ENTAILLE" ? shape.filletRadius : shape.semiMinor;
    if (!(a > 0.0) || !(b > 0.0))
        throw UserError(
            fmt::format("DEFI_FISS/FORM_FISS='{}': the half-lengths must be positive (got {:g}, {:g})", f, a, b));
    const double r = shape.filletRadius;
    if ((f == "RECTANGLE" || f == "ENTAILLE") && r > std::min(a, b))
        throw UserError(
            fmt::format("DEFI_FISS/RAYON_CONGE={:g} exceeds the half-length {:g} of the shape", r, std::min(a, b)));
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        const Vec3 d = difference(mesh.coords[n], shape.centre);
        const double u = dot(frame[0], d), v = dot(frame[1], d), w = dot(frame[2], d);
        const double h =
            (f == "ELLIPSE" || f == "CYLINDRE") ? ellipseDistance(u, v, a, b) : roundedRectangleDistance(u, v, a, b, r);
        if (!isCrack) {
            out.lsn[n] = h;
        } else if (f == "CYLINDRE") {
            out.lsn[n] = h, out.lst[n] = w;
        } else {
            out.lsn[n] = w, out.lst[n] = shape.outside ? -h : h;
        }
    }
}

}  // namespace

double ellipseDistance(double x, double y, double a, double b) {
    if (a < b) std::swap(a, b), std::swap(x, y);
    const double inside = (x / a) * (x / a) + (y / b) * (y / b) - 1.0;
    if (a == b) return std::hypot(x, y) - a;
    const double d = quadrantDistance(a, b, std::abs(x), std::abs(y));
    return inside < 0.0 ? -d : d;
}

double roundedRectangleDistance(double x, double y, double a, double b, double r) {
    if (a < b) std::swap(a, b), std::swap(x, y);
    x = std::abs(x), y = std::abs(y);
    const double xc = a - r, yc = b - r;  // centre of the corner's fillet
    if (y >= x + b - a && x <= xc) return y - b;
    if (y <= x + b - a && y <= yc) return x - a;
    return std::hypot(x - xc, y - yc) - r;
}

ShapeLevelSets shapeLevelSets(const Mesh& mesh, const CrackShape& shape, bool isCrack) {
    checkForm(shape, isCrack, mesh.dim);
    const size_t nn = mesh.coords.size();
    ShapeLevelSets out{std::vector<double>(nn, 0.0), std::vector<double>(nn, -1.0)};
    const std::string& f = shape.form;
    if (isOneOf(f, {"ELLIPSE", "RECTANGLE", "CYLINDRE", "ENTAILLE"})) {
        closedShape(mesh, shape, isCrack, out);
    } else if (f == "DEMI_PLAN") {
        const Vec3 n = nonZeroUnit(shape.normal, "NORMALE"), t = nonZeroUnit(shape.tangent, "DTAN");
        if (std::abs(dot(n, t)) > 1e-6)
            throw UserError(fmt::format("DEFI_FISS/NORMALE and DTAN are not orthogonal (cosine {:g})", dot(n, t)));
        for (size_t k = 0; k < nn; ++k) {
            const Vec3 d = difference(mesh.coords[k], shape.point);
            out.lsn[k] = dot(n, d), out.lst[k] = dot(t, d);
        }
    } else if (f == "SEGMENT") {
        const Vec3 mid{0.5 * (shape.point[0] + shape.end[0]), 0.5 * (shape.point[1] + shape.end[1]), 0.0};
        const double length = distance(shape.point, shape.end);
        if (!(length > 0.0)) throw UserError("DEFI_FISS/PFON_ORIG and PFON_EXTR are the same point");
        const Vec3 s = nonZeroUnit(difference(shape.end, shape.point), "PFON_EXTR - PFON_ORIG");
        for (size_t k = 0; k < nn; ++k) {
            const double dx = mesh.coords[k][0] - mid[0], dy = mesh.coords[k][1] - mid[1];
            out.lsn[k] = -s[1] * dx + s[0] * dy;
            out.lst[k] = std::abs(s[0] * dx + s[1] * dy) - 0.5 * length;
        }
    } else if (f == "DEMI_DROITE" || f == "DROITE") {
        const Vec3 t = nonZeroUnit(shape.tangent, "DTAN");
        for (size_t k = 0; k < nn; ++k) {
            const double dx = mesh.coords[k][0] - shape.point[0], dy = mesh.coords[k][1] - shape.point[1];
            out.lsn[k] = -t[1] * dx + t[0] * dy;
            if (f == "DEMI_DROITE") out.lst[k] = t[0] * dx + t[1] * dy;
        }
    } else {
        throw InternalError("FORM_FISS='" + f + "' has no level sets");
    }
    return out;
}

}  // namespace ma::xfem
