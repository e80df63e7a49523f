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

std::vector<double> rigidBodyModes(const Discretisation& space, const DirichletConstraints& constraints, int rows) {
    if (constraints.freeCount != rows) return {};
    const DofNumbering& numbering = space.numbering();
    const auto& coords = space.mesh().coords;
    const int dim = numbering.dim(), modes = dim == 2 ? 3 : 6;
    const size_t n = static_cast<size_t>(rows);
    std::vector<double> v(static_cast<size_t>(modes) * n, 0.0);
    for (int node = 0; node < numbering.nodeCount(); ++node) {
        const double x = coords[node][0], y = coords[node][1], z = coords[node][2];
        // Rotation values per component: about z (2D and 3D), then about x and y (3D).
        const double rotations[3][3] = {{-y, x, 0.0}, {0.0, -z, y}, {z, 0.0, -x}};
        for (int comp = 0; comp < dim; ++comp) {
            const int d = numbering.dof(node, 0, comp);
            if (d < 0) continue;
            const int e = constraints.eq[d];
            if (e < 0 || e >= rows) continue;
            const size_t row = static_cast<size_t>(e);
            v[static_cast<size_t>(comp) * n + row] = 1.0;
            for (int r = 0; r < (dim == 2 ? 1 : 3); ++r) v[static_cast<size_t>(dim + r) * n + row] = rotations[r][comp];
        }
    }
    return v;
}

}  // namespace ma
