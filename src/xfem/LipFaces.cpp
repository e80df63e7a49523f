// The lips of an interface or a crack for loads (PRES_REP FISSURE): XfemModel::lipIntegration. Each
// side integrates the faces of its own sub-cells that lie on the interface, with its own psi and its
// outward normal, so both lips are loaded without pairing the two sides' faces (they tile the
// same interface: docs/xfem.md, "Loads on the lips"). A crack with a front in the mesh is loaded
// behind the front only (LST <= 0), and its crack-tip elements carry the tip fields of each side
// (Phi at theta = +-pi) with a rule suited to their sqrt(r) (docs/cracks.md, "Loads on tip cells").
#include <algorithm>
#include <cmath>

#include "core/Error.hpp"
#include "core/Vec3.hpp"
#include "fe/Quadrature.hpp"
#include "mesh/ElementGeometry.hpp"
#include "mesh/ShapeFunctions.hpp"
#include "xfem/TipEnrichment.hpp"
#include "xfem/XfemModel.hpp"

namespace ma::xfem {

namespace {

// Faces of a simplex of dimension d (local vertex numbers) and the vertex opposite each.
const std::vector<std::vector<int>>& simplexFaces(int d) {
    static const std::vector<std::vector<int>> tri{{0, 1, 2}, {1, 2, 0}, {2, 0, 1}};
    static const std::vector<std::vector<int>> tet{{1, 2, 3, 0}, {0, 2, 3, 1}, {0, 1, 3, 2}, {0, 1, 2, 3}};
    return d == 2 ? tri : tet;
}

// A face of a sub-cell on the interface: its vertices and the opposite one, in the parent's
// reference coordinates.
struct LipFace {
    int subcell = -1;
    std::vector<Vec3> ref;
    Vec3 opposite{};
};

// A piece of a lip face inside LST <= 0: its vertices (parent reference coordinates) and the
// distance to the front at each, -LST (0 on the front).
struct LipPiece {
    std::vector<Vec3> ref;
    std::vector<double> depth;
};

// The part of a face (segment or triangle) where the linear interpolation of the vertices' LST is
// not positive, as simplices of the same dimension (a clipped triangle's quadrilateral is split from
// its first vertex, so that each triangle has its vertices on the front last).
std::vector<LipPiece> clipBehindFront(const std::vector<Vec3>& ref, const std::vector<double>& lst) {
    const size_t n = ref.size();
    double scale = 0.0;
    for (double v : lst) scale = std::max(scale, std::abs(v));
    const double tol = 1e-12 * scale;
    std::vector<Vec3> poly;
    std::vector<double> depth;
    if (n == 2) {  // a segment: the end behind the front and the crossing, or the whole segment
        if (lst[0] > tol && lst[1] > tol) return {};
        if (lst[0] <= tol && lst[1] <= tol) return {LipPiece{ref, {std::max(0.0, -lst[0]), std::max(0.0, -lst[1])}}};
        const size_t behind = lst[0] <= tol ? 0 : 1;
        if (lst[behind] >= -tol) return {};  // touches the front at one end only
        const double w = lst[0] / (lst[0] - lst[1]);
        const Vec3 cross0{ref[0][0] + w * (ref[1][0] - ref[0][0]), ref[0][1] + w * (ref[1][1] - ref[0][1]),
                          ref[0][2] + w * (ref[1][2] - ref[0][2])};
        return {LipPiece{{ref[behind], cross0}, {std::max(0.0, -lst[behind]), 0.0}}};
    }
    for (size_t i = 0; i < n; ++i) {
        const size_t j = (i + 1) % n;
        const double a = lst[i], b = lst[j];
        if (a <= tol) poly.push_back(ref[i]), depth.push_back(std::max(0.0, -a));
        if ((a < -tol && b > tol) || (a > tol && b < -tol)) {
            const double w = a / (a - b);
            poly.push_back({ref[i][0] + w * (ref[j][0] - ref[i][0]), ref[i][1] + w * (ref[j][1] - ref[i][1]),
                            ref[i][2] + w * (ref[j][2] - ref[i][2])});
            depth.push_back(0.0);
        }
    }
    std::vector<LipPiece> out;
    if (poly.size() < n) return out;
    for (size_t k = 1; k + 1 < poly.size(); ++k)
        out.push_back(LipPiece{{poly[0], poly[k], poly[k + 1]}, {depth[0], depth[k], depth[k + 1]}});
    return out;
}

// A point of a lip piece: parent reference coordinates and the weight relative to the piece's
// measure in `measureOf` (the length of V1 - V0, or |(V1 - V0) x (V2 - V0)|).
struct LipRulePoint {
    Vec3 xi{};
    double weight = 0.0;
};

Vec3 affine(const Vec3& a, const Vec3& b, double w) {
    return {a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1]), a[2] + w * (b[2] - a[2])};
}

