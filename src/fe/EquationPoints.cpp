#include "fe/EquationPoints.hpp"

namespace ma {

std::vector<RowPoint> equationPoints(const Discretisation& space, const DirichletConstraints& constraints, int rows) {
    if (constraints.freeCount != rows) return {};
    const DofNumbering& numbering = space.numbering();
    const auto& coords = space.mesh().coords;
    std::vector<RowPoint> points(static_cast<size_t>(rows));
    for (int node = 0; node < numbering.nodeCount(); ++node) {
        const RowPoint p{float(coords[node][0]), float(coords[node][1]), float(coords[node][2])};
        for (int d = numbering.first(node); d < numbering.first(node + 1); ++d)
            if (const int e = constraints.eq[d]; e >= 0 && e < rows) points[e] = p;
    }
    return points;
}

}  // namespace ma
