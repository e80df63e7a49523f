#include "fe/MechanicalLoad.hpp"

#include <map>

#include "fe/DofNumbering.hpp"
#include "fe/Enrichment.hpp"

namespace ma {

std::vector<double> evaluateAtPoints(const Function& f, const std::vector<std::array<double, 3>>& points, double inst) {
    const size_t n = points.size();
    std::map<std::string, std::vector<double>> columns;
    auto& x = columns["X"];
    auto& y = columns["Y"];
    auto& z = columns["Z"];
    x.resize(n), y.resize(n), z.resize(n);
    for (size_t i = 0; i < n; ++i) x[i] = points[i][0], y[i] = points[i][1], z[i] = points[i][2];
    columns["INST"].assign(n, inst);
    return f.evaluateColumns(columns, n);
}

void MechanicalLoad::appendRelations(double inst, std::vector<LinearRelation>& out) const {
    const Model& m = *model;
    const Mesh& mesh = *m.mesh;
    // Which nodes carry which slots (the numbering knows; cheap compared with a solve).
    const DofNumbering numbering(m);
    for (const auto& request : imposed) {
        if (m.enrichment && m.enrichment->imposeDof(m, request, inst, out)) continue;
        std::vector<int> nodes;
        for (int node : request.nodes)
            if (numbering.dofOf(node, request.component) >= 0) nodes.push_back(node);
        std::vector<double> values(nodes.size(), request.value);
        if (request.function) {
            std::vector<std::array<double, 3>> points(nodes.size());
            for (size_t i = 0; i < nodes.size(); ++i) points[i] = mesh.coords[nodes[i]];
            values = evaluateAtPoints(*request.function, points, inst);
        }
        for (size_t i = 0; i < nodes.size(); ++i) out.push_back({{{nodes[i], request.component, 1.0}}, values[i]});
    }
    appendDirectional(inst, out);
    for (const auto& request : relationRequests) {
        double value = request.value.value;
        if (request.value.function)  // a function of INST (X, Y, Z: the first node's, if it asks)
            value = evaluateAtPoints(*request.value.function, {mesh.coords[request.terms.front().node]}, inst)[0];
        out.push_back({request.terms, value});
    }
    out.insert(out.end(), relations.begin(), relations.end());
}

// DNOR / DTAN on X-FEM enriched nodes (code_aster's xddlim, motcle 'DEPL'): per side of the node,
// sum_c n_c (D_c + H(side) H1_c) = value, i.e. the relations of DX, DY, DZ = 1 on those nodes
// combined with the direction's components. Keyed by node, the value left to the caller.
std::map<int, std::vector<LinearRelation>> MechanicalLoad::enrichedDirectional(const DirectionalDof& request,
                                                                               double inst) const {
    std::map<int, std::vector<LinearRelation>> out;
    const Model& m = *model;
    if (!m.enrichment) return out;
    std::vector<int> nodes;
    std::map<int, std::array<double, 3>> direction;
    for (size_t i = 0; i < request.nodes.size(); ++i)
        if (m.enrichment->nodeSlots(request.nodes[i]) > 1)
            nodes.push_back(request.nodes[i]), direction[request.nodes[i]] = request.direction[i];
    if (nodes.empty()) return out;
    static const char* const kComponents[] = {"DX", "DY", "DZ"};
    for (int c = 0; c < m.dim; ++c) {
        ImposedDof one;
        one.path = request.path, one.nodes = nodes, one.component = kComponents[c], one.value = 1.0;
        std::vector<LinearRelation> rel;
        if (!m.enrichment->imposeDof(m, one, inst, rel)) continue;
        std::map<int, size_t> seen;  // k-th relation of a node: its k-th side
        for (const LinearRelation& r : rel) {
            const int node = r.terms.front().node;
            auto& list = out[node];
            const size_t k = seen[node]++;
            if (list.size() <= k) list.emplace_back();
            for (const DofTerm& t : r.terms)
                if (direction[node][size_t(c)] != 0.0)
                    list[k].terms.push_back({t.node, t.component, t.coef * direction[node][size_t(c)]});
        }
    }
    return out;
}

void MechanicalLoad::appendDirectional(double inst, std::vector<LinearRelation>& out) const {
    const Mesh& mesh = *model->mesh;
    static const char* const kComponents[] = {"DX", "DY", "DZ"};
    for (const auto& request : directional) {
        std::vector<double> values(request.nodes.size(), request.value.value);
        if (request.value.function) {
            std::vector<std::array<double, 3>> points;
            for (int n : request.nodes) points.push_back(mesh.coords[n]);
            values = evaluateAtPoints(*request.value.function, points, inst);
        }
        const auto enriched = enrichedDirectional(request, inst);
        for (size_t i = 0; i < request.nodes.size(); ++i) {
            if (const auto it = enriched.find(request.nodes[i]); it != enriched.end()) {
                for (LinearRelation r : it->second) out.push_back({std::move(r.terms), values[i]});
                continue;
            }
            LinearRelation r;
            for (int c = 0; c < model->dim; ++c)
                if (request.direction[i][c] != 0.0)
                    r.terms.push_back({request.nodes[i], kComponents[c], request.direction[i][c]});
            r.value = values[i];
            out.push_back(std::move(r));
        }
    }
}

}  // namespace ma