// Points on a piece whose integrand behaves like sqrt(depth) near the front (the crack-tip fields on
// the lips), depth linear and >= 0 on it. A segment with a vertex on the front: s = t^2 from that
// vertex. A triangle collapsed (Duffy) at its vertex A: x = A + u ((1 - v) B + v C - A), area u du dv,
// with u = t^2 when A is on the front alone, 1 - u = t^2 when B and C are (the edge on the front).
// sqrt(depth) is then t times a smooth function: Gauss-Legendre in t, v is exact for polynomials.
std::vector<LipRulePoint> sqrtRule(const LipPiece& piece, int n) {
    std::vector<double> x, w;
    gaussLegendre01(n, x, w);
    const double top = *std::max_element(piece.depth.begin(), piece.depth.end());
    std::vector<char> onFront;
    for (double d : piece.depth) onFront.push_back(d <= 1e-10 * top);
    std::vector<LipRulePoint> out;
    const auto& V = piece.ref;
    if (V.size() == 2) {
        const bool zeroFirst = onFront[0] || !onFront[1];
        const Vec3 &Z = zeroFirst ? V[0] : V[1], &O = zeroFirst ? V[1] : V[0];
        const bool singular = onFront[0] || onFront[1];
        for (int i = 0; i < n; ++i) {
            const double s = singular ? x[size_t(i)] * x[size_t(i)] : x[size_t(i)];
            out.push_back({affine(Z, O, s), w[size_t(i)] * (singular ? 2 * x[size_t(i)] : 1.0)});
        }
        return out;
    }
    const int zeros = onFront[0] + onFront[1] + onFront[2];
    int apex = 0;  // the vertex on the front alone, or the one off the front's edge
    for (int k = 0; k < 3; ++k)
        if ((zeros == 1 && onFront[size_t(k)]) || (zeros == 2 && !onFront[size_t(k)])) apex = k;
    const Vec3 &A = V[size_t(apex)], &B = V[size_t((apex + 1) % 3)], &C = V[size_t((apex + 2) % 3)];
    // The rule's area element is relative to |(B - A) x (C - A)|, which equals the piece's measure.
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double t = x[size_t(i)];
            double u = t, du = 1.0;
            if (zeros == 1) u = t * t, du = 2 * t;
            if (zeros >= 2) u = 1 - t * t, du = 2 * t;
            const Vec3 edge = affine(B, C, x[size_t(j)]);
            out.push_back({affine(A, edge, u), w[size_t(i)] * w[size_t(j)] * u * du});
        }
    return out;
}

class LipBuilder {
public:
    LipBuilder(const XfemModel& xm, const Crack& crack, bool front)
        : xm_(xm), mesh_(xm.mesh()), dim_(xm.dim()), crack_(crack), front_(front) {}

    // The faces of the sub-cells of `cut` on the interface (local crack j), on either side.
    std::vector<LipFace> faces(const CellCut& cut, size_t j) const {
        const double tol = 1e-8 * cellSize(cut.cell);
        std::vector<LipFace> out;
        for (int s = 0; s < int(cut.subcells.size()); ++s) {
            const auto& sub = cut.subcells[size_t(s)];
            if (sub.heaviside[j] == 0) continue;  // forbidden side of a branch
            for (const auto& face : simplexFaces(dim_)) {
                LipFace f;
                f.subcell = s;
                bool on = true;
                for (int v = 0; v < dim_ && on; ++v) {
                    const auto& point = cut.points[size_t(sub.vertices[size_t(face[size_t(v)])])];
                    on = std::abs(point.lsn[j]) <= tol;
                    f.ref.push_back(point.ref);
                }
                if (!on) continue;
                f.opposite = cut.points[size_t(sub.vertices[size_t(face[size_t(dim_)])])].ref;
                out.push_back(std::move(f));
            }
        }
        return out;
    }

