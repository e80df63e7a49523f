#include "fracture/LipJumps.hpp"

#include "mesh/PointLocation.hpp"
#include "mesh/ShapeFunctions.hpp"

namespace ma::fracture {

LipSamples heavisideJumps(const Mesh& mesh, const NodalField& depl, const Vec3& front, const Vec3& direction,
                          double length, int points, double maxDistance, const TipJump& tipJump) {
    const int comps[3] = {depl.componentIndex("H1X"), depl.componentIndex("H1Y"), depl.componentIndex("H1Z")};
    LipSamples out;
    std::vector<double> N;
    for (int i = 0; i < points; ++i) {
        const double s = length * i / (points - 1);
        const Vec3 x{front[0] - s * direction[0], front[1] - s * direction[1], front[2] - s * direction[2]};
        const PointInCell at = locateNearPoint(mesh, x, maxDistance);
        if (at.cell < 0) continue;
        const auto nodes = mesh.cellNodes(at.cell);
        N.assign(nodes.size(), 0.0);
        shapeValues(mesh.cellTypes[size_t(at.cell)], at.xi, N);
        Vec3 jump = tipJump ? tipJump(at, N) : Vec3{};
        for (size_t a = 0; a < nodes.size(); ++a)
            for (int c = 0; c < 3; ++c)
                if (comps[c] >= 0 && depl.has(nodes[a], comps[c]))
                    jump[size_t(c)] += 2 * N[a] * depl.at(nodes[a], comps[c]);
        out.abscissa.push_back(s);
        out.jump.push_back(jump);
    }
    return out;
}

}  // namespace ma::fracture
