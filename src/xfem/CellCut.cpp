#include "xfem/CellCut.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/Error.hpp"
#include "core/Vec3.hpp"
#include "mesh/ShapeFunctions.hpp"
#include "xfem/CellGeometry.hpp"
#include "xfem/Crack.hpp"

namespace ma::xfem {

namespace {

// code_aster sets the level set of a new point to 0 when |LSN| < 1e-4 L_ref (xdecou); that moves
// the discrete interface by up to 1e-4 h near junctions and nodes, which the rigid-block answer of
// ssnv511 cannot afford. miniaster only removes round-off of the interpolation (docs/xfem.md): a
// point eps^2 h off an interface (interfaces eps h from node rows next to a junction) is not on it.
constexpr double kPointSnap = 1e-14;
constexpr double kMergeDistance = 1e-9;      // a zero this close (edge length) to a point of its edge merges
constexpr double kVertexOnInterface = 1e-9;  // zero closer than this (relative) to a vertex
// Round-off of reference coordinates (magnitude <= 1), with a margin: the determinant of a piece
// whose measure is below it times its cofactors is numerically zero.
constexpr double kMeasureRoundOff = 16 * 2.2e-16;

using Piece = std::vector<int>;

class Cutter {
public:
    Cutter(const Mesh& mesh, CellCut& cut) : mesh_(mesh), cut_(cut) {
        nodes_ = mesh.cellNodes(cut.cell);
        simplexParent_ = cut.type == CellType::SEG2 || cut.type == CellType::TRIA3 || cut.type == CellType::TETRA4;
        lref_ = characteristicLength(mesh, cut.cell);
    }

    // Level set of lsnCracks[k] interpolated with the parent shape functions.
    double interpolate(int k, const std::array<double, 3>& ref) const {
        std::array<double, 8> N{};
        shapeValues(cut_.type, ref, N);
        double v = 0;
        for (size_t a = 0; a < nodes_.size(); ++a) v += N[a] * cut_.lsnCracks[k]->lsn[nodes_[a]];
        return v;
    }

    // Zero of crack k's level set on the segment p -> q (strict sign change between the ends).
    int edgePoint(int k, int p, int q, double sp, double sq) {
        const auto key = std::make_pair(std::min(p, q), std::max(p, q));
        if (auto it = edgePoints_.find(key); it != edgePoints_.end()) return it->second;
        const auto& rp = cut_.points[p].ref;
        const auto& rq = cut_.points[q].ref;
        auto at = [&](double t) {
            return std::array<double, 3>{rp[0] + t * (rq[0] - rp[0]), rp[1] + t * (rq[1] - rp[1]),
                                         rp[2] + t * (rq[2] - rp[2])};
        };
        double t = sp / (sp - sq);
        if (!simplexParent_) {
            // Bilinear/trilinear parent: the level set is a polynomial along the segment.
            // Illinois (regula falsi) from the linear guess, bracket [0, 1].
            double a = 0, fa = sp, b = 1, fb = sq;
            double ft = interpolate(k, at(t));
            const double scale = std::max(std::abs(sp), std::abs(sq));
            int side = 0;
            for (int it = 0; it < 100 && std::abs(ft) > 1e-15 * scale && b - a > 1e-16; ++it) {
                if ((ft > 0) == (fb > 0)) {
                    b = t, fb = ft;
                    if (side == -1) fa *= 0.5;
                    side = -1;
                } else {
                    a = t, fa = ft;
                    if (side == 1) fb *= 0.5;
                    side = 1;
                }
                t = (a * fb - b * fa) / (fb - fa);
                ft = interpolate(k, at(t));
            }
        }
        const auto ref = at(t);
        // Merged only with the ends of the segment or a point an earlier crack put on the same
        // segment (a sub-cell its cut did not reach, e.g. the forbidden side of a branch): a point
        // of another edge, even 1e-10 h away, is elsewhere. Taking it moved a zero off its edge
        // (holes of 1e-10 of the cell where the neighbour across the edge kept it) or put the
        // junction point eps^2 h off the master interface (kinked by 1e-5 rad next to the junction):
        // energy errors up to 5e-9 with interfaces 1e-5 ... 3e-5 h from node rows (docs/xfem.md).
        std::vector<int> candidates{p, q};
        if (auto it = onSegment_.find(key); it != onSegment_.end())
            candidates.insert(candidates.end(), it->second.begin(), it->second.end());
        double nearest = kMergeDistance * distance(rp, rq);
        int id = -1;
        for (int i : candidates)
            if (const double d = distance(cut_.points[i].ref, ref); d <= nearest) nearest = d, id = i;
        if (id < 0) {
            CutPoint point;
            point.ref = ref;
            point.lsn.resize(cut_.lsnCracks.size());
            for (size_t j = 0; j < cut_.lsnCracks.size(); ++j) {
                // A segment lying on interface j (both ends on it) keeps its points on it: the
                // junction point is on the master exactly, not where the interpolation rounds.
                if (cut_.points[p].lsn[j] == 0.0 && cut_.points[q].lsn[j] == 0.0) continue;
                const double v = interpolate(static_cast<int>(j), ref);
                point.lsn[j] = std::abs(v) < kPointSnap * lref_ ? 0.0 : v;
            }
            point.lsn[k] = 0.0;
            id = static_cast<int>(cut_.points.size());
            cut_.points.push_back(std::move(point));
            onSegment_[key].push_back(id);
        }
        edgePoints_[key] = id;
        return id;
    }

