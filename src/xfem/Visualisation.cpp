#include "xfem/Visualisation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <span>

#include "core/Error.hpp"
#include "fe/ElasticityKernels.hpp"
#include "fe/Quadrature.hpp"
#include "mesh/ElementGeometry.hpp"
#include "mesh/ShapeFunctions.hpp"
#include "xfem/CellGeometry.hpp"
#include "xfem/XfemModel.hpp"

namespace ma::xfem {

namespace {

std::vector<std::array<double, 3>> nodeCoords(const Mesh& mesh, int cell) {
    std::vector<std::array<double, 3>> x;
    for (int n : mesh.cellNodes(cell)) x.push_back(mesh.coords[n]);
    return x;
}

// Level set of local crack j at a point for naming: a branch's value on the forbidden side of a
// master is replaced by 1 (xpolsn).
double namingLevelSet(const CellCut& cut, const CutPoint& p, size_t j) {
    const Crack& c = *cut.lsnCracks[j];
    for (const auto& m : c.masters) {
        const auto it = std::find(cut.lsnCracks.begin(), cut.lsnCracks.end(), m.crack.get());
        if (it == cut.lsnCracks.end()) continue;
        if (m.coef * p.lsn[it - cut.lsnCracks.begin()] > 0) return 1.0;
    }
    return p.lsn[j];
}

// Counter strings that would make a node name contain another prefix (e.g. NM + "NP" = "NMNP",
// which CALC_TABLE FILTRE REGEXP 'NP' would take for an upper-lip node) are skipped.
bool clashes(const std::string& digits, const VisualisationNames& names) {
    const std::string prefixes[] = {names.nodeX, names.nodeMinus, names.nodePlus};
    for (const auto& p : prefixes) {
        const std::string full = p + digits;
        for (const auto& r : prefixes) {
            if (r.empty()) continue;
            for (size_t pos = full.find(r); pos != std::string::npos; pos = full.find(r, pos + 1))
                if (!(pos == 0 && r == p)) return true;
        }
    }
    return false;
}

// Contact pressure at an interface node of the visualisation: the normal stress n.sigma.n of the
// node's own side (sub-cell) at the point, n = the interface normal (level-set gradient), kept
// <= 0 (an open interface carries no pressure). With the consistent contact of src/contact the
// normal stress is continuous across the interface and equals the contact pressure (Nitsche:
// min(P, 0) with a zero gap; penalty: kappa * gap, weakly). NaN when the node is on no interface
// with contact.
template <class Value>
double contactPressure(const XfemModel& xm, const MaterialField& material, Modelisation modelisation,
                       const VisualisationNode& vn, const Value& value) {
    const Mesh& mesh = xm.mesh();
    const CellCut& cut = *xm.cut(vn.parentCell);
    if (cut.skin) return std::nan("");
    const auto& point = cut.points[vn.point];
    const auto& sub = cut.subcells[vn.subcell];
    int crack = -1;
    for (size_t j = 0; j < cut.cracks.size() && crack < 0; ++j)
        if (point.lsn[j] == 0.0 && sub.heaviside[j] != 0) crack = static_cast<int>(j);
    if (crack < 0) return std::nan("");
    const auto nodes = mesh.cellNodes(vn.parentCell);
    const int n = static_cast<int>(nodes.size());
    const int dim = xm.dim();
    std::array<double, 8> N{};
    std::array<double, 24> dN{};
    shapeValues(cut.type, point.ref, N);
    shapeDerivatives(cut.type, point.ref, dN);
    // Jacobian and physical gradients.
    double J[3][3] = {}, inv[3][3] = {};
    auto X = [&](int a) -> const Vec3& { return mesh.coords[nodes[a]]; };
    auto d = [&](int a, int k) { return dN[3 * a + k]; };
    jacobian(dim, dim, n, X, d, J);
    invertJacobian(dim, J, inv);
    // du_c/dx_j of the node's side and the interface normal (level-set gradient).
    double G[3][3] = {};
    std::array<double, 3> normal{};
    const Crack& c = *cut.lsnCracks[crack];
    for (int a = 0; a < n; ++a) {
        double g[3] = {};
        physicalGradient(
            dim, inv, [&](int k) { return dN[3 * a + k]; }, g);
        for (int j = 0; j < dim; ++j) normal[j] += c.lsn[nodes[a]] * g[j];
        for (int k = 0; k <= xm.activeSlots(nodes[a]); ++k) {
            const double psi = k == 0 ? 1.0 : xm.psi(nodes[a], k, cut, vn.subcell);
            if (psi == 0.0) continue;
            for (int comp = 0; comp < dim; ++comp)
                for (int j = 0; j < dim; ++j) G[comp][j] += psi * value(nodes[a], k, comp) * g[j];
        }
    }
    const double len = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    if (len == 0.0) return std::nan("");
    for (auto& v : normal) v /= len;
    const Material& mat = material.at(vn.parentCell);
    const IsotropicLaw law = IsotropicLaw::from(mat, modelisation, mat.name);
    double tr = 0.0, nGn = 0.0;
    for (int j = 0; j < dim; ++j) tr += G[j][j];
    for (int i = 0; i < dim; ++i)
        for (int j = 0; j < dim; ++j) nGn += normal[i] * G[i][j] * normal[j];
    return std::min(law.lambdaEff * tr + 2.0 * law.mu * nGn, 0.0);
}

// The model's cells that are drawn (volume and skin, not POI1), in cell order.
std::vector<int> visualisedCells(const Model& model, const Mesh& mesh) {
    std::vector<int> modelCells;
    for (const auto& e : model.elements) modelCells.push_back(e.cell);
    for (const auto& e : model.skinElements) modelCells.push_back(e.cell);
    std::sort(modelCells.begin(), modelCells.end());
    modelCells.erase(std::unique(modelCells.begin(), modelCells.end()), modelCells.end());
    modelCells.erase(std::remove_if(modelCells.begin(), modelCells.end(),
                                    [&](int c) { return mesh.cellTypes[c] == CellType::POI1; }),
                     modelCells.end());
    return modelCells;
}

// Classical cells: their nodes first, in original order, then the cells.
void addClassicalCells(const Mesh& mesh, const XfemModel& xm, const std::vector<int>& modelCells, Visualisation& out,
                       std::vector<std::pair<int, int>>& cellMap) {
    Mesh& vm = *out.mesh;
    std::vector<int> nodeMap(mesh.nodeCount(), -1);
    std::vector<char> used(mesh.nodeCount(), 0);
    for (int c : modelCells)
        if (!xm.isEnriched(c))
            for (int n : mesh.cellNodes(c)) used[n] = 1;
    const size_t usedCount = size_t(std::count(used.begin(), used.end(), 1));
    vm.coords.reserve(usedCount), vm.nodeNames.reserve(usedCount), out.nodes.reserve(usedCount);
    vm.cellTypes.reserve(modelCells.size()), vm.cellNames.reserve(modelCells.size());
    vm.cellOffsets.reserve(modelCells.size() + 1), out.cells.reserve(modelCells.size());
    for (int n = 0; n < mesh.nodeCount(); ++n)
        if (used[n]) {
            nodeMap[n] = vm.addNode(mesh.coords[n], mesh.nodeNames[n]);
            out.nodes.push_back({n, -1, -1, -1, false});
        }
    for (int c : modelCells) {
        if (xm.isEnriched(c)) continue;
        const auto cn = mesh.cellNodes(c);
        std::array<int, 27> nodes{};
        for (size_t a = 0; a < cn.size(); ++a) nodes[a] = nodeMap[cn[a]];
        const int id = vm.addCell(mesh.cellTypes[c], std::span<const int>(nodes.data(), cn.size()), mesh.cellNames[c]);
        cellMap[c] = {id, id + 1};
        out.cells.push_back({c, -1, -1});
    }
}

// Name prefix of a node on an interface: the lip (side) of the interface closest to the point
// among those the sub-cell has a side of.
const std::string& lipPrefix(const CellCut& cut, const SubCell& sub, const CutPoint& p,
                             const VisualisationNames& names) {
    int best = -1;
    double bestValue = std::numeric_limits<double>::infinity();
    for (size_t j = 0; j < cut.cracks.size(); ++j) {
        if (sub.heaviside[j] == 0) continue;
        const double value = std::abs(namingLevelSet(cut, p, j));
        if (value < bestValue) bestValue = value, best = static_cast<int>(j);
    }
    if (best < 0) return names.nodeX;
    return sub.heaviside[best] < 0 ? names.nodeMinus : names.nodePlus;
}

// Sub-cells are positive in the parent's reference coordinates; keep them positive in physical
// ones (a parent with a negative Jacobian flips them).
void keepPositive(const CellCut& cut, int meshDim, const Mesh& vm, std::vector<int>& nodes) {
    if (!((cut.dim == 2 && meshDim == 2) || cut.dim == 3)) return;
    std::array<std::array<double, 3>, 4> pv{};
    for (int v = 0; v < cut.vertexCount(); ++v) pv[v] = vm.coords[nodes[v]];
    const auto span = std::span<const std::array<double, 3>>(pv.data(), cut.vertexCount());
    if (simplexMeasure(cut.dim, span) < 0) std::swap(nodes[0], nodes[1]);
}

}  // namespace

std::string base36(long long value) {
    static const char* digits = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ";
    if (value <= 0) return "0";
    std::string s;
    while (value > 0) s.insert(s.begin(), digits[value % 36]), value /= 36;
    return s;
}

Visualisation buildVisualisation(const Model& model, const XfemModel& xm, const VisualisationNames& names) {
    const Mesh& mesh = xm.mesh();
    Visualisation out;
    out.mesh = std::make_shared<Mesh>();
    Mesh& vm = *out.mesh;
    vm.dim = mesh.dim;

    const std::vector<int> modelCells = visualisedCells(model, mesh);
    // Cells of the visualisation mesh made from each cell: a contiguous range [first, last).
    std::vector<std::pair<int, int>> cellMap(mesh.cellCount(), {0, 0});
    addClassicalCells(mesh, xm, modelCells, out, cellMap);

    // X-FEM cells: sub-cells, with nodes per (vertex, side) and per parent cell.
    long long nodeCounter = 0, cellCounter = 0;
    std::vector<int> crackNodes;
    for (int c : modelCells) {
        const CellCut* cut = xm.cut(c);
        if (!cut) continue;
        const auto xs = nodeCoords(mesh, c);
        std::map<std::pair<int, std::vector<signed char>>, int> made;
        const CellType simplex = simplexType(cut->type);
        for (int s = 0; s < static_cast<int>(cut->subcells.size()); ++s) {
            const SubCell& sub = cut->subcells[s];
            std::vector<int> nodes;
            for (int v = 0; v < cut->vertexCount(); ++v) {
                const int pid = sub.vertices[v];
                auto key = std::make_pair(pid, sub.heaviside);
                auto it = made.find(key);
                if (it != made.end()) {
                    nodes.push_back(it->second);
                    continue;
                }
                const CutPoint& p = cut->points[pid];
                bool onCrack = p.parentNode < 0;
                for (size_t j = 0; j < cut->cracks.size() && !onCrack; ++j) onCrack = namingLevelSet(*cut, p, j) == 0.0;
                const std::string& prefix = onCrack ? lipPrefix(*cut, sub, p, names) : names.nodeX;
                const auto x = mapToPhysical(cut->type, xs, p.ref);
                std::string digits = base36(++nodeCounter);
                while (clashes(digits, names)) digits = base36(++nodeCounter);
                const int id = vm.addNode(x, prefix + digits);
                out.nodes.push_back({-1, c, pid, s, onCrack});
                if (onCrack) crackNodes.push_back(id);
                made.emplace(std::move(key), id);
                nodes.push_back(id);
            }
            keepPositive(*cut, mesh.dim, vm, nodes);
            const int id = vm.addCell(simplex, nodes, names.cellX + std::to_string(++cellCounter));
            cellMap[c] = {s == 0 ? id : cellMap[c].first, id + 1};
            out.cells.push_back({-1, c, s});
        }
    }
    if (cellCounter > 999999)
        throw UserError("POST_MAIL_XFEM: more than 999999 sub-cells; the MX names would overflow");

    for (const auto& g : mesh.cellGroups.names()) {
        std::vector<int> members;
        for (int c : mesh.cellGroups.get(g))
            for (int id = cellMap[c].first; id < cellMap[c].second; ++id) members.push_back(id);
        if (!members.empty()) vm.cellGroups.set(g, std::move(members));
    }
    if (!crackNodes.empty()) vm.nodeGroups.set(names.crackGroup, crackNodes);
    return out;
}

namespace {

// DEPL on the visualisation mesh: each new node takes the displacement of its side of the
// interface in its parent cell (all active Heaviside slots); contact models add LAGS_C.
std::shared_ptr<NodalField> visualisationDisplacement(const XfemModel* xm, const Model& model,
                                                      const Visualisation& visu, const std::shared_ptr<Mesh>& vmesh,
                                                      const NodalField* depl, const std::vector<std::string>& comps,
                                                      const Result& input, bool withContact) {
    const Mesh& mesh = xm->mesh();
    const int dim = model.dim;
    std::array<double, 8> N{};
    auto field = std::make_shared<NodalField>();
    field->resize(vmesh, comps);
    // (slot, component) -> column of the input field
    const int maxSlot = 5;
    std::vector<int> column(maxSlot * 3, -1);
    for (int k = 0; k < maxSlot; ++k)
        for (int j = 0; j < dim; ++j)
            column[k * 3 + j] = depl->componentIndex(k == 0 ? comps[j] : fmt::format("H{}{}", k, "XYZ"[j]));
    auto value = [&](int node, int k, int j) {
        const int col = k < maxSlot ? column[k * 3 + j] : -1;
        return col >= 0 && depl->has(node, col) ? depl->at(node, col) : 0.0;
    };
    std::array<int, 3> tipColumn{-1, -1, -1};  // K1, K2[, K3]
    for (int m = 0; m < dim; ++m) tipColumn[size_t(m)] = depl->componentIndex(fmt::format("K{}", m + 1));
    // u += N_a Phi K_a over the tip nodes of the parent cell (docs/cracks.md).
    auto addTip = [&](const VisualisationNode& vn, std::array<double, 3>& u) {
        if (xm->tipCrack() < 0 || tipColumn[0] < 0) return;
        if (!input.material)
            throw UserError("the result has no material: the crack-tip terms of its displacement need it");
        const Material& mat = input.material->at(vn.parentCell);
        const IsotropicLaw law = IsotropicLaw::from(mat, model.modelisation, mat.name);
        XfemModel::TipPoint at;
        const CellCut& cut = *xm->cut(vn.parentCell);
        if (!xm->tipMatrix(vn.parentCell, vn.subcell, cut.points[size_t(vn.point)].ref, law.lambdaEff, law.mu, at))
            return;
        const auto cn = mesh.cellNodes(at.cell);
        std::array<double, 8> Na{};
        shapeValues(mesh.cellTypes[size_t(at.cell)], at.ref, std::span<double>(Na.data(), cn.size()));
        for (size_t a = 0; a < cn.size(); ++a) {
            if (!xm->tipNode(cn[a])) continue;
            for (int m = 0; m < dim; ++m) {
                const int col = tipColumn[size_t(m)];
                const double K = col >= 0 && depl->has(cn[a], col) ? depl->at(cn[a], col) : 0.0;
                for (int j = 0; j < dim; ++j) u[size_t(j)] += Na[a] * at.Phi[a][j * 3 + m] * K;
            }
        }
    };
    for (int v = 0; v < vmesh->nodeCount(); ++v) {
        const auto& vn = visu.nodes[v];
        std::array<double, 3> u{0, 0, 0};
        if (vn.original >= 0) {
            for (int j = 0; j < dim; ++j) u[j] = value(vn.original, 0, j);
        } else {
            const CellCut& cut = *xm->cut(vn.parentCell);
            const auto cn = mesh.cellNodes(vn.parentCell);
            shapeValues(cut.type, cut.points[vn.point].ref, N);
            for (size_t a = 0; a < cn.size(); ++a) {
                if (N[a] == 0.0) continue;
                for (int j = 0; j < dim; ++j) u[j] += N[a] * value(cn[a], 0, j);
                for (int k = 1; k <= xm->activeSlots(cn[a]); ++k) {
                    const double psi = xm->psi(cn[a], k, cut, vn.subcell);
                    if (psi == 0.0) continue;
                    for (int j = 0; j < dim; ++j) u[j] += N[a] * psi * value(cn[a], k, j);
                }
            }
            addTip(vn, u);
        }
        for (int j = 0; j < dim; ++j) field->set(v, j, u[j]);
        if (withContact && vn.onCrack && vn.original < 0) {
            const double lagsC = contactPressure(*xm, *input.material, model.modelisation, vn, value);
            if (!std::isnan(lagsC)) {
                field->set(v, dim, lagsC);
                // Frictionless: the tangential multipliers are zero where LAGS_C is defined.
                for (int f = 1; f < dim; ++f) field->set(v, dim + f, 0.0);
            }
        }
    }
    return field;
}

// SIEF_ELGA on the visualisation mesh: classical elements keep their points; a sub-cell element
// takes the mean of its parent's points of that sub-cell at each of its own points.
std::shared_ptr<GaussField> visualisationStress(const XfemModel* xm, const Visualisation& visu,
                                                const std::shared_ptr<Mesh>& vmesh, const Model& modelVisu,
                                                const GaussField* sief) {
    const Mesh& mesh = xm->mesh();
    auto field = std::make_shared<GaussField>();
    field->mesh = vmesh;
    field->quantity = sief->quantity;
    field->components = sief->components;
    const size_t nc = sief->components.size();
    std::vector<int> elementOf(size_t(mesh.cellCount()), -1);  // input cell -> element of the input field
    for (size_t e = 0; e < sief->cells.size(); ++e)
        if (sief->cells[e] >= 0 && sief->cells[e] < mesh.cellCount())
            elementOf[size_t(sief->cells[e])] = static_cast<int>(e);
    const size_t reserve = sief->pointWeights.size() + sief->pointWeights.size() / 8;
    field->cells.reserve(modelVisu.elements.size());
    field->pointOffsets.reserve(modelVisu.elements.size() + 1);
    field->pointCoords.reserve(reserve);
    field->pointWeights.reserve(reserve);
    field->pointSubcell.reserve(reserve);
    field->pointRefCoords.reserve(reserve);
    field->values.reserve(reserve * nc);
    for (const auto& el : modelVisu.elements) {
        const int vc = el.cell;
        const auto& info = visu.cells[vc];
        const int parent = info.original >= 0 ? info.original : info.parentCell;
        const int e = parent >= 0 && parent < mesh.cellCount() ? elementOf[size_t(parent)] : -1;
        if (e < 0) continue;
        const int p0 = sief->pointOffsets[e], p1 = sief->pointOffsets[e + 1];
        field->cells.push_back(vc);
        if (info.original >= 0) {  // classical element: same points
            for (int p = p0; p < p1; ++p) {
                field->pointCoords.push_back(sief->pointCoords[p]);
                field->pointWeights.push_back(sief->pointWeights[p]);
                field->pointSubcell.push_back(0);
                field->pointRefCoords.push_back(p < int(sief->pointRefCoords.size()) ? sief->pointRefCoords[p]
                                                                                     : std::array<double, 3>{});
                field->values.insert(field->values.end(), sief->values.begin() + size_t(p) * nc,
                                     sief->values.begin() + size_t(p + 1) * nc);
            }
        } else {  // sub-cell: mean of the parent's points of that sub-cell, at every point
            std::vector<double> mean(nc, 0.0);
            int count = 0;
            for (int p = p0; p < p1; ++p)
                if (sief->pointSubcell[p] == info.subcell) {
                    ++count;
                    for (size_t j = 0; j < nc; ++j) mean[j] += sief->values[size_t(p) * nc + j];
                }
            for (auto& m : mean) m = count ? m / count : 0.0;
            const CellType type = vmesh->cellTypes[vc];
            const QuadratureRule& rule = stiffnessRule(type);
            const auto xs = nodeCoords(*vmesh, vc);
            std::vector<std::array<double, 3>> corners(xs.begin(), xs.end());
            const double measure = std::abs(simplexMeasure(cellDimension(type), corners));
            const double refMeasure = cellDimension(type) == 2 ? 0.5 : 1.0 / 6.0;
            for (int q = 0; q < rule.size(); ++q) {
                field->pointCoords.push_back(mapToPhysical(type, xs, rule.points[q]));
                field->pointWeights.push_back(rule.weights[q] * measure / refMeasure);
                field->pointSubcell.push_back(0);
                field->pointRefCoords.push_back(rule.points[q]);
                field->values.insert(field->values.end(), mean.begin(), mean.end());
            }
        }
        field->pointOffsets.push_back(static_cast<int>(field->pointWeights.size()));
    }
    return field;
}

}  // namespace

std::shared_ptr<Result> visualisationResult(const Result& input, const std::shared_ptr<Model>& modelVisu) {
    if (!input.model) throw UserError("RESULTAT " + input.name + " has no model");
    const Model& model = *input.model;
    const auto* xm = dynamic_cast<const XfemModel*>(model.enrichment.get());
    if (!xm) throw UserError("RESULTAT " + input.name + " was not computed on an X-FEM model (MODI_MODELE_XFEM)");
    if (modelVisu->enrichment)
        throw UserError(
            "MODELE_VISU must be a classical model built on the POST_MAIL_XFEM mesh, not an X-FEM "
            "model (code_aster XFEM2_30)");
    const Visualisation visu = buildVisualisation(model, *xm);
    const auto& vmesh = modelVisu->mesh;
    if (!vmesh || vmesh->nodeCount() != visu.mesh->nodeCount() || vmesh->cellCount() != visu.mesh->cellCount())
        throw UserError(
            fmt::format("MODELE_VISU {} is not built on the POST_MAIL_XFEM mesh of the model {} of "
                        "RESULTAT {} ({} nodes and {} cells expected)",
                        modelVisu->name, model.name, input.name, visu.mesh->nodeCount(), visu.mesh->cellCount()));
    const int dim = model.dim;
    auto out = std::make_shared<Result>(input.typeName());
    out->mesh = vmesh;
    out->model = modelVisu;

    std::vector<std::string> comps =
        dim == 3 ? std::vector<std::string>{"DX", "DY", "DZ"} : std::vector<std::string>{"DX", "DY"};
    // Contact models: the contact pressure LAGS_C (<= 0 in compression, code_aster's sign) at the
    // interface nodes, after the displacement components, and the friction multipliers LAGS_F1
    // [, LAGS_F2] as code_aster's contact elements carry them (0: no friction; docs/contact.md).
    const bool withContact = xm->contact() == XfemContact::Standard && input.material;
    if (withContact) comps.push_back("LAGS_C");
    if (withContact) comps.push_back("LAGS_F1");
    if (withContact && dim == 3) comps.push_back("LAGS_F2");
    for (const auto& step : input.steps) {
        ResultStep s;
        s.order = step.order;
        s.inst = step.inst;
        if (auto depl = step.nodal("DEPL"))
            s.nodalFields.emplace_back("DEPL", visualisationDisplacement(xm, model, visu, vmesh, depl.get(), comps,
                                                                         input, withContact));
        if (auto sief = step.gauss("SIEF_ELGA"))
            s.gaussFields.emplace_back("SIEF_ELGA", visualisationStress(xm, visu, vmesh, *modelVisu, sief.get()));
        out->steps.push_back(std::move(s));
    }
    return out;
}

}  // namespace ma::xfem