    // One LipIntegration for the cell: the points of the faces of both sides, each with its side's
    // psi; on a crack with a front only the part behind it (LST <= 0), and in an element with
    // crack-tip nodes the sqrt rule and the tip flags (Phi: Enrichment::tipFields, the point's
    // sub-cell giving its side).
    void integrate(const CellCut& cut, const std::vector<LipFace>& faces, std::vector<LipIntegration>& out) const {
        const auto nodes = mesh_.cellNodes(cut.cell);
        const int nn = int(nodes.size());
        xyz_.resize(size_t(nn));
        for (int a = 0; a < nn; ++a) xyz_[size_t(a)] = mesh_.coords[size_t(nodes[size_t(a)])];
        LipIntegration lip;
        auto& ei = lip.element;
        ei.cell = cut.cell;
        ei.nodeCount = nn;
        ei.slots.resize(size_t(nn));
        ei.maxSlots = 1;
        bool tip = false;
        for (int a = 0; a < nn; ++a) {
            ei.slots[size_t(a)] = 1 + xm_.activeSlots(nodes[size_t(a)]);
            ei.maxSlots = std::max(ei.maxSlots, ei.slots[size_t(a)]);
            tip = tip || (front_ && xm_.tipNode(nodes[size_t(a)]));
        }
        for (const auto& f : faces) {
            if (!front_) {
                addCatalogueRule(cut, f, lip);
                continue;
            }
            std::vector<double> lst;
            for (const auto& r : f.ref) lst.push_back(levelSetAt(cut, r));
            for (const auto& piece : clipBehindFront(f.ref, lst)) {
                const Vec3 d1 = difference(piece.ref[1], piece.ref[0]);
                const Vec3 d2 = dim_ == 3 ? difference(piece.ref[2], piece.ref[0]) : Vec3{};
                const auto rule = tip ? sqrtRule(piece, kLipPoints) : catalogueRule(piece);
                for (const auto& q : rule) addPoint(cut, f, q.xi, d1, d2, q.weight, lip);
            }
        }
        if (ei.refPoints.empty()) return;
        if (tip) {  // flags only: the user of the lip fills Phi for its material (Enrichment::tipFields)
            ei.tip.assign(size_t(nn), 0);
            for (int a = 0; a < nn; ++a) ei.tip[size_t(a)] = xm_.tipNode(nodes[size_t(a)]) ? 1 : 0;
        }
        out.push_back(std::move(lip));
    }

private:
    // Points along each radius of the lip rules near the front (exact for sqrt(r) times polynomials
    // of degree 2 kLipPoints - 2 in t).
    static constexpr int kLipPoints = 8;

    double cellSize(int cell) const {
        const auto nodes = mesh_.cellNodes(cell);
        double h = 0.0;
        for (size_t a = 1; a < nodes.size(); ++a)
            h = std::max(h, norm(difference(mesh_.coords[size_t(nodes[a])], mesh_.coords[size_t(nodes[0])])));
        return h;
    }

    double levelSetAt(const CellCut& cut, const Vec3& ref) const {
        const auto nodes = mesh_.cellNodes(cut.cell);
        std::array<double, 8> N{};
        shapeValues(cut.type, ref, std::span<double>(N.data(), nodes.size()));
        double v = 0.0;
        for (size_t a = 0; a < nodes.size(); ++a) v += N[a] * crack_.lst[size_t(nodes[a])];
        return v;
    }

    // The catalogue's face rule (FPG3 on a segment, FPG12 on a triangle) on a piece.
    std::vector<LipRulePoint> catalogueRule(const LipPiece& piece) const {
        const QuadratureRule& rule =
            quadratureRule(dim_ == 2 ? CellType::SEG2 : CellType::TRIA3, dim_ == 2 ? "FPG3" : "FPG12");
        std::vector<LipRulePoint> out;
        for (int q = 0; q < rule.size(); ++q) {
            const auto& qp = rule.points[size_t(q)];
            const double w = rule.weights[size_t(q)];
            if (dim_ == 2) {
                out.push_back({affine(piece.ref[0], piece.ref[1], 0.5 * (qp[0] + 1.0)), 0.5 * w});
            } else {
                Vec3 xi{};
                for (int i = 0; i < 3; ++i)
                    xi[size_t(i)] = piece.ref[0][size_t(i)] +
                                    qp[0] * (piece.ref[1][size_t(i)] - piece.ref[0][size_t(i)]) +
                                    qp[1] * (piece.ref[2][size_t(i)] - piece.ref[0][size_t(i)]);
                out.push_back({xi, w});
            }
        }
        return out;
    }

