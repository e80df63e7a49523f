#include "xfem/XfemModel.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "fe/Quadrature.hpp"
#include "mesh/ElementGeometry.hpp"
#include "mesh/ShapeFunctions.hpp"
#include "xfem/CellGeometry.hpp"

namespace ma::xfem {

namespace {

// Measure of the reference simplex of each dimension (SEG2 [-1,1], unit triangle, unit tetra).
double referenceSimplexMeasure(int dim) { return dim == 1 ? 2.0 : (dim == 2 ? 0.5 : 1.0 / 6.0); }

// Barycentric coordinates of a point of the reference simplex.
std::array<double, 4> barycentric(int dim, const std::array<double, 3>& x) {
    if (dim == 1) return {0.5 * (1 - x[0]), 0.5 * (1 + x[0]), 0, 0};
    if (dim == 2) return {1 - x[0] - x[1], x[0], x[1], 0};
    return {1 - x[0] - x[1] - x[2], x[0], x[1], x[2]};
}

// Physical gradient of the parent shape functions at a reference point and |det J|.
double physicalGradients(const Mesh& mesh, int cell, const std::array<double, 3>& xi, std::vector<double>& grad) {
    const CellType type = mesh.cellTypes[cell];
    const int d = cellDimension(type);
    const auto nodes = mesh.cellNodes(cell);
    const int n = static_cast<int>(nodes.size());
    std::array<double, 24> dN{};
    shapeDerivatives(type, xi, dN);
    double J[3][3] = {}, inv[3][3] = {};
    jacobian(
        d, d, n, [&](int a) -> const Vec3& { return mesh.coords[nodes[a]]; },
        [&](int a, int j) { return dN[3 * a + j]; }, J);
    grad.assign(3 * n, 0.0);
    const double det = invertJacobian(d, J, inv);
    if (det == 0.0) return 0.0;
    for (int a = 0; a < n; ++a)
        physicalGradient(
            d, inv, [&](int j) { return dN[3 * a + j]; }, &grad[3 * a]);
    return std::abs(det);
}

std::string digits(const std::vector<signed char>& key) {
    std::string s = "(";
    for (size_t i = 0; i < key.size(); ++i) s += fmt::format("{}{:+d}", i ? "," : "", int(key[i]));
    return s + ")";
}

}  // namespace

XfemModel::XfemModel(const Model& model, std::vector<std::shared_ptr<const Crack>> cracks, XfemContact contact,
                     double conditioningCriterion, int subcellDegree)
    : mesh_(model.mesh),
      cracks_(std::move(cracks)),
      contact_(contact),
      criterion_(conditioningCriterion),
      subcellDegree_(subcellDegree) {
    if (!mesh_) throw UserError("MODELE_IN has no mesh");
    if (subcellDegree_ < 0 || subcellDegree_ > kMaxSubcellDegree)
        throw UserError(
            fmt::format("sub-cell quadrature degree {} is outside 1..{}", subcellDegree_, kMaxSubcellDegree));
    dim_ = model.dim;
    if (cracks_.empty()) throw UserError("FISSURE: at least one crack is needed");
    for (size_t i = 0; i < cracks_.size(); ++i) {
        const Crack& c = *cracks_[i];
        if (c.mesh.get() != mesh_.get())
            throw UserError(fmt::format("FISSURE: crack {} is defined on mesh {}, the model on mesh {}", c.name,
                                        c.mesh ? c.mesh->name : "?", mesh_->name));
        for (size_t j = 0; j < i; ++j)
            if (cracks_[j] == cracks_[i]) throw UserError(fmt::format("FISSURE: crack {} is listed twice", c.name));
        for (const auto& m : c.masters) {
            auto it =
                std::find_if(cracks_.begin(), cracks_.end(), [&](const auto& x) { return x.get() == m.crack.get(); });
            if (it == cracks_.end())
                throw UserError(
                    fmt::format("FISSURE: crack {} is joined (JONCTION) to crack {}, which is not in "
                                "the list; add {} before {}",
                                c.name, m.crack->name, m.crack->name, c.name));
            if (static_cast<size_t>(it - cracks_.begin()) > i)
                throw UserError(
                    fmt::format("FISSURE: crack {} is joined (JONCTION) to crack {}, which must be listed before it "
                                "(code_aster XFEM_46: the master interface comes first)",
                                c.name, m.crack->name));
        }
    }
    buildCells(model);
    buildNodes();
    buildTip();
}

void XfemModel::buildCells(const Model& model) {
    const Mesh& mesh = *mesh_;
    const int nc = mesh.cellCount();
    std::vector<signed char> kind(nc, 0);  // 1 volume element, 2 skin element
    for (const auto& e : model.elements) kind[e.cell] = 1;
    for (const auto& e : model.skinElements)
        if (kind[e.cell] == 0) kind[e.cell] = 2;
    std::vector<std::vector<int>> local;
    cellIndex_.assign(nc, -1);
    std::vector<int> order;
    for (size_t k = 0; k < cracks_.size(); ++k)
        for (int c : cracks_[k]->heavisideCells) {
            if (kind[c] == 0) continue;
            if (cellIndex_[c] < 0) {
                cellIndex_[c] = static_cast<int>(local.size());
                local.emplace_back();
                order.push_back(c);
            }
            local[cellIndex_[c]].push_back(static_cast<int>(k));
        }
    std::sort(order.begin(), order.end());

    // Volume elements around each node (to find the volume next to a skin cell).
    std::vector<int> offsets(mesh.nodeCount() + 1, 0), cells;
    bool haveSkin = std::any_of(order.begin(), order.end(), [&](int c) { return kind[c] == 2; });
    if (haveSkin) {
        for (const auto& e : model.elements)
            for (int n : mesh.cellNodes(e.cell)) ++offsets[n + 1];
        for (int n = 0; n < mesh.nodeCount(); ++n) offsets[n + 1] += offsets[n];
        cells.resize(offsets.back());
        std::vector<int> fill(offsets.begin(), offsets.end() - 1);
        for (const auto& e : model.elements)
            for (int n : mesh.cellNodes(e.cell)) cells[fill[n]++] = e.cell;
    }

    std::vector<int> newIndex(nc, -1);
    for (int c : order) {
        const auto& loc = local[cellIndex_[c]];
        std::vector<const Crack*> crackPtrs;
        for (int k : loc) crackPtrs.push_back(cracks_[k].get());
        std::vector<int> outside;
        int volume = -1;
        if (kind[c] == 2) {
            const auto sn = mesh.cellNodes(c);
            for (int i = offsets[sn[0]]; i < offsets[sn[0] + 1] && volume < 0; ++i) {
                const auto vn = mesh.cellNodes(cells[i]);
                bool all = std::all_of(sn.begin(), sn.end(),
                                       [&](int n) { return std::find(vn.begin(), vn.end(), n) != vn.end(); });
                if (all) volume = cells[i];
            }
            for (const Crack* k : crackPtrs) {
                double sum = 0;
                if (volume >= 0)
                    for (int n : mesh.cellNodes(volume)) sum += k->lsn[n];
                outside.push_back(sum >= 0 ? 1 : -1);
            }
        }
        newIndex[c] = static_cast<int>(cuts_.size());
        cuts_.push_back(cutCell(mesh, c, crackPtrs, loc, kind[c] == 2, outside));
        skinVolume_.push_back(volume);
        xfemCells_.push_back(c);
    }
    cellIndex_ = std::move(newIndex);
}

std::vector<int> XfemModel::cellsOfNode(int node) const {
    return {nodeCells_.begin() + nodeCellOffsets_[node], nodeCells_.begin() + nodeCellOffsets_[node + 1]};
}

// Domains of node n's support, in order of first appearance, with their weights (§3.10): each
// volume sub-cell of the support weighs its measure times the square of the node's largest
// shape-function gradient at its barycentre.
void XfemModel::supportDomains(int n, const std::vector<int>& active, std::vector<std::vector<signed char>>& keys,
                               std::vector<double>& weight, double& total, std::vector<double>& grad) const {
    const Mesh& mesh = *mesh_;
    for (int i = nodeCellOffsets_[n]; i < nodeCellOffsets_[n + 1]; ++i) {
        const CellCut& cut = cuts_[cellIndex_[nodeCells_[i]]];
        if (cut.skin) continue;
        const auto cn = mesh.cellNodes(cut.cell);
        const int a = static_cast<int>(std::find(cn.begin(), cn.end(), n) - cn.begin());
        for (int s = 0; s < static_cast<int>(cut.subcells.size()); ++s) {
            std::array<double, 3> bary{0, 0, 0};
            for (int v = 0; v < cut.vertexCount(); ++v)
                for (int j = 0; j < 3; ++j) bary[j] += cut.points[cut.subcells[s].vertices[v]].ref[j];
            for (int j = 0; j < 3; ++j) bary[j] /= cut.vertexCount();
            const double det = physicalGradients(mesh, cut.cell, bary, grad);
            double gmax = 0;
            for (int j = 0; j < 3; ++j) gmax = std::max(gmax, std::abs(grad[3 * a + j]));
            const double w = cut.referenceMeasure(s) * det * gmax * gmax;
            auto key = domainKeyFor(active, cut, s);
            auto it = std::find(keys.begin(), keys.end(), key);
            if (it == keys.end()) {
                keys.push_back(key);
                weight.push_back(w);
            } else {
                weight[it - keys.begin()] += w;
            }
            total += w;
        }
    }
}

void XfemModel::buildNodes() {
    const Mesh& mesh = *mesh_;
    const int nn = mesh.nodeCount();
    nodeCellOffsets_.assign(nn + 1, 0);
    for (int c : xfemCells_)
        for (int n : mesh.cellNodes(c)) ++nodeCellOffsets_[n + 1];
    for (int n = 0; n < nn; ++n) nodeCellOffsets_[n + 1] += nodeCellOffsets_[n];
    nodeCells_.resize(nodeCellOffsets_.back());
    {
        std::vector<int> fill(nodeCellOffsets_.begin(), nodeCellOffsets_.end() - 1);
        for (int c : xfemCells_)
            for (int n : mesh.cellNodes(c)) nodeCells_[fill[n]++] = c;  // increasing cell order
    }

    nodeIndex_.assign(nn, -1);
    const double threshold = std::pow(criterion_, dim_);
    std::vector<double> grad;
    for (int n = 0; n < nn; ++n) {
        if (nodeCellOffsets_[n] == nodeCellOffsets_[n + 1]) continue;
        NodeEnrichment e;
        for (size_t k = 0; k < cracks_.size(); ++k)  // Heaviside status: 1, or 3 (Heaviside and crack tip)
            if (cracks_[k]->nodeStatus[n] == 1 || cracks_[k]->nodeStatus[n] == 3)
                e.activeCracks.push_back(static_cast<int>(k));
        if (!e.activeCracks.empty()) {
            for (int k : e.activeCracks) e.own.push_back(nodalDigit(k, n));
            std::vector<std::vector<signed char>> keys;
            std::vector<double> weight;
            double total = 0;
            supportDomains(n, e.activeCracks, keys, weight, total, grad);
            auto ownIt = std::find(keys.begin(), keys.end(), e.own);
            if (ownIt == keys.end() && !keys.empty()) {
                e.ownMissing = true;
                e.own = keys.front();
                ownIt = keys.begin();
                msg().infof("    node {}: its own side {} is absent from its support; side {} taken instead",
                            mesh.nodeNames[n], digits(e.own), digits(keys.front()));
            }
            for (size_t d = 0; d < keys.size(); ++d) {
                if (keys.begin() + d == ownIt) continue;
                ++e.domainsBeforeGuard;
                const double fraction = total > 0 ? weight[d] / total : 0.0;
                if (fraction < threshold) {
                    ++droppedSlots_;
                    msg().infof("    node {}: enrichment for side {} dropped (support fraction {:.3e} < {:.1e})",
                                mesh.nodeNames[n], digits(keys[d]), fraction, threshold);
                    continue;
                }
                e.slotDomain.push_back(keys[d]);
                e.slotFraction.push_back(fraction);
                smallestFraction_ = std::min(smallestFraction_, fraction);
            }
            if (e.domainsBeforeGuard > 4)
                throw UserError(
                    fmt::format("node {} is connected to {} regions cut off by the interfaces; at most 4 Heaviside "
                                "enrichments per node are possible (code_aster XFEM_40)",
                                mesh.nodeNames[n], e.domainsBeforeGuard));
            const bool mono = e.activeCracks.size() == 1 && e.slotDomain.size() == 1 && e.own[0] != 0 &&
                              e.slotDomain[0][0] == -e.own[0];
            for (const auto& d : e.slotDomain) e.slotValue.push_back(mono ? 2.0 * d[0] : 2.0);
        }
        nodeIndex_[n] = static_cast<int>(nodes_.size());
        nodes_.push_back(std::move(e));
    }

    // Slots of every element type (nbheav) and slots carried by the nodes (§3.3).
    heavisideCount_.assign(cuts_.size(), 1);
    for (size_t i = 0; i < cuts_.size(); ++i) {
        int count = 1;
        for (int n : mesh.cellNodes(cuts_[i].cell)) count = std::max(count, nodes_[nodeIndex_[n]].domainsBeforeGuard);
        heavisideCount_[i] = count;
        for (int n : mesh.cellNodes(cuts_[i].cell))
            nodes_[nodeIndex_[n]].carried = std::max(nodes_[nodeIndex_[n]].carried, count);
    }
}

std::vector<signed char> XfemModel::domainKeyFor(const std::vector<int>& active, const CellCut& cut, int s) const {
    std::vector<signed char> key;
    key.reserve(active.size());
    for (int c : active) {
        auto it = std::find(cut.cracks.begin(), cut.cracks.end(), c);
        key.push_back(it == cut.cracks.end() ? 0 : cut.subcells[s].heaviside[it - cut.cracks.begin()]);
    }
    return key;
}

signed char XfemModel::nodalDigit(int crack, int node) const {
    const Crack& c = *cracks_[crack];
    for (const auto& m : c.masters) {
        const double v = m.coef * m.crack->lsn[node];
        if ((m.coef > 0 && v >= 0) || (m.coef < 0 && v > 0)) return 0;
    }
    return c.lsn[node] < 0 ? -1 : 1;
}

int XfemModel::nodeSlots(int node) const {
    const auto* e = this->node(node);
    return 1 + (e ? e->carried : 0);
}

bool XfemModel::isEnriched(int cell) const {
    return cell >= 0 && cell < int(cellIndex_.size()) && cellIndex_[cell] >= 0;
}

const CellCut* XfemModel::cut(int cell) const { return isEnriched(cell) ? &cuts_[cellIndex_[cell]] : nullptr; }

const NodeEnrichment* XfemModel::node(int node) const {
    if (node < 0 || node >= int(nodeIndex_.size()) || nodeIndex_[node] < 0) return nullptr;
    return &nodes_[nodeIndex_[node]];
}

int XfemModel::activeSlots(int node) const {
    const auto* e = this->node(node);
    return e ? static_cast<int>(e->slotDomain.size()) : 0;
}

std::vector<signed char> XfemModel::domainKey(int node, const CellCut& cut, int subcell) const {
    const auto* e = this->node(node);
    if (!e) return {};
    return domainKeyFor(e->activeCracks, cut, subcell);
}

double XfemModel::psi(int node, int k, const CellCut& cut, int subcell) const {
    const auto* e = this->node(node);
    if (!e || k < 1 || k > static_cast<int>(e->slotDomain.size())) return 0.0;
    return domainKeyFor(e->activeCracks, cut, subcell) == e->slotDomain[k - 1] ? e->slotValue[k - 1] : 0.0;
}

int XfemModel::slotCrack(int node, int k) const {
    const auto* e = this->node(node);
    if (!e || k < 1 || k > static_cast<int>(e->activeCracks.size()) || k > static_cast<int>(e->slotDomain.size()))
        return -1;
    return e->activeCracks[k - 1];
}

int XfemModel::cellHeavisideCount(int cell) const { return isEnriched(cell) ? heavisideCount_[cellIndex_[cell]] : 0; }

int XfemModel::adjacentVolume(int skinCell) const {
    return isEnriched(skinCell) ? skinVolume_[cellIndex_[skinCell]] : -1;
}

int XfemModel::referenceCell(int node) const {
    if (activeSlots(node) == 0) return -1;
    for (int i = nodeCellOffsets_[node]; i < nodeCellOffsets_[node + 1]; ++i)
        if (!cuts_[cellIndex_[nodeCells_[i]]].skin) return nodeCells_[i];
    return -1;
}

SubcellKind XfemModel::subcellKind(int cell) const {
    const CellCut& cut = cuts_[cellIndex_[cell]];
    return SubcellKind{cut.dim, cut.skin, cut.cracks.size() > 1};
}

std::string XfemModel::subcellRule(int cell) const { return xfem::subcellRule(subcellKind(cell), subcellDegree_); }

std::vector<std::pair<int, int>> XfemModel::inactiveSlots() const {
    std::vector<std::pair<int, int>> out;
    for (int n = 0; n < int(nodeIndex_.size()); ++n) {
        if (nodeIndex_[n] < 0) continue;
        const auto& e = nodes_[nodeIndex_[n]];
        for (int k = static_cast<int>(e.slotDomain.size()) + 1; k <= e.carried; ++k) out.emplace_back(n, k);
    }
    return out;
}

std::vector<std::vector<int>> XfemModel::subcellParentNodes(int cell) const {
    std::vector<std::vector<int>> out;
    const CellCut* c = cut(cell);
    if (!c) return out;
    for (const auto& sub : c->subcells) {
        auto& nodes = out.emplace_back();
        for (int v = 0; v < c->vertexCount(); ++v)
            if (const int a = c->points[size_t(sub.vertices[size_t(v)])].parentNode; a >= 0) nodes.push_back(a);
    }
    return out;
}

void XfemModel::integration(int cell, ElementIntegration& out) const {
    if (!isEnriched(cell)) throw InternalError("XfemModel::integration on a classical cell");
    const CellCut& cut = cuts_[cellIndex_[cell]];
    const auto nodes = mesh_->cellNodes(cell);
    const int nn = static_cast<int>(nodes.size());
    const CellType simplex = simplexType(cut.type);
    const QuadratureRule& rule = quadratureRule(simplex, subcellRule(cell));
    const int nsub = static_cast<int>(cut.subcells.size());
    const int np = nsub * rule.size();

    out = ElementIntegration{};
    out.cell = cell;
    out.nodeCount = nn;
    out.refPoints.reserve(np);
    out.refWeights.reserve(np);
    out.pointSubcell.reserve(np);
    out.slots.resize(nn);
    int maxSlots = 1;
    for (int a = 0; a < nn; ++a) {
        out.slots[a] = 1 + activeSlots(nodes[a]);
        maxSlots = std::max(maxSlots, out.slots[a]);
    }
    out.maxSlots = maxSlots;
    out.psi.reserve(size_t(nsub) * nn * maxSlots);
    bool hasTip = false;
    for (int a = 0; a < nn && !cut.skin; ++a) hasTip = hasTip || tipNode(nodes[a]);
    // Crack-tip elements of a 2D model with the catalogue's rules: collapsed Gauss rules (the
    // sub-cell rule of an override is kept, code_aster's FPG12 at degree 6).
    const bool tipRule = hasTip && subcellDegree_ == 0;
    const double refMeasure = referenceSimplexMeasure(cut.dim);
    std::vector<double> subPsi(size_t(nn) * maxSlots);
    int p = 0;
    for (int s = 0; s < nsub; ++s) {
        const auto& sub = cut.subcells[s];
        const double ratio = cut.referenceMeasure(s) / refMeasure;
        for (int a = 0; a < nn; ++a) {
            subPsi[size_t(a) * maxSlots] = 1.0;
            for (int k = 1; k < out.slots[a]; ++k) subPsi[size_t(a) * maxSlots + k] = psi(nodes[a], k, cut, s);
        }
        out.psi.insert(out.psi.end(), subPsi.begin(), subPsi.end());
        if (tipRule) {
            const size_t before = out.refPoints.size();
            if (cut.dim == 3) tipSubcellRule3(cut, s, out.refPoints.mut(), out.refWeights.mut());
            else tipSubcellRule(cut, s, out.refPoints.mut(), out.refWeights.mut());
            for (size_t q = before; q < out.refPoints.size(); ++q, ++p) out.pointSubcell.push_back(s);
            continue;
        }
        for (int q = 0; q < rule.size(); ++q, ++p) {
            const auto lambda = barycentric(cut.dim, rule.points[q]);
            std::array<double, 3> xi{0, 0, 0};
            for (int v = 0; v < cut.vertexCount(); ++v)
                for (int j = 0; j < 3; ++j) xi[j] += lambda[v] * cut.points[sub.vertices[v]].ref[j];
            out.refPoints.push_back(xi);
            out.refWeights.push_back(rule.weights[q] * ratio);
            out.pointSubcell.push_back(s);
        }
    }
    if (tipRule) {  // the tip rules' point counts are not known beforehand: drop the growth slack
        out.refPoints.mut().shrink_to_fit();
        out.refWeights.mut().shrink_to_fit();
        out.pointSubcell.mut().shrink_to_fit();
    }
    if (hasTip) addTipFields(cut, out);
    if (cut.skin && !tipNodes_.empty()) {  // flags only: loads on such cells are refused (fe/ExternalForces)
        std::vector<char> flags(size_t(nn), 0);
        for (int a = 0; a < nn; ++a) flags[size_t(a)] = tipNode(nodes[a]);
        if (std::count(flags.begin(), flags.end(), 1) > 0) out.tip = std::move(flags);
    }
}

}  // namespace ma::xfem
