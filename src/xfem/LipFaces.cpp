// The lips of an interface for loads (PRES_REP FISSURE): XfemModel::lipIntegration. Each side
// integrates the faces of its own sub-cells that lie on the interface, with its own psi and its
// outward normal, so both lips are loaded without pairing the two sides' faces (they tile the
// same interface: docs/xfem.md, "Loads on the lips").
#include <algorithm>
#include <cmath>

#include "core/Error.hpp"
#include "core/Vec3.hpp"
#include "fe/Quadrature.hpp"
#include "mesh/ElementGeometry.hpp"
#include "mesh/ShapeFunctions.hpp"
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

class LipBuilder {
public:
    explicit LipBuilder(const XfemModel& xm) : xm_(xm), mesh_(xm.mesh()), dim_(xm.dim()) {}

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

    // One LipIntegration for the cell: the points of the faces of both sides, each with its side's psi.
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
        for (int a = 0; a < nn; ++a) {
            ei.slots[size_t(a)] = 1 + xm_.activeSlots(nodes[size_t(a)]);
            ei.maxSlots = std::max(ei.maxSlots, ei.slots[size_t(a)]);
        }
        const QuadratureRule& rule =
            quadratureRule(dim_ == 2 ? CellType::SEG2 : CellType::TRIA3, dim_ == 2 ? "FPG3" : "FPG12");
        for (const auto& f : faces)
            for (int q = 0; q < rule.size(); ++q)
                addPoint(cut, f, rule.points[size_t(q)], rule.weights[size_t(q)], lip);
        out.push_back(std::move(lip));
    }

private:
    double cellSize(int cell) const {
        const auto nodes = mesh_.cellNodes(cell);
        double h = 0.0;
        for (size_t a = 1; a < nodes.size(); ++a)
            h = std::max(h, norm(difference(mesh_.coords[size_t(nodes[a])], mesh_.coords[size_t(nodes[0])])));
        return h;
    }

    void addPoint(const CellCut& cut, const LipFace& f, const Vec3& qp, double qw, LipIntegration& lip) const {
        auto& ei = lip.element;
        // The point and the face's tangent directions in the parent's reference element.
        Vec3 xi{}, d1{}, d2{};
        if (dim_ == 2) {
            const double s = 0.5 * (qp[0] + 1.0);
            for (int i = 0; i < 3; ++i) {
                xi[size_t(i)] = f.ref[0][size_t(i)] + s * (f.ref[1][size_t(i)] - f.ref[0][size_t(i)]);
                d1[size_t(i)] = 0.5 * (f.ref[1][size_t(i)] - f.ref[0][size_t(i)]);
            }
        } else {
            for (int i = 0; i < 3; ++i) {
                d1[size_t(i)] = f.ref[1][size_t(i)] - f.ref[0][size_t(i)];
                d2[size_t(i)] = f.ref[2][size_t(i)] - f.ref[0][size_t(i)];
                xi[size_t(i)] = f.ref[0][size_t(i)] + qp[0] * d1[size_t(i)] + qp[1] * d2[size_t(i)];
            }
        }
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
        const size_t p = ei.refPoints.size() - 1;
        ei.psi.resize((p + 1) * size_t(nn) * size_t(ei.maxSlots), 0.0);
        for (int a = 0; a < nn; ++a) {
            const size_t base = (p * size_t(nn) + size_t(a)) * size_t(ei.maxSlots);
            ei.psi[base] = 1.0;
            for (int k = 1; k < ei.slots[size_t(a)]; ++k)
                ei.psi[base + size_t(k)] = xm_.psi(nodes[size_t(a)], k, cut, f.subcell);
        }
        lip.xyz.push_back(x);
        lip.weight.push_back(qw * measure);
        lip.normal.push_back(n);
    }

    const XfemModel& xm_;
    const Mesh& mesh_;
    int dim_;
    mutable std::vector<Vec3> xyz_;
};

}  // namespace

bool XfemModel::lipIntegration(const Concept& crack, std::vector<LipIntegration>& out) const {
    const auto it = std::find_if(cracks_.begin(), cracks_.end(), [&](const auto& c) { return c.get() == &crack; });
    if (it == cracks_.end()) return false;
    const int index = int(it - cracks_.begin());
    if (index == tipCrack_)
        throw NotImplemented("PRES_REP FISSURE on crack " + (*it)->name +
                             ", whose front lies in the mesh: lip loads on crack-tip enriched cells are not "
                             "implemented yet");
    const LipBuilder builder(*this);
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
