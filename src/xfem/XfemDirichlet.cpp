#include "xfem/XfemDirichlet.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/Messages.hpp"
#include "fe/DofNumbering.hpp"
#include "fe/MechanicalLoad.hpp"
#include "xfem/CellGeometry.hpp"
#include "xfem/XfemMessages.hpp"
#include "xfem/XfemModel.hpp"

namespace ma::xfem {

namespace {

constexpr double kSideOffset = 1e-6;  // f is sampled 1e-6 (edge fraction) away from the crossing

std::array<double, 3> along(const std::array<double, 3>& a, const std::array<double, 3>& b, double t) {
    return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
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
        const int ref = xm_.referenceCell(n);
        const CellCut* cut = ref >= 0 ? xm_.cut(ref) : nullptr;
        if (!cut || cut->cracks.size() != 1 || xm_.activeSlots(n) < 1) return plain(n, at(mesh_.coords[n]));
        Enriched e{n, *xm_.cracks()[cut->cracks[0]], xm_.node(n)->slotValue[0], fmt::format("H1{}", "XYZ"[c_]), {}};
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
