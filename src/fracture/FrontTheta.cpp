#include "fracture/FrontTheta.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "core/Error.hpp"
#include "fracture/FrontPoints.hpp"
#include "mesh/PointLocation.hpp"
#include "xfem/CellGeometry.hpp"
#include "xfem/TipEnrichment.hpp"

namespace ma::fracture {

namespace {

// e2 the unit normal, e1 the propagation direction made orthogonal to it, e3 = e1 x e2.
FrontFrame frameAt(const Vec3& origin, const Vec3& gn, const Vec3& gt) {
    FrontFrame f;
    f.origin = origin;
    const double ln = norm(gn);
    if (!(ln > 0)) return f;
    f.e2 = scaled(gn, 1.0 / ln);
    const Vec3 t = difference(gt, scaled(f.e2, dot(gt, f.e2)));
    const double lt = norm(t);
    if (!(lt > 0)) return f;
    f.e1 = scaled(t, 1.0 / lt);
    f.e3 = cross(f.e1, f.e2);
    return f;
}

}  // namespace

Front3D front3D(const Mesh& mesh, const xfem::Crack& crack, const std::vector<Vec3>& grln,
                const std::vector<Vec3>& grlt, int numeFond) {
    if (numeFond < 1 || size_t(numeFond) > crack.fronts.size() || crack.fronts[size_t(numeFond - 1)].points.size() < 2)
        throw UserError(
            fmt::format("NUME_FOND={}: crack {} has {} front(s)", numeFond, crack.name, crack.fronts.size()));
    const auto& source = crack.fronts[size_t(numeFond - 1)];
    Front3D front;
    front.points = source.points;
    front.abscissa = source.abscissa;
    front.closed = source.closed;
    for (size_t i = 0; i < front.points.size(); ++i) {
        const Vec3& p = front.points[i];
        const PointInCell at = locatePoint(mesh, p);
        if (at.cell < 0)
            throw InternalError(
                fmt::format("front {} of crack {}: point {} lies in no cell", numeFond, crack.name, i + 1));
        front.frames.push_back(frameAt(p, interpolateAt(mesh, at, grln), interpolateAt(mesh, at, grlt)));
        if (norm(front.frames.back().e1) == 0.0)
            throw UserError(
                fmt::format("front {} of crack {}: the level sets have no gradient at front point {}, so "
                            "its local basis (BASEFOND) is undefined",
                            numeFond, crack.name, i + 1));
        front.cellSize.push_back(tipCellSize(mesh, crack, p, front.frames.back().e1));
        if (!(front.cellSize.back() > 0))
            throw InternalError(
                fmt::format("front {} of crack {}: no tip cell holds front point {}", numeFond, crack.name, i + 1));
    }
    return front;
}

Front3D redistributed(const Front3D& front, size_t count) {
    Front3D out;
    out.closed = front.closed;
    out.cellSize = front.cellSize;
    const double length = front.abscissa.back();
    auto mix = [](const Vec3& a, const Vec3& b, double t) {
        return Vec3{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
    };
    size_t k = 1;
    for (size_t i = 0; i < count; ++i) {
        const double s = i + 1 == count ? length : double(i) * length / double(count - 1);
        while (k + 1 < front.abscissa.size() && front.abscissa[k] <= s) ++k;
        const double s1 = front.abscissa[k - 1], s2 = front.abscissa[k];
        const double t = i == 0 ? 0.0 : (i + 1 == count ? 1.0 : (s - s1) / (s2 - s1));
        const size_t a = i + 1 == count ? front.points.size() - 2 : k - 1;
        const size_t b = a + 1;
        out.points.push_back(mix(front.points[a], front.points[b], t));
        const FrontFrame &fa = front.frames[a], &fb = front.frames[b];
        out.frames.push_back({out.points.back(), mix(fa.e1, fb.e1, t), mix(fa.e2, fb.e2, t), mix(fa.e3, fb.e3, t)});
        out.abscissa.push_back(s);
    }
    return out;
}

FrontProjection projectOnFront(const Front3D& front, const Vec3& x) {
    const double eps = 1e-12;  // gcour3's tolerance on the segment parameter
    FrontProjection best;
    best.distance = std::numeric_limits<double>::max();
    for (size_t j = 0; j + 1 < front.points.size(); ++j) {
        const Vec3 a = front.points[j], ab = difference(front.points[j + 1], a);
        double s = dot(ab, difference(x, a)) / dot(ab, ab);
        if (s - 1 >= eps) s = 1.0;
        if (s <= eps) s = 0.0;
        const Vec3 n = {a[0] + s * ab[0], a[1] + s * ab[1], a[2] + s * ab[2]};
        const double d = distance(n, x);
        // The first of equally near segments, as gcour3 keeps it.
        if (d < best.distance * (1 - 1e4 * std::numeric_limits<double>::epsilon())) best = {j, s, d};
    }
    return best;
}

std::vector<double> lagrangeHat(const Front3D& front, size_t k) {
    const size_t count = front.points.size();
    std::vector<double> phi(count, 0.0);
    phi[k] = 1.0;
    if (front.closed && k == 0) phi[count - 1] = 1.0;
    if (front.closed && k == count - 1) phi[0] = 1.0;
    return phi;
}

std::vector<double> legendrePolynomial(const std::vector<double>& s, double length, int k) {
    std::vector<double> phi;
    for (double a : s) {
        const double x = 2 * a / length - 1;
        // Bonnet's recurrence: (n + 1) P_n+1 = (2n + 1) x P_n - n P_n-1.
        double previous = 1.0, current = x;
        if (k == 0) current = 1.0;
        for (int n = 1; n < k; ++n) {
            const double next = ((2 * n + 1) * x * current - n * previous) / (n + 1);
            previous = current, current = next;
        }
        phi.push_back(std::sqrt((2 * k + 1) / length) * current);
    }
    return phi;
}

std::vector<Vec3> frontTheta(const Mesh& mesh, const Front3D& front, const std::vector<FrontProjection>& nodes,
                             const std::vector<Vec3>& grlt, const std::vector<double>& phi, double rInf, double rSup) {
    const size_t count = front.points.size();
    const double eps = 1e-12;
    std::vector<Vec3> theta(size_t(mesh.nodeCount()), Vec3{});
    for (size_t n = 0; n < theta.size(); ++n) {
        const FrontProjection& p = nodes[n];
        const size_t j = p.segment;
        const double h0 = phi[j], h1 = phi[j + 1];
        if (h0 == 0.0 && h1 == 0.0) continue;
        const double alpha = (p.distance - rInf) / (rSup - rInf);
        if (std::abs(alpha - 1) <= eps || alpha > 1) continue;
        const double scale = (std::abs(alpha) <= eps || alpha < 0) ? 1.0 : 1 - alpha;
        Vec3 v = scaled(grlt[n], (1 - p.s) * h0 + p.s * h1);
        if (j == 0 || j + 2 == count) {
            const Vec3 a = scaled(front.frames[j].e1, (1 - p.s) * h0), b = scaled(front.frames[j + 1].e1, p.s * h1);
            v = {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
        }
        theta[n] = scaled(v, scale);
    }
    return theta;
}

}  // namespace ma::fracture
