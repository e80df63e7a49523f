#include "commands/RelationLoads.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "commands/MechanicsKeywords.hpp"
#include "core/Messages.hpp"
#include "core/Vec3.hpp"
#include "fe/DofNumbering.hpp"
#include "fe/Enrichment.hpp"
#include "mesh/ElementGeometry.hpp"
#include "mesh/ShapeFunctions.hpp"

namespace ma::mechanics {

namespace {

LoadValue readValue(const KeywordSet& occ, const std::string& key, bool functions) {
    LoadValue v;
    if (functions) v.function = occ.object<Function>(key);
    else v.value = occ.real(key);
    return v;
}

std::vector<int> cellsOf(const Mesh& mesh, const KeywordSet& occ, const std::string& groups, const std::string& cells) {
    KeywordSet sel(occ.path());
    if (occ.has(groups)) sel.setValues("GROUP_MA", occ.values(groups));
    if (occ.has(cells)) sel.setValues("MAILLE", occ.values(cells));
    return selectedCells(mesh, sel);
}

// Nodes named by GROUP_NO/NOEUD-like keywords, in the order given (groups in their own order).
std::vector<int> nodesInOrder(const Mesh& mesh, const KeywordSet& occ, const std::string& groups,
                              const std::string& nodes) {
    std::vector<int> out;
    if (occ.has(groups))
        for (const auto& g : occ.texts(groups)) {
            const auto& members = namedGroup(mesh, GroupKind::Nodes, g, occ.pathOf(groups));
            out.insert(out.end(), members.begin(), members.end());
        }
    if (occ.has(nodes))
        for (const auto& n : occ.texts(nodes)) {
            const int i = mesh.findNode(n);
            if (i < 0)
                throw UserError(fmt::format("{}: the mesh {} has no node '{}'", occ.pathOf(nodes), mesh.name, n));
            out.push_back(i);
        }
    return out;
}

void removeExcluded(const Mesh& mesh, const KeywordSet& occ, std::vector<int>& nodes) {
    std::vector<int> excluded;
    for (const auto& [g, c] : {std::pair<const char*, const char*>{"SANS_GROUP_MA", "SANS_MAILLE"}})
        if (occ.has(g) || occ.has(c))
            for (int cell : cellsOf(mesh, occ, g, c))
                for (int n : mesh.cellNodes(cell)) excluded.push_back(n);
    for (int n : nodesInOrder(mesh, occ, "SANS_GROUP_NO", "SANS_NOEUD")) excluded.push_back(n);
    std::sort(excluded.begin(), excluded.end());
    std::erase_if(nodes, [&](int n) { return std::binary_search(excluded.begin(), excluded.end(), n); });
}

// A displacement component of the model (DX, DY[, DZ], HkX ...) or a UserError.
void checkComponent(const Model& model, const std::string& path, const std::string& name) {
    int slot = 0, comp = 0;
    if (!parseDisplacementComponent(name, slot, comp) || comp >= model.dim)
        throw UserError(fmt::format("{}: '{}' is not a displacement component of the {} model {}", path, name,
                                    modelisationName(model.modelisation), model.name));
}

// Unit normal (DNOR) or tangent (DTAN) at each node, averaged over the cells around it (code_aster's
// canort): the node-order normal of a face or plane edge, the node-order tangent of an edge.
std::map<int, Vec3> nodeDirections(const Mesh& mesh, const std::vector<int>& cells, int dim, bool tangent,
                                   const std::string& path) {
    std::map<int, Vec3> sum;
    for (int c : cells) {
        const CellType type = mesh.cellTypes[size_t(c)];
        const int rdim = referenceDimension(type);
        if (rdim != (tangent ? 1 : dim - 1))
            throw UserError(fmt::format("{}: cell {} is a {}: {} needs {}", path, mesh.cellNames[size_t(c)],
                                        cellTypeName(type), tangent ? "DTAN" : "DNOR",
                                        tangent ? "edges (SEG2)" : (dim == 2 ? "edges (SEG2)" : "faces")));
        const auto nodes = mesh.cellNodes(c);
        std::vector<Vec3> xyz;
        for (int n : nodes) xyz.push_back(mesh.coords[size_t(n)]);
        const auto ref = referenceNodes(type);
        for (size_t a = 0; a < nodes.size(); ++a) {
            std::array<double, 24> dN{};
            shapeDerivatives(type, ref[a], dN);
            double J[3][3] = {};
            jacobian(xyz, std::span<const double>(dN.data(), nodes.size() * 3), rdim, J);
            Vec3 d = tangent ? Vec3{J[0][0], J[1][0], J[2][0]} : boundaryNormal(J, rdim);
            const double len = norm(d);
            if (!(len > 0.0))
                throw UserError(fmt::format("{}: cell {} is degenerate", path, mesh.cellNames[size_t(c)]));
            for (int i = 0; i < 3; ++i) sum[nodes[a]][size_t(i)] += d[size_t(i)] / len;
        }
    }
    for (auto& [n, d] : sum) {
        const double len = norm(d);
        if (!(len > 1e-12))
            throw UserError(fmt::format("{}: the {} at node {} is undefined (opposite cells around it)", path,
                                        tangent ? "tangent" : "normal", mesh.nodeNames[size_t(n)]));
        for (auto& v : d) v /= len;
    }
    return sum;
}

void readImposedOnCells(const KeywordSet& occ, bool functions, bool face, const std::vector<char>& modelNodes,
                        MechanicalLoad& load) {
    const Model& model = *load.model;
    const Mesh& mesh = *model.mesh;
    if (!face && model.dim != 3)
        throw UserError(fmt::format("{}: ARETE_IMPO holds edges of 3D models; the model {} is plane (FACE_IMPO)",
                                    occ.path(), model.name));
    const auto cells = cellsOf(mesh, occ, "GROUP_MA", "MAILLE");
    std::vector<int> nodes;
    for (int c : cells)
        for (int n : mesh.cellNodes(c)) nodes.push_back(n);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    removeExcluded(mesh, occ, nodes);
    for (int n : nodes)
        if (!modelNodes[size_t(n)])
            throw UserError(fmt::format("{}: node {} carries no unknown of the model {}", occ.path(),
                                        mesh.nodeNames[size_t(n)], model.name));
    for (const char* key : {"DX", "DY", "DZ"}) {
        if (!occ.has(key)) continue;
        checkComponent(model, occ.pathOf(key), key);
        ImposedDof d;
        d.path = occ.pathOf(key);
        d.nodes = nodes;
        d.component = key;
        const LoadValue v = readValue(occ, key, functions);
        d.value = v.value;
        d.function = v.function;
        load.imposed.push_back(std::move(d));
    }
    for (const char* key : {"DNOR", "DTAN"}) {
        if (!occ.has(key)) continue;
        const bool tangent = std::string(key) == "DTAN";
        if (tangent && face && model.dim == 3)  // code_aster's CHARGES2_63
            throw UserError(
                fmt::format("{}: the tangential displacement of 3D faces has two directions; use "
                            "DDL_IMPO or LIAISON_DDL",
                            occ.pathOf(key)));
        const bool edgeTangent = tangent && model.dim == 3;
        auto dirs = nodeDirections(mesh, cells, model.dim, edgeTangent, occ.pathOf(key));
        DirectionalDof d;
        d.path = occ.pathOf(key);
        d.value = readValue(occ, key, functions);
        for (int n : nodes) {
            if (model.enrichment && model.enrichment->nodeSlots(n) > 1 && d.value.function)
                throw NotImplemented(
                    fmt::format("{}: node {} is enriched by an interface or a crack; {} given by a function on "
                                "X-FEM enriched nodes is not modelled (a real value is)",
                                occ.pathOf(key), mesh.nodeNames[size_t(n)], key));
            Vec3 dir = dirs.at(n);
            if (tangent && !edgeTangent) dir = {-dir[1], dir[0], 0.0};  // plane: the normal turned by +90 degrees
            d.nodes.push_back(n);
            d.direction.push_back(dir);
        }
        load.directional.push_back(std::move(d));
    }
    msg().infof("    {}: {} node(s) of {} cell(s)", occ.path(), nodes.size(), cells.size());
}

void readLiaisonDdl(const KeywordSet& occ, bool functions, MechanicalLoad& load) {
    const Model& model = *load.model;
    const Mesh& mesh = *model.mesh;
    const auto nodes = nodesInOrder(mesh, occ, "GROUP_NO", "NOEUD");
    const auto dofs = occ.texts("DDL");
    const auto coefs = occ.reals("COEF_MULT");
    if (dofs.size() != nodes.size() || coefs.size() != nodes.size())
        throw UserError(fmt::format("{}: {} node(s), {} DDL and {} COEF_MULT: one of each per node", occ.path(),
                                    nodes.size(), dofs.size(), coefs.size()));
    const DofNumbering numbering(model);
    RelationRequest r;
    r.path = occ.path();
    for (size_t i = 0; i < nodes.size(); ++i) {
        checkComponent(model, occ.pathOf("DDL"), dofs[i]);
        if (numbering.dofOf(nodes[i], dofs[i]) < 0)
            throw UserError(fmt::format("{}: node {} has no unknown {} in the model {}", occ.path(),
                                        mesh.nodeNames[size_t(nodes[i])], dofs[i], model.name));
        r.terms.push_back({nodes[i], dofs[i], coefs[i]});
    }
    r.value = readValue(occ, "COEF_IMPO", functions);
    msg().infof("    {}: a relation of {} term(s)", occ.path(), r.terms.size());
    load.relationRequests.push_back(std::move(r));
}

std::vector<int> groupNodes(const Mesh& mesh, const KeywordSet& occ, const std::string& suffix) {
    std::vector<int> nodes = nodesInOrder(mesh, occ, "GROUP_NO" + suffix, "NOEUD" + suffix);
    if (occ.has("GROUP_MA" + suffix) || occ.has("MAILLE" + suffix))
        for (int c : cellsOf(mesh, occ, "GROUP_MA" + suffix, "MAILLE" + suffix))
            for (int n : mesh.cellNodes(c)) nodes.push_back(n);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    removeExcluded(mesh, occ, nodes);
    return nodes;
}

// Nearest node of `candidates` to x.
int nearest(const Mesh& mesh, const std::vector<int>& candidates, const Vec3& x) {
    int best = -1;
    double bestDistance = 0.0;
    for (int n : candidates) {
        const double d = distance(mesh.coords[size_t(n)], x);
        if (best < 0 || d < bestDistance) best = n, bestDistance = d;
    }
    return best;
}

void readLiaisonGroup(const KeywordSet& occ, bool functions, MechanicalLoad& load) {
    const Model& model = *load.model;
    const Mesh& mesh = *model.mesh;
    auto first = groupNodes(mesh, occ, "_1");
    auto second = groupNodes(mesh, occ, "_2");
    // A node in both lists would be related to itself (code_aster drops it too).
    std::vector<int> common;
    std::set_intersection(first.begin(), first.end(), second.begin(), second.end(), std::back_inserter(common));
    for (auto* list : {&first, &second})
        std::erase_if(*list, [&](int n) { return std::binary_search(common.begin(), common.end(), n); });
    if (first.size() != second.size() || first.empty())
        throw UserError(
            fmt::format("{}: {} node(s) on side 1 and {} on side 2 (nodes on both sides left out): "
                        "the sides must face each other node by node",
                        occ.path(), first.size(), second.size()));
    Vec3 shift{};
    if (occ.has("TRAN")) {
        const auto t = occ.reals("TRAN");
        for (size_t i = 0; i < std::min<size_t>(3, t.size()); ++i) shift[i] = t[i];
    }
    const auto dofs1 = occ.texts("DDL_1"), dofs2 = occ.texts("DDL_2");
    const auto coefs1 = occ.reals("COEF_MULT_1"), coefs2 = occ.reals("COEF_MULT_2");
    if (dofs1.size() != coefs1.size() || dofs2.size() != coefs2.size())
        throw UserError(
            fmt::format("{}: DDL_1/COEF_MULT_1 and DDL_2/COEF_MULT_2 must have the same lengths", occ.path()));
    for (const auto& d : dofs1) checkComponent(model, occ.pathOf("DDL_1"), d);
    for (const auto& d : dofs2) checkComponent(model, occ.pathOf("DDL_2"), d);
    const LoadValue value = readValue(occ, "COEF_IMPO", functions);
    std::vector<int> partnerOfSecond(size_t(mesh.nodeCount()), -1);
    for (int n1 : first) {
        const Vec3 target = {mesh.coords[size_t(n1)][0] + shift[0], mesh.coords[size_t(n1)][1] + shift[1],
                             mesh.coords[size_t(n1)][2] + shift[2]};
        const int n2 = nearest(mesh, second, target);
        if (partnerOfSecond[size_t(n2)] >= 0)
            throw UserError(fmt::format("{}: nodes {} and {} of side 1 both face node {} of side 2", occ.path(),
                                        mesh.nodeNames[size_t(partnerOfSecond[size_t(n2)])], mesh.nodeNames[size_t(n1)],
                                        mesh.nodeNames[size_t(n2)]));
        partnerOfSecond[size_t(n2)] = n1;
        RelationRequest r;
        r.path = occ.path();
        for (size_t i = 0; i < dofs1.size(); ++i) r.terms.push_back({n1, dofs1[i], coefs1[i]});
        for (size_t i = 0; i < dofs2.size(); ++i) r.terms.push_back({n2, dofs2[i], coefs2[i]});
        r.value = value;
        load.relationRequests.push_back(std::move(r));
    }
    msg().infof("    {}: {} pair(s) of nodes{}", occ.path(), first.size(),
                common.empty() ? "" : fmt::format(" ({} node(s) on both sides left out)", common.size()));
}

}  // namespace

void readRelationLoads(const KeywordSet& kw, bool functions, const std::vector<char>& modelNodes,
                       MechanicalLoad& load) {
    for (const auto& occ : kw.factor("FACE_IMPO")) readImposedOnCells(occ, functions, true, modelNodes, load);
    for (const auto& occ : kw.factor("ARETE_IMPO")) readImposedOnCells(occ, functions, false, modelNodes, load);
    for (const auto& occ : kw.factor("LIAISON_DDL")) readLiaisonDdl(occ, functions, load);
    for (const auto& occ : kw.factor("LIAISON_GROUP")) readLiaisonGroup(occ, functions, load);
}

}  // namespace ma::mechanics