    // Cuts every current sub-cell by local crack j.
    void cutBy(int j, const std::vector<int>& outsideSign) {
        edgePoints_.clear();
        const Crack& crack = *cut_.lsnCracks[j];
        std::vector<std::pair<int, double>> masters;  // (lsnCracks index, coef)
        for (const auto& m : crack.masters) {
            auto it = std::find(cut_.lsnCracks.begin(), cut_.lsnCracks.end(), m.crack.get());
            masters.emplace_back(static_cast<int>(it - cut_.lsnCracks.begin()), m.coef);
        }
        const size_t count = cut_.subcells.size();
        std::vector<SubCell> appended;
        std::vector<SubCell> kept;
        kept.reserve(count);
        for (size_t si = 0; si < count; ++si) {
            SubCell sub = cut_.subcells[si];
            const int nv = cut_.vertexCount();
            // Forbidden side of a master (§2.5): not cut, Heaviside 0.
            bool forbidden = false;
            for (const auto& [mk, coef] : masters) {
                double sum = 0;
                for (int v = 0; v < nv; ++v) sum += cut_.points[sub.vertices[v]].lsn[mk];
                if (coef * sum > 0) forbidden = true;
            }
            if (forbidden) {
                sub.heaviside[j] = 0;
                kept.push_back(sub);
                continue;
            }
            std::vector<int> verts(sub.vertices.begin(), sub.vertices.begin() + nv);
            std::vector<double> s(nv);
            std::vector<int> sign(nv);
            for (int v = 0; v < nv; ++v) s[v] = cut_.points[verts[v]].lsn[j];
            for (int v = 0; v < nv; ++v) {
                sign[v] = s[v] > 0 ? 1 : (s[v] < 0 ? -1 : 0);
                // A vertex numerically on the interface (its zero within 1e-9 of it on an edge).
                for (int w = 0; w < nv && sign[v] != 0; ++w)
                    if (s[v] * s[w] < 0 && std::abs(s[v]) <= kVertexOnInterface * std::abs(s[v] - s[w])) sign[v] = 0;
            }
            auto pieces = split(j, verts, s, sign);
            bool first = true;
            for (auto& piece : pieces) {
                SubCell out = sub;
                orient(piece);
                if (flat(piece)) {
                    ++cut_.droppedDegenerate;
                    continue;
                }
                for (int v = 0; v < nv; ++v) out.vertices[v] = piece[v];
                int sum = 0;
                for (int v = 0; v < nv; ++v) {
                    auto it = std::find(verts.begin(), verts.end(), piece[v]);
                    if (it != verts.end()) sum += sign[it - verts.begin()];
                    // new points lie on the interface: they add 0
                }
                signed char h = sum > 0 ? 1 : (sum < 0 ? -1 : 0);
                if (h == 0) {
                    // Every vertex on the interface: the interpolated level set at the centroid.
                    std::array<double, 3> centroid{0, 0, 0};
                    for (int v = 0; v < nv; ++v)
                        for (int k = 0; k < 3; ++k) centroid[k] += cut_.points[piece[v]].ref[k] / nv;
                    const double value = interpolate(j, centroid);
                    h = value > 0 ? 1 : (value < 0 ? -1 : 0);
                }
                if (h == 0) {
                    // A sub-cell lying on the interface: only skin sub-cells can (xoripe).
                    h = outsideSign.empty() ? 1 : static_cast<signed char>(outsideSign[j] >= 0 ? 1 : -1);
                }
                out.heaviside[j] = h;
                if (first) {
                    kept.push_back(out);
                    first = false;
                } else {
                    appended.push_back(out);
                }
            }
        }
        // The first piece replaces its parent in place, further pieces go at the end (§3.5.2e);
        // a parent that vanished entirely (degenerate) is removed.
        cut_.subcells = std::move(kept);
        cut_.subcells.insert(cut_.subcells.end(), appended.begin(), appended.end());
    }

