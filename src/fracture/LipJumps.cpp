#include "fracture/LipJumps.hpp"

#include <span>

#include "mesh/PointLocation.hpp"
#include "mesh/ShapeFunctions.hpp"

namespace ma::fracture {

namespace {

// code_aster's projection of a nodal component at a point of a cell (PROJ_CHAMP COLLOCATION, which
// MACR_LIGN_COUPE uses: cnsprj): all the cell's nodes when all carry it; otherwise only those that
// carry it with a positive shape function, renormalised by the sum of their shape functions; when
// none of those, the carriers' arithmetic mean; when no node carries it, no value (post_k1_k2_k3
// then takes 0). H1 is carried by the Heaviside nodes only, so near the front the renormalisation
// extrapolates the jump of the nodes behind it instead of tapering it to zero.
double projectedComponent(const NodalField& depl, int component, std::span<const int> nodes,
                          const std::vector<double>& N) {
    if (component < 0) return 0.0;
    int carriers = 0, positive = 0;
    double all = 0.0, weighted = 0.0, weights = 0.0, mean = 0.0;
    for (size_t a = 0; a < nodes.size(); ++a) {
        if (!depl.has(nodes[a], component)) continue;
        const double v = depl.at(nodes[a], component);
        ++carriers, mean += v, all += N[a] * v;
        if (N[a] > 0) ++positive, weighted += N[a] * v, weights += N[a];
    }
    if (carriers == 0) return 0.0;
    if (size_t(carriers) == nodes.size()) return all;
    return positive > 0 ? weighted / weights : mean / carriers;
}

}  // namespace

LipSamples heavisideJumps(const Mesh& mesh, const NodalField& depl, const Vec3& front, const Vec3& direction,
                          double length, int points) {
    const int comps[3] = {depl.componentIndex("H1X"), depl.componentIndex("H1Y"), depl.componentIndex("H1Z")};
    LipSamples out;
    std::vector<double> N;
    for (int i = 0; i < points; ++i) {
        const double s = length * i / (points - 1);
        const Vec3 x{front[0] - s * direction[0], front[1] - s * direction[1], front[2] - s * direction[2]};
        const PointInCell at = locatePoint(mesh, x);
        if (at.cell < 0) continue;
        const auto nodes = mesh.cellNodes(at.cell);
        N.assign(nodes.size(), 0.0);
        shapeValues(mesh.cellTypes[size_t(at.cell)], at.xi, N);
        Vec3 jump{};
        for (int c = 0; c < 3; ++c) jump[size_t(c)] = 2 * projectedComponent(depl, comps[c], nodes, N);
        out.abscissa.push_back(s);
        out.jump.push_back(jump);
    }
    return out;
}

}  // namespace ma::fracture