    // An interface's face: the catalogue rule on the whole face, as for every interface.
    void addCatalogueRule(const CellCut& cut, const LipFace& f, LipIntegration& lip) const {
        const LipPiece whole{f.ref, {}};
        const Vec3 d1 = difference(f.ref[1], f.ref[0]);
        const Vec3 d2 = dim_ == 3 ? difference(f.ref[2], f.ref[0]) : Vec3{};
        for (const auto& q : catalogueRule(whole)) addPoint(cut, f, q.xi, d1, d2, q.weight, lip);
    }

    // A point at reference `xi` of face f, whose tangents in the reference element are d1 (, d2):
    // physical weight `w` times the length |J d1| or the area measure |J d1 x J d2|.
    void addPoint(const CellCut& cut, const LipFace& f, const Vec3& xi, const Vec3& d1, const Vec3& d2, double w,
                  LipIntegration& lip) const {
        auto& ei = lip.element;
        std::array<double, 24> dN{};
        const int nn = ei.nodeCount;
        shapeDerivatives(cut.type, xi, dN);
        double J[3][3] = {};
        jacobian(xyz_, std::span<const double>(dN.data(), size_t(nn) * 3), dim_, J);
        auto apply = [&](const Vec3& d) {
            Vec3 t{};
            for (int i = 0; i < 3; ++i)
                for (int k = 0; k < dim_; ++k) t[size_t(i)] += J[i][k] * d[size_t(k)];
            return t;
        };
        const Vec3 t1 = apply(d1);
        Vec3 n = dim_ == 2 ? Vec3{t1[1], -t1[0], 0.0} : cross(t1, apply(d2));
        const double measure = norm(n);
        if (!(measure > 0.0)) return;  // a face flat to round-off carries nothing
        for (auto& v : n) v /= measure;
        const Vec3 x = mapToPhysical(cut.type, xyz_, xi);
        if (dot(n, difference(x, mapToPhysical(cut.type, xyz_, f.opposite))) < 0.0)
            for (auto& v : n) v = -v;
        ei.refPoints.push_back(xi);
        ei.refWeights.push_back(0.0);
        ei.pointSubcell.push_back(f.subcell);
        const auto nodes = mesh_.cellNodes(cut.cell);
        const size_t s = size_t(f.subcell);  // psi is stored per sub-cell (ElementIntegration)
        std::vector<double>& psi = ei.psi.mut();
        if (psi.size() < (s + 1) * size_t(nn) * size_t(ei.maxSlots))
            psi.resize((s + 1) * size_t(nn) * size_t(ei.maxSlots), 0.0);
        for (int a = 0; a < nn; ++a) {
            const size_t base = (s * size_t(nn) + size_t(a)) * size_t(ei.maxSlots);
            psi[base] = 1.0;
            for (int k = 1; k < ei.slots[size_t(a)]; ++k)
                psi[base + size_t(k)] = xm_.psi(nodes[size_t(a)], k, cut, f.subcell);
        }
        lip.xyz.push_back(x);
        lip.weight.push_back(w * measure);
        lip.normal.push_back(n);
    }

    const XfemModel& xm_;
    const Mesh& mesh_;
    int dim_;
    const Crack& crack_;
    bool front_;
    mutable std::vector<Vec3> xyz_;
};

}  // namespace

bool XfemModel::lipIntegration(const Concept& crack, std::vector<LipIntegration>& out) const {
    const auto it = std::find_if(cracks_.begin(), cracks_.end(), [&](const auto& c) { return c.get() == &crack; });
    if (it == cracks_.end()) return false;
    const int index = int(it - cracks_.begin());
    const LipBuilder builder(*this, **it, index == tipCrack_);
    for (int cell : xfemCells_) {
        const CellCut& cut = cuts_[size_t(cellIndex_[size_t(cell)])];
        if (cut.skin) continue;
        const auto local = std::find(cut.cracks.begin(), cut.cracks.end(), index);
        if (local == cut.cracks.end()) continue;
        const auto faces = builder.faces(cut, size_t(local - cut.cracks.begin()));
        if (!faces.empty()) builder.integrate(cut, faces, out);
    }
    return true;
}

}  // namespace ma::xfem