    double measure(const Piece& piece) const {
        std::array<std::array<double, 3>, 4> v{};
        for (size_t i = 0; i < piece.size(); ++i) v[i] = cut_.points[piece[i]].ref;
        if (cut_.dim == 1) return v[1][0] - v[0][0];
        return simplexMeasure(cut_.dim, std::span<const std::array<double, 3>>(v.data(), piece.size()));
    }

private:
    // Whether a piece is degenerate: its measure is round-off for its own edges (repeated or
    // aligned vertices). A threshold relative to the parent (formerly 1e-14 of it) also dropped
    // real slivers, eps^2 h wide next to a junction, and the block of eps^2 of the cell they belong
    // to then lost a relative part of its volume: its stress was off by that much (1e-5 at
    // eps = 1e-5 h). The bound is the first-order error of the determinant: round-off of the
    // coordinates times the cofactors (edge lengths in 2D, edge cross products in 3D).
    bool flat(const Piece& piece) const {
        std::array<std::array<double, 3>, 3> e{};
        for (size_t a = 1; a < piece.size(); ++a)
            e[a - 1] = difference(cut_.points[piece[a]].ref, cut_.points[piece[0]].ref);
        double det = 0.0, cofactors = 1.0;
        if (cut_.dim == 1) det = norm(e[0]);
        if (cut_.dim == 2) det = 2.0 * std::abs(measure(piece)), cofactors = norm(e[0]) + norm(e[1]);
        if (cut_.dim == 3) {
            det = 6.0 * std::abs(measure(piece));
            cofactors = norm(cross(e[0], e[1])) + norm(cross(e[1], e[2])) + norm(cross(e[0], e[2]));
        }
        return det <= kMeasureRoundOff * cofactors;
    }

    void orient(Piece& piece) const {
        if (measure(piece) < 0) std::swap(piece[0], piece[1]);
    }

