#include "xfem/XfemDirichlet.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/Messages.hpp"
#include "fe/DofNumbering.hpp"
#include "xfem/CellGeometry.hpp"
#include "xfem/XfemModel.hpp"

namespace ma::xfem {

namespace {

constexpr double kSideOffset = 1e-6;  // f is sampled 1e-6 (edge fraction) away from the crossing

std::array<double, 3> along(const std::array<double, 3>& a, const std::array<double, 3>& b, double t) {
    return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

}  // namespace

std::vector<LinearRelation> xfemDirichlet(const XfemModel& xm, const ImposedDof& request, double inst) {
    const Mesh& mesh = xm.mesh();
    const std::string& comp = request.component;
    int slot = 0, c = 0;
    parseDisplacementComponent(comp, slot, c);
    std::vector<LinearRelation> out;
    if (c >= xm.dim()) return out;  // DZ on a 2D model: no such unknown
    const char letter = "XYZ"[c];

    std::vector<int> nodes;
    std::vector<char> inGroup(mesh.nodeCount(), 0);
    for (int n : request.nodes)
        if (!inGroup[n]) inGroup[n] = 1, nodes.push_back(n);

    // Points where the value is needed, evaluated in one batch at the end; relations are emitted
    // by closures reading the values.
    std::vector<std::array<double, 3>> points;
    std::vector<std::function<void(const std::vector<double>&)>> emit;
    auto at = [&](const std::array<double, 3>& x) {
        points.push_back(x);
        return points.size() - 1;
    };
    bool bothLipsAlarm = false;

    for (int n : nodes) {
        const int carried = xm.nodeSlots(n) - 1;
        if (slot > 0) {  // H-component: plain relation where the slot is active
            if (slot <= xm.activeSlots(n)) {
                const size_t p = at(mesh.coords[n]);
                emit.push_back([&, n, p](const std::vector<double>& f) { out.push_back({{{n, comp, 1.0}}, f[p]}); });
            } else if (slot <= carried && request.function == nullptr && request.value != 0.0) {
                msg().alarm("XFEM_DDL", fmt::format("{}: {} = {} ignored on node {}: that Heaviside slot is inactive "
                                                    "there and fixed to 0",
                                                    request.path, comp, request.value, mesh.nodeNames[n]));
            }
            continue;
        }
        const int ref = xm.referenceCell(n);
        const CellCut* cut = ref >= 0 ? xm.cut(ref) : nullptr;
        if (!cut || cut->cracks.size() != 1 || xm.activeSlots(n) < 1) {
            const size_t p = at(mesh.coords[n]);
            emit.push_back([&, n, p](const std::vector<double>& f) { out.push_back({{{n, comp, 1.0}}, f[p]}); });
            continue;
        }
        const Crack& crack = *xm.cracks()[cut->cracks[0]];
        const auto& lsn = crack.lsn;
        const double s = xm.node(n)->slotValue[0];  // psi of the node's slot on the other side
        const std::string h = fmt::format("H1{}", letter);
        // Prescribed nodes connected to n through the X-FEM cells around it.
        std::vector<int> neighbours;
        for (int cell : xm.cellsOfNode(n))
            for (int w : mesh.cellNodes(cell))
                if (w != n && inGroup[w] && std::find(neighbours.begin(), neighbours.end(), w) == neighbours.end())
                    neighbours.push_back(w);

        if (!request.function) {  // §4.2
            const double v = request.value;
            if (lsn[n] != 0.0) {
                out.push_back({{{n, comp, 1.0}}, v});
                continue;
            }
            bool plus = false, minus = false;
            for (int w : neighbours) plus |= lsn[w] > 0, minus |= lsn[w] < 0;
            if (neighbours.empty() || (plus && minus)) {
                out.push_back({{{n, comp, 1.0}}, v});
                out.push_back({{{n, comp, 1.0}, {n, h, s}}, v});
                bothLipsAlarm = true;
            } else if (plus) {
                out.push_back({{{n, comp, 1.0}}, v});
            } else if (minus) {
                out.push_back({{{n, comp, 1.0}, {n, h, s}}, v});
            } else {
                msg().alarm("XFEM_DDL", fmt::format("{}: node {} lies on the interface {} and the other prescribed "
                                                    "nodes around it too: {} is not imposed there",
                                                    request.path, mesh.nodeNames[n], crack.name, comp));
            }
            continue;
        }

        // §4.3: function values. A cut edge of the prescribed group from n.
        int other = -1;
        for (int cell : xm.cellsOfNode(n)) {
            if (cellDimension(mesh.cellTypes[cell]) != xm.dim()) continue;  // volume cells only
            const auto cn = mesh.cellNodes(cell);
            for (const auto& e : cellEdges(mesh.cellTypes[cell])) {
                const int a = cn[e[0]], b = cn[e[1]];
                if (a != n && b != n) continue;
                const int w = a == n ? b : a;
                if (inGroup[w] && lsn[n] * lsn[w] < 0) {
                    other = w;
                    break;
                }
            }
            if (other >= 0) break;
        }
        const auto& xn = mesh.coords[n];
        if (lsn[n] != 0.0 && other >= 0) {
            const int vm = lsn[n] < 0 ? n : other, vp = lsn[n] < 0 ? other : n;
            const double t = lsn[vm] / (lsn[vm] - lsn[vp]);  // crossing, from V- (0) to V+ (1)
            const double Nm = 1 - t, Np = t;
            const size_t pn = at(xn), pm = at(mesh.coords[vm]), pp = at(mesh.coords[vp]);
            const size_t fPlus = at(along(mesh.coords[vm], mesh.coords[vp], std::min(1.0, t + kSideOffset)));
            const size_t fMinus = at(along(mesh.coords[vm], mesh.coords[vp], std::max(0.0, t - kSideOffset)));
            const bool minusNode = n == vm;
            emit.push_back([&, n, h, s, pn, pm, pp, fPlus, fMinus, Nm, Np, minusNode](const std::vector<double>& f) {
                // (f+ - Np f(V+) - Nm f(V-)) / (s Nm) written without the cancellation of
                // f(V+) - Np f(V+) when the crossing is close to V- (Nm small), using Nm + Np = 1.
                const double b = minusNode ? ((f[fPlus] - f[pp]) + Nm * (f[pp] - f[pm])) / (s * Nm)
                                           : ((f[fMinus] - f[pm]) + Np * (f[pm] - f[pp])) / (s * Np);
                out.push_back({{{n, h, 1.0}}, b});
                out.push_back({{{n, comp, 1.0}}, f[pn]});
            });
            continue;
        }
        if (lsn[n] == 0.0) {
            // Node on the interface: f just on each side, towards prescribed neighbours.
            int wPlus = -1, wMinus = -1;
            for (int w : neighbours) {
                if (lsn[w] > 0 && wPlus < 0) wPlus = w;
                if (lsn[w] < 0 && wMinus < 0) wMinus = w;
            }
            if (wPlus < 0 && wMinus < 0) {
                const size_t p = at(xn);
                emit.push_back([&, n, h, s, p](const std::vector<double>& f) {
                    out.push_back({{{n, comp, 1.0}}, f[p]});
                    out.push_back({{{n, comp, 1.0}, {n, h, s}}, f[p]});
                });
                bothLipsAlarm = true;
                continue;
            }
            const size_t pp = wPlus >= 0 ? at(along(xn, mesh.coords[wPlus], kSideOffset)) : 0;
            const size_t pm = wMinus >= 0 ? at(along(xn, mesh.coords[wMinus], kSideOffset)) : 0;
            const bool hasPlus = wPlus >= 0, hasMinus = wMinus >= 0;
            emit.push_back([&, n, h, s, pp, pm, hasPlus, hasMinus](const std::vector<double>& f) {
                if (hasPlus) out.push_back({{{n, comp, 1.0}}, f[pp]});
                if (hasPlus && hasMinus) out.push_back({{{n, h, 1.0}}, (f[pm] - f[pp]) / s});
                if (!hasPlus) out.push_back({{{n, comp, 1.0}, {n, h, s}}, f[pm]});
            });
            continue;
        }
        // No cut edge in the group (§4.3.5): the other lip at the node takes f just across the
        // interface towards the prescribed node of the other side farthest from it.
        int far = -1;
        for (int w : neighbours)
            if (lsn[w] * lsn[n] <= 0 && (far < 0 || std::abs(lsn[w]) > std::abs(lsn[far]))) far = w;
        const size_t pn = at(xn);
        if (far < 0) {
            emit.push_back([&, n, pn](const std::vector<double>& f) { out.push_back({{{n, comp, 1.0}}, f[pn]}); });
            continue;
        }
        const double t0 = lsn[far] == 0.0 ? 1.0 : lsn[n] / (lsn[n] - lsn[far]);
        const size_t po = at(along(xn, mesh.coords[far], std::min(1.0, t0 + kSideOffset)));
        emit.push_back([&, n, h, s, pn, po](const std::vector<double>& f) {
            out.push_back({{{n, comp, 1.0}}, f[pn]});
            out.push_back({{{n, comp, 1.0}, {n, h, s}}, f[po]});
        });
    }

    std::vector<double> values(points.size(), request.value);
    if (request.function && !points.empty()) values = evaluateAtPoints(*request.function, points, inst);
    for (const auto& e : emit) e(values);
    if (bothLipsAlarm)
        msg().alarm("XFEM_22", fmt::format("{}: {} is prescribed on both lips of nodes lying on an interface; "
                                           "do not also prescribe their Heaviside components (singular system)",
                                           request.path, comp));
    return out;
}

bool xfemImposedDofHandler(const Model& model, const ImposedDof& request, double inst,
                           std::vector<LinearRelation>& out) {
    const auto* xm = dynamic_cast<const XfemModel*>(model.enrichment.get());
    if (!xm) return false;
    int slot = 0, comp = 0;
    if (!parseDisplacementComponent(request.component, slot, comp)) return false;
    // Nodes outside the model carry no unknown: let them out like the classical path does.
    const DofNumbering numbering(model);
    ImposedDof kept = request;
    kept.nodes.clear();
    for (int n : request.nodes)
        if (numbering.hasNode(n)) kept.nodes.push_back(n);
    auto relations = xfemDirichlet(*xm, kept, inst);
    out.insert(out.end(), relations.begin(), relations.end());
    return true;
}

}  // namespace ma::xfem
