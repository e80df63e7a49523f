#include "mesh/ElementGeometry.hpp"

#include <algorithm>
#include <cmath>

namespace ma {

void jacobian(std::span<const Vec3> nodes, std::span<const double> dN, int rdim, double J[3][3]) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) J[i][j] = 0.0;
    for (size_t a = 0; a < nodes.size(); ++a)
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < rdim; ++j) J[i][j] += nodes[a][i] * dN[3 * a + j];
}

double jacobianMeasure(const double J[3][3], int rdim) {
    double G[3][3] = {};  // J^T J
    for (int p = 0; p < rdim; ++p)
        for (int q = 0; q < rdim; ++q)
            for (int i = 0; i < 3; ++i) G[p][q] += J[i][p] * J[i][q];
    double det = 0;
    if (rdim == 1) det = G[0][0];
    else if (rdim == 2) det = G[0][0] * G[1][1] - G[0][1] * G[1][0];
    else
        det = G[0][0] * (G[1][1] * G[2][2] - G[1][2] * G[2][1]) - G[0][1] * (G[1][0] * G[2][2] - G[1][2] * G[2][0]) +
              G[0][2] * (G[1][0] * G[2][1] - G[1][1] * G[2][0]);
    return std::sqrt(std::max(det, 0.0));
}

Vec3 boundaryNormal(const double J[3][3], int rdim) {
    if (rdim == 1) return {J[1][0], -J[0][0], 0.0};
    return {J[1][0] * J[2][1] - J[2][0] * J[1][1], J[2][0] * J[0][1] - J[0][0] * J[2][1],
            J[0][0] * J[1][1] - J[1][0] * J[0][1]};
}

}  // namespace ma