    std::vector<Piece> split(int j, const std::vector<int>& v, const std::vector<double>& s,
                             const std::vector<int>& sign) {
        const int nv = static_cast<int>(v.size());
        int pos = 0, neg = 0, zero = 0;
        for (int i = 0; i < nv; ++i) (sign[i] > 0 ? pos : (sign[i] < 0 ? neg : zero))++;
        if (pos == 0 || neg == 0) return {v};
        auto point = [&](int a, int b) { return edgePoint(j, v[a], v[b], s[a], s[b]); };
        if (nv == 2) {
            const int q = point(0, 1);
            return {{v[0], q}, {q, v[1]}};
        }
        if (nv == 3) {
            if (zero == 1) {
                int z = 0;
                while (sign[z] != 0) ++z;
                const int a = (z + 1) % 3, b = (z + 2) % 3;
                const int q = point(a, b);
                return {{v[z], v[a], q}, {v[z], q, v[b]}};
            }
            const int i = isolated(sign);
            const int a = (i + 1) % 3, b = (i + 2) % 3;
            const int qa = point(i, a), qb = point(i, b);
            Piece corner{v[i], qa, qb};
            // The remaining quadrilateral qa, va, vb, qb: the diagonal giving the better pieces.
            Piece a1{qa, v[a], v[b]}, a2{qa, v[b], qb}, b1{qa, v[a], qb}, b2{v[a], v[b], qb};
            const double qualityA = std::min(std::abs(measure(a1)), std::abs(measure(a2)));
            const double qualityB = std::min(std::abs(measure(b1)), std::abs(measure(b2)));
            if (qualityA >= qualityB) return {corner, a1, a2};
            return {corner, b1, b2};
        }
        // Tetrahedron.
        std::vector<int> zeros, pl, mi;
        for (int i = 0; i < 4; ++i) (sign[i] == 0 ? zeros : (sign[i] > 0 ? pl : mi)).push_back(i);
        if (zeros.size() == 2) {
            const int q = point(pl[0], mi[0]);
            return {{v[zeros[0]], v[zeros[1]], v[pl[0]], q}, {v[zeros[0]], v[zeros[1]], q, v[mi[0]]}};
        }
        if (zeros.size() == 1) {
            const auto& single = pl.size() == 1 ? pl : mi;
            const auto& pair = pl.size() == 1 ? mi : pl;
            const int i = single[0], a = pair[0], b = pair[1];
            const int qa = point(i, a), qb = point(i, b);
            std::vector<Piece> out{{v[zeros[0]], v[i], qa, qb}};
            pyramid(v[zeros[0]], {qa, v[a], v[b], qb}, out);
            return out;
        }
        if (pl.size() == 1 || mi.size() == 1) {
            const auto& single = pl.size() == 1 ? pl : mi;
            const auto& rest = pl.size() == 1 ? mi : pl;
            const int i = single[0];
            const int qa = point(i, rest[0]), qb = point(i, rest[1]), qc = point(i, rest[2]);
            std::vector<Piece> out{{v[i], qa, qb, qc}};
            prism({qa, qb, qc}, {v[rest[0]], v[rest[1]], v[rest[2]]}, out);
            return out;
        }
        // Two vertices on each side: two prisms sharing the interface quadrilateral.
        const int p1 = pl[0], p2 = pl[1], n1 = mi[0], n2 = mi[1];
        const int q11 = point(p1, n1), q12 = point(p1, n2), q21 = point(p2, n1), q22 = point(p2, n2);
        std::vector<Piece> out;
        prism({v[p1], q11, q12}, {v[p2], q21, q22}, out);
        prism({v[n1], q11, q21}, {v[n2], q12, q22}, out);
        return out;
    }

    static int isolated(const std::vector<int>& sign) {
        for (int i = 0; i < 3; ++i)
            if (sign[i] != sign[(i + 1) % 3] && sign[i] != sign[(i + 2) % 3]) return i;
        return 0;
    }

    // Pyramid (apex, quadrilateral q0..q3 in cyclic order) -> 2 tetrahedra; the base diagonal
    // starts at the base vertex of smallest index so that faces shared by neighbours match.
    static void pyramid(int apex, const std::array<int, 4>& q, std::vector<Piece>& out) {
        const int m = static_cast<int>(std::min_element(q.begin(), q.end()) - q.begin());
        if (m % 2 == 0) {
            out.push_back({apex, q[0], q[1], q[2]});
            out.push_back({apex, q[0], q[2], q[3]});
        } else {
            out.push_back({apex, q[0], q[1], q[3]});
            out.push_back({apex, q[1], q[2], q[3]});
        }
    }

