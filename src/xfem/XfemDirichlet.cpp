#include "xfem/XfemDirichlet.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/Messages.hpp"
#include "fe/DofNumbering.hpp"
#include "fe/MechanicalLoad.hpp"
#include "mesh/ShapeFunctions.hpp"
#include "xfem/CellGeometry.hpp"
#include "xfem/XfemMessages.hpp"
#include "xfem/XfemModel.hpp"

namespace ma::xfem {

namespace {

constexpr double kSideOffset = 1e-6;  // f is sampled 1e-6 (edge fraction) away from the crossing

std::array<double, 3> along(const std::array<double, 3>& a, const std::array<double, 3>& b, double t) {
    return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

// Sub-cells of `cut` containing the reference point p (on their boundary included).
std::vector<int> subcellsAt(const CellCut& cut, const std::array<double, 3>& p) {
    std::vector<int> out;
    const int nv = cut.vertexCount();
    for (int s = 0; s < static_cast<int>(cut.subcells.size()); ++s) {
        std::array<std::array<double, 3>, 4> v{};
        for (int i = 0; i < nv; ++i) v[i] = cut.points[cut.subcells[s].vertices[i]].ref;
        const double whole = simplexMeasure(cut.dim, std::span<const std::array<double, 3>>(v.data(), nv));
        bool inside = whole != 0.0;
        for (int i = 0; i < nv && inside; ++i) {
            auto w = v;
            w[i] = p;
            const double part = simplexMeasure(cut.dim, std::span<const std::array<double, 3>>(w.data(), nv));
            inside = part / whole >= -1e-12;
        }
        if (inside) out.push_back(s);
    }
    return out;
}

// Relations of one DDL_IMPO request, node by node. Points where the value is needed are evaluated
// in one batch at the end; relations that need them are emitted by closures reading the values.
class DirichletBuilder {
public:
    DirichletBuilder(const XfemModel& xm, const ImposedDof& request)
        : xm_(xm), mesh_(xm.mesh()), request_(request), comp_(request.component), inGroup_(mesh_.nodeCount(), 0) {
        parseDisplacementComponent(comp_, slot_, c_);
        for (int n : request.nodes)
            if (!inGroup_[n]) inGroup_[n] = 1, nodes_.push_back(n);
    }

    std::vector<LinearRelation> build(double inst) {
        if (c_ >= xm_.dim()) return {};  // DZ on a 2D model: no such unknown
        for (int n : nodes_) node(n);
        std::vector<double> values(points_.size(), request_.value);
        if (request_.function && !points_.empty()) values = evaluateAtPoints(*request_.function, points_, inst);
        for (const auto& e : emit_) e(values);
        if (bothLipsAlarm_) msg().alarm(XFEM_22, request_.path, comp_);
        return std::move(out_);
    }

private:
    size_t at(const std::array<double, 3>& x) {
        points_.push_back(x);
        return points_.size() - 1;
    }

    // u_comp(n) = f(point p).
    void plain(int n, size_t p) {
        emit_.push_back([this, n, p](const std::vector<double>& f) { out_.push_back({{{n, comp_, 1.0}}, f[p]}); });
    }

    void node(int n) {
        if (slot_ > 0) return heavisideComponent(n);
        // The interfaces that enrich the node decide, not those its cells see: a node next to a
        // junction cell sits in cells seeing three interfaces while only one enriches it.
        const NodeEnrichment* en = xm_.node(n);
        if (!en || xm_.activeSlots(n) < 1) return plain(n, at(mesh_.coords[n]));
        // A crack-tip node (docs/cracks.md): its enrichments vanish at the node itself (shifted
        // Heaviside, fields minus their nodal interpolation), so u(node) = DX; the other side's
        // Heaviside unknowns and K1..K3 stay as the user gives them (H1X=, K1=).
        if (xm_.tipNode(n)) return plain(n, at(mesh_.coords[n]));
        if (en->activeCracks.size() != 1) return severalInterfaces(n, *en);
        Enriched e{n, *xm_.cracks()[en->activeCracks[0]], en->slotValue[0], fmt::format("H1{}", "XYZ"[c_]), {}};
        // Prescribed nodes connected to n through the X-FEM cells around it.
        for (int cell : xm_.cellsOfNode(n))
            for (int w : mesh_.cellNodes(cell))
                if (w != n && inGroup_[w] &&
                    std::find(e.neighbours.begin(), e.neighbours.end(), w) == e.neighbours.end())
                    e.neighbours.push_back(w);
        if (!request_.function) return constantValue(e);
        const int other = cutEdgeInGroup(n, e.crack.lsn);
        if (e.crack.lsn[n] != 0.0 && other >= 0) return functionOnCutEdge(e, other);
        if (e.crack.lsn[n] == 0.0) return functionOnInterface(e);
        functionAcross(e);
    }

    // A node several interfaces enrich (code_aster imposes the classical unknown only there, or
    // nothing when the node is on one of them: xddlim, nfiss > 1; the other sides of the node are
    // then free or wrong). One relation per side (domain) of the node that a prescribed neighbour w
    // reaches: next to n, u_D = U0 + psi_k U_k = f just inside D (the own side, and the sides of an
    // interface through n), as §4.2 does for one interface. For a function, also across the last
    // interface crossing of an edge n-w: the side of w gets the value that makes u along the edge
    // equal to f beyond the crossing, as §4.3's cut edge does for one interface.
    void severalInterfaces(int n, const NodeEnrichment& en) {
        std::vector<std::vector<signed char>> done;
        auto fresh = [&done](const std::vector<signed char>& key) {
            if (std::find(done.begin(), done.end(), key) != done.end()) return false;
            done.push_back(key);
            return true;
        };
        for (int cell : xm_.cellsOfNode(n)) {
            const CellCut* cut = xm_.cut(cell);
            if (!cut || cut->skin) continue;
            const auto cn = mesh_.cellNodes(cell);
            const auto ref = referenceNodes(mesh_.cellTypes[cell]);
            const auto ln = std::find(cn.begin(), cn.end(), n) - cn.begin();
            for (size_t lw = 0; lw < cn.size(); ++lw) {
                const int w = cn[lw];
                if (w == n || !inGroup_[w]) continue;
                const auto nearN = sideAt(n, *cut, along(ref[ln], ref[lw], kSideOffset));
                if (nearN.subcell >= 0 && fresh(nearN.key))
                    sideRelation(n, en, nearN.key, valueAt(at(insideSubcell(*cut, nearN.subcell, nearN.ref))));
                const auto nearW = sideAt(n, *cut, along(ref[lw], ref[ln], kSideOffset));
                const double t = lastCrossing(n, w);
                if (!request_.function || nearW.subcell < 0 || nearW.key == nearN.key || !isEdge(cell, ln, lw) ||
                    t <= 0.0)
                    continue;
                if (!fresh(nearW.key)) continue;
                const double tc = std::min(t + kSideOffset, 1.0 - 2 * kSideOffset), tw = 1.0 - kSideOffset;
                const size_t pc = at(along(mesh_.coords[n], mesh_.coords[w], tc));
                const size_t pw = at(along(mesh_.coords[n], mesh_.coords[w], tw));
                sideRelation(n, en, nearW.key, [pc, pw, tc, tw](const std::vector<double>& f) {
                    return f[pc] - tc * (f[pw] - f[pc]) / (tw - tc);
                });
            }
        }
        if (done.empty()) {
            for (size_t k = 0; k <= en.slotDomain.size(); ++k)
                sideRelation(n, en, k == 0 ? en.own : en.slotDomain[k - 1], valueAt(at(mesh_.coords[n])));
            bothLipsAlarm_ = true;
        }
    }

    static std::function<double(const std::vector<double>&)> valueAt(size_t p) {
        return [p](const std::vector<double>& f) { return f[p]; };
    }

    // The side of node n's domains that contains reference point p of `cut` (subcell -1 when p
    // lies between sub-cells of different sides, on an interface).
    struct Side {
        std::vector<signed char> key;
        int subcell = -1;
        std::array<double, 3> ref{};
    };
    Side sideAt(int n, const CellCut& cut, const std::array<double, 3>& p) const {
        const auto subs = subcellsAt(cut, p);
        if (subs.empty()) return {};
        Side side{xm_.domainKey(n, cut, subs[0]), subs[0], p};
        for (int s : subs)
            if (xm_.domainKey(n, cut, s) != side.key) return {};
        return side;
    }

    bool isEdge(int cell, long a, long b) const {
        for (const auto& e : cellEdges(mesh_.cellTypes[cell]))
            if ((e[0] == a && e[1] == b) || (e[0] == b && e[1] == a)) return true;
        return false;
    }

    // Edge fraction from n of the last zero of any interface's level set on the edge n-w (0: none).
    double lastCrossing(int n, int w) const {
        double t = 0.0;
        for (const auto& crack : xm_.cracks()) {
            const double a = crack->lsn[n], b = crack->lsn[w];
            if (a * b < 0.0) t = std::max(t, a / (a - b));
        }
        return t;
    }

    // Physical point just inside sub-cell s from its point p (reference coordinates): f is sampled
    // there, not on p, which may lie on an interface where f jumps (an edge along the interface).
    std::array<double, 3> insideSubcell(const CellCut& cut, int s, std::array<double, 3> p) const {
        const int nv = cut.vertexCount();
        std::array<double, 3> centroid{0, 0, 0};
        for (int i = 0; i < nv; ++i)
            for (int k = 0; k < 3; ++k) centroid[k] += cut.points[cut.subcells[s].vertices[i]].ref[k] / nv;
        p = along(p, centroid, kSideOffset);
        std::array<double, 8> N{};
        shapeValues(cut.type, p, N);
        const auto cn = mesh_.cellNodes(cut.cell);
        std::array<double, 3> x{0, 0, 0};
        for (size_t a = 0; a < cn.size(); ++a)
            for (int k = 0; k < 3; ++k) x[k] += N[a] * mesh_.coords[cn[a]][k];
        return x;
    }

    // u of node n in domain `key` equals value(f) (a domain whose slot was dropped: none).
    void sideRelation(int n, const NodeEnrichment& en, const std::vector<signed char>& key,
                      std::function<double(const std::vector<double>&)> value) {
        LinearRelation r{{{n, comp_, 1.0}}, 0.0};
        if (key != en.own) {
            const auto it = std::find(en.slotDomain.begin(), en.slotDomain.end(), key);
            if (it == en.slotDomain.end()) return;
            const auto k = it - en.slotDomain.begin();
            r.terms.push_back({n, fmt::format("H{}{}", k + 1, "XYZ"[c_]), en.slotValue[size_t(k)]});
        }
        emit_.push_back([this, r, value = std::move(value)](const std::vector<double>& f) {
            out_.push_back(r);
            out_.back().value = value(f);
        });
    }

    // An enriched node of a cell cut by one interface: the interface, psi of the node's slot on the
    // other side (s), the Heaviside component h and the prescribed neighbours.
    struct Enriched {
        int n;
        const Crack& crack;
        double s;
        std::string h;
        std::vector<int> neighbours;
    };

    // H-component: plain relation where the slot is active.
    void heavisideComponent(int n) {
        const int carried = xm_.nodeSlots(n) - 1;
        if (slot_ <= xm_.activeSlots(n)) {
            plain(n, at(mesh_.coords[n]));
        } else if (slot_ <= carried && request_.function == nullptr && request_.value != 0.0) {
            msg().alarm(XFEM_DDL_INACTIVE_SLOT, request_.path, comp_, request_.value, mesh_.nodeNames[n]);
        }
    }

    // §4.2: a constant value.
    void constantValue(const Enriched& e) {
        const int n = e.n;
        const auto& lsn = e.crack.lsn;
        const double v = request_.value;
        if (lsn[n] != 0.0) {
            out_.push_back({{{n, comp_, 1.0}}, v});
            return;
        }
        bool plus = false, minus = false;
        for (int w : e.neighbours) plus |= lsn[w] > 0, minus |= lsn[w] < 0;
        if (e.neighbours.empty() || (plus && minus)) {
            out_.push_back({{{n, comp_, 1.0}}, v});
            out_.push_back({{{n, comp_, 1.0}, {n, e.h, e.s}}, v});
            bothLipsAlarm_ = true;
        } else if (plus) {
            out_.push_back({{{n, comp_, 1.0}}, v});
        } else if (minus) {
            out_.push_back({{{n, comp_, 1.0}, {n, e.h, e.s}}, v});
        } else {
            msg().alarm(XFEM_DDL_INTERFACE_NODES, request_.path, mesh_.nodeNames[n], e.crack.name, comp_);
        }
    }

    // §4.3: function values. A cut edge of the prescribed group from n (-1: none).
    int cutEdgeInGroup(int n, const std::vector<double>& lsn) const {
        for (int cell : xm_.cellsOfNode(n)) {
            if (cellDimension(mesh_.cellTypes[cell]) != xm_.dim()) continue;  // volume cells only
            const auto cn = mesh_.cellNodes(cell);
            for (const auto& e : cellEdges(mesh_.cellTypes[cell])) {
                const int a = cn[e[0]], b = cn[e[1]];
                if (a != n && b != n) continue;
                const int w = a == n ? b : a;
                if (inGroup_[w] && lsn[n] * lsn[w] < 0) return w;
            }
        }
        return -1;
    }

    void functionOnCutEdge(const Enriched& e, int other) {
        const int n = e.n;
        const auto& lsn = e.crack.lsn;
        const int vm = lsn[n] < 0 ? n : other, vp = lsn[n] < 0 ? other : n;
        const double t = lsn[vm] / (lsn[vm] - lsn[vp]);  // crossing, from V- (0) to V+ (1)
        const double Nm = 1 - t, Np = t;
        const size_t pn = at(mesh_.coords[n]), pm = at(mesh_.coords[vm]), pp = at(mesh_.coords[vp]);
        const size_t fPlus = at(along(mesh_.coords[vm], mesh_.coords[vp], std::min(1.0, t + kSideOffset)));
        const size_t fMinus = at(along(mesh_.coords[vm], mesh_.coords[vp], std::max(0.0, t - kSideOffset)));
        const bool minusNode = n == vm;
        emit_.push_back(
            [this, n, h = e.h, s = e.s, pn, pm, pp, fPlus, fMinus, Nm, Np, minusNode](const std::vector<double>& f) {
                // (f+ - Np f(V+) - Nm f(V-)) / (s Nm) written without the cancellation of
                // f(V+) - Np f(V+) when the crossing is close to V- (Nm small), using Nm + Np = 1.
                const double b = minusNode ? ((f[fPlus] - f[pp]) + Nm * (f[pp] - f[pm])) / (s * Nm)
                                           : ((f[fMinus] - f[pm]) + Np * (f[pm] - f[pp])) / (s * Np);
                out_.push_back({{{n, h, 1.0}}, b});
                out_.push_back({{{n, comp_, 1.0}}, f[pn]});
            });
    }

    // Node on the interface: f just on each side, towards prescribed neighbours.
    void functionOnInterface(const Enriched& e) {
        const int n = e.n;
        const auto& lsn = e.crack.lsn;
        const auto& xn = mesh_.coords[n];
        int wPlus = -1, wMinus = -1;
        for (int w : e.neighbours) {
            if (lsn[w] > 0 && wPlus < 0) wPlus = w;
            if (lsn[w] < 0 && wMinus < 0) wMinus = w;
        }
        if (wPlus < 0 && wMinus < 0) {
            const size_t p = at(xn);
            emit_.push_back([this, n, h = e.h, s = e.s, p](const std::vector<double>& f) {
                out_.push_back({{{n, comp_, 1.0}}, f[p]});
                out_.push_back({{{n, comp_, 1.0}, {n, h, s}}, f[p]});
            });
            bothLipsAlarm_ = true;
            return;
        }
        const size_t pp = wPlus >= 0 ? at(along(xn, mesh_.coords[wPlus], kSideOffset)) : 0;
        const size_t pm = wMinus >= 0 ? at(along(xn, mesh_.coords[wMinus], kSideOffset)) : 0;
        const bool hasPlus = wPlus >= 0, hasMinus = wMinus >= 0;
        emit_.push_back([this, n, h = e.h, s = e.s, pp, pm, hasPlus, hasMinus](const std::vector<double>& f) {
            if (hasPlus) out_.push_back({{{n, comp_, 1.0}}, f[pp]});
            if (hasPlus && hasMinus) out_.push_back({{{n, h, 1.0}}, (f[pm] - f[pp]) / s});
            if (!hasPlus) out_.push_back({{{n, comp_, 1.0}, {n, h, s}}, f[pm]});
        });
    }

    // No cut edge in the group (§4.3.5): the other lip at the node takes f just across the
    // interface towards the prescribed node of the other side farthest from it.
    void functionAcross(const Enriched& e) {
        const int n = e.n;
        const auto& lsn = e.crack.lsn;
        const auto& xn = mesh_.coords[n];
        int far = -1;
        for (int w : e.neighbours)
            if (lsn[w] * lsn[n] <= 0 && (far < 0 || std::abs(lsn[w]) > std::abs(lsn[far]))) far = w;
        const size_t pn = at(xn);
        if (far < 0) return plain(n, pn);
        const double t0 = lsn[far] == 0.0 ? 1.0 : lsn[n] / (lsn[n] - lsn[far]);
        const size_t po = at(along(xn, mesh_.coords[far], std::min(1.0, t0 + kSideOffset)));
        emit_.push_back([this, n, h = e.h, s = e.s, pn, po](const std::vector<double>& f) {
            out_.push_back({{{n, comp_, 1.0}}, f[pn]});
            out_.push_back({{{n, comp_, 1.0}, {n, h, s}}, f[po]});
        });
    }

    const XfemModel& xm_;
    const Mesh& mesh_;
    const ImposedDof& request_;
    const std::string& comp_;
    int slot_ = 0, c_ = 0;
    std::vector<char> inGroup_;
    std::vector<int> nodes_;
    std::vector<std::array<double, 3>> points_;
    std::vector<std::function<void(const std::vector<double>&)>> emit_;
    std::vector<LinearRelation> out_;
    bool bothLipsAlarm_ = false;
};

}  // namespace

std::vector<LinearRelation> xfemDirichlet(const XfemModel& xm, const ImposedDof& request, double inst) {
    return DirichletBuilder(xm, request).build(inst);
}

bool XfemModel::imposeDof(const Model& model, const ImposedDof& request, double inst,
                          std::vector<LinearRelation>& out) const {
    int slot = 0, comp = 0;
    if (!parseDisplacementComponent(request.component, slot, comp)) return false;
    // Nodes outside the model carry no unknown: let them out like the classical path does.
    const DofNumbering numbering(model);
    ImposedDof kept = request;
    kept.nodes.clear();
    for (int n : request.nodes)
        if (numbering.hasNode(n)) kept.nodes.push_back(n);
    auto relations = xfemDirichlet(*this, kept, inst);
    out.insert(out.end(), relations.begin(), relations.end());
    return true;
}

}  // namespace ma::xfem
