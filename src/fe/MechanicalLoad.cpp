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
    out.insert(out.end(), relations.begin(), relations.end());
}

}  // namespace ma