    // Prism (triangles t and u, t[i]-u[i] lateral edges) -> 3 tetrahedra, every quadrilateral
    // face split from its vertex of smallest index (conforming with the neighbours).
    static void prism(std::array<int, 3> t, std::array<int, 3> u, std::vector<Piece>& out) {
        int best = t[0], where = 0;
        for (int i = 0; i < 3; ++i) {
            if (t[i] < best) best = t[i], where = i;
            if (u[i] < best) best = u[i], where = i + 3;
        }
        if (where >= 3) std::swap(t, u), where -= 3;
        const int m = t[where], x = t[(where + 1) % 3], y = t[(where + 2) % 3];
        const int mp = u[where], xp = u[(where + 1) % 3], yp = u[(where + 2) % 3];
        out.push_back({m, mp, xp, yp});
        if (std::min(x, yp) < std::min(y, xp)) {
            out.push_back({m, x, y, yp});
            out.push_back({m, x, yp, xp});
        } else {
            out.push_back({m, x, y, xp});
            out.push_back({m, xp, y, yp});
        }
    }

    const Mesh& mesh_;
    CellCut& cut_;
    std::span<const int> nodes_;
    bool simplexParent_ = true;
    double lref_ = 1.0;
    std::map<std::pair<int, int>, int> edgePoints_;              // zero of the current crack per segment
    std::map<std::pair<int, int>, std::vector<int>> onSegment_;  // points created on a segment, any crack
};

}  // namespace

double CellCut::referenceMeasure(int s) const {
    std::array<std::array<double, 3>, 4> v{};
    for (int i = 0; i < vertexCount(); ++i) v[i] = points[subcells[s].vertices[i]].ref;
    if (dim == 1) return std::abs(v[1][0] - v[0][0]);
    return std::abs(simplexMeasure(dim, std::span<const std::array<double, 3>>(v.data(), vertexCount())));
}

CellCut cutCell(const Mesh& mesh, int cell, const std::vector<const Crack*>& local, const std::vector<int>& localIndex,
                bool skin, const std::vector<int>& outsideSign) {
    CellCut cut;
    cut.cell = cell;
    cut.type = mesh.cellTypes[cell];
    if (!xfemSupports(cut.type)) primarySimplices(cut.type);  // throws NotImplemented
    cut.dim = cellDimension(cut.type);
    cut.skin = skin;
    cut.cracks = localIndex;
    cut.lsnCracks = local;
    for (const Crack* c : local)
        for (const auto& m : c->masters)
            if (std::find(cut.lsnCracks.begin(), cut.lsnCracks.end(), m.crack.get()) == cut.lsnCracks.end())
                cut.lsnCracks.push_back(m.crack.get());
    const auto nodes = mesh.cellNodes(cell);
    const auto ref = referenceNodes(cut.type);
    for (size_t a = 0; a < nodes.size(); ++a) {
        CutPoint p;
        p.ref = ref[a];
        p.parentNode = static_cast<int>(a);
        for (const Crack* c : cut.lsnCracks) p.lsn.push_back(c->lsn[nodes[a]]);
        cut.points.push_back(std::move(p));
    }
    for (const auto& simplex : primarySimplices(cut.type)) {
        SubCell sub;
        for (size_t i = 0; i < simplex.size(); ++i) sub.vertices[i] = simplex[i];
        sub.heaviside.assign(local.size(), 0);
        cut.subcells.push_back(std::move(sub));
    }
    Cutter cutter(mesh, cut);
    for (size_t j = 0; j < local.size(); ++j) cutter.cutBy(static_cast<int>(j), outsideSign);
    return cut;
}

}  // namespace ma::xfem
