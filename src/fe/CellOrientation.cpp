#include "fe/CellOrientation.hpp"

#include "fe/Quadrature.hpp"
#include "mesh/ElementGeometry.hpp"
#include "mesh/MeshQueries.hpp"
#include "mesh/ShapeFunctions.hpp"

namespace ma {
namespace {

enum class Sign { positive, negative, mixed, degenerate };

Sign jacobianSign(const Mesh& mesh, int cell, int dim) {
    const CellType type = mesh.cellTypes[size_t(cell)];
    const auto nodes = mesh.cellNodes(cell);
    const int n = static_cast<int>(nodes.size());
    const QuadratureRule& rule = stiffnessRule(type);
    std::array<double, 24> dN{};
    bool positive = false, negative = false;
    for (const auto& xi : rule.points) {
        shapeDerivatives(type, xi, dN);
        double J[3][3] = {}, inv[3][3] = {};
        jacobian(
            dim, dim, n, [&](int a) -> const Vec3& { return mesh.coords[size_t(nodes[size_t(a)])]; },
            [&](int a, int j) { return dN[size_t(3 * a + j)]; }, J);
        const double det = invertJacobian(dim, J, inv);
        if (degenerateJacobian(dim, J, det)) return Sign::degenerate;
        (det > 0.0 ? positive : negative) = true;
    }
    return positive && negative ? Sign::mixed : (negative ? Sign::negative : Sign::positive);
}

}  // namespace

int OrientationCensus::reversedCount() const {
    int n = 0;
    for (const auto& [type, count] : reversed) n += count;
    return n;
}

OrientationCensus orientationCensus(const Mesh& mesh) {
    OrientationCensus census;
    census.dimension = effectiveDimension(mesh);
    for (int c = 0; c < mesh.cellCount(); ++c) {
        const CellType type = mesh.cellTypes[size_t(c)];
        if (cellDimension(type) != census.dimension || !hasShapeFunctions(type)) continue;
        ++census.total[type];
        switch (jacobianSign(mesh, c, census.dimension)) {
            case Sign::positive: break;
            case Sign::negative: ++census.reversed[type]; break;
            case Sign::mixed: census.distorted.push_back(c); break;
            case Sign::degenerate: census.degenerate.push_back(c); break;
        }
    }
    return census;
}

}  // namespace ma
