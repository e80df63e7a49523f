// The GMSH POS writer on its own: number format, header and count lines, and the split of the
// quadratic volumes into tetrahedra (code_aster's irgmtb tables) checked by the volume they cover.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <sstream>

#include "post/GmshWriter.hpp"

namespace {

using ma::CellType;

TEST(GmshWriter, NumbersInCodeAstersFormat) {
    EXPECT_EQ(ma::gmsh::fortranE(1.0), " 1.0000000E+000");
    EXPECT_EQ(ma::gmsh::fortranE(-5e-3), "-5.0000000E-003");
    EXPECT_EQ(ma::gmsh::fortranE(0.0), " 0.0000000E+000");
    EXPECT_EQ(ma::gmsh::fortranE(1e-100), " 0.0000000E+000");  // |v| <= 1e-99 is 0
    EXPECT_EQ(ma::gmsh::fortranE(9.99999999), " 1.0000000E+001");
    EXPECT_EQ(ma::gmsh::fortranE(-2.5e6), "-2.5000000E+006");
    EXPECT_EQ(ma::gmsh::fortranE(std::nan("")), " 0.0000000E+000");
}

// A unit cube (HEXA20 / HEXA27, code_aster's node order) or the prism x, y >= 0, x + y <= 1,
// 0 <= z <= 1 (PENTA18).
ma::Mesh oneCell(CellType type) {
    ma::Mesh m;
    std::vector<std::array<double, 3>> v;
    std::vector<std::array<int, 2>> edges;
    std::vector<std::vector<int>> faces;
    if (type == CellType::PENTA18) {
        v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
        edges = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 4}, {2, 5}, {3, 4}, {4, 5}, {5, 3}};
        faces = {{0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
    } else {
        v = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
        edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5}, {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
        if (type == CellType::HEXA27)
            faces = {{0, 1, 2, 3},
                     {0, 1, 5, 4},
                     {1, 2, 6, 5},
                     {2, 3, 7, 6},
                     {3, 0, 4, 7},
                     {4, 5, 6, 7},
                     {0, 1, 2, 3, 4, 5, 6, 7}};
    }
    auto points = v;
    for (auto [a, b] : edges)
        points.push_back({(v[a][0] + v[b][0]) / 2, (v[a][1] + v[b][1]) / 2, (v[a][2] + v[b][2]) / 2});
    for (const auto& f : faces) {
        std::array<double, 3> c{0, 0, 0};
        for (int i : f)
            for (int k = 0; k < 3; ++k) c[k] += v[i][k] / double(f.size());
        points.push_back(c);
    }
    std::vector<int> nodes;
    for (const auto& p : points) nodes.push_back(m.addNode(p));
    m.addCell(type, nodes);
    return m;
}

// Volume covered by the tetrahedra of a scalar view (records: x of 4 nodes, y, z, values).
double tetraVolume(const std::string& view, int* count) {
    std::istringstream in(view);
    std::string line;
    for (int i = 0; i < 2; ++i) std::getline(in, line);  // $View, name
    std::array<int, 24> counts{};
    for (auto& c : counts) in >> c;
    *count = counts[12];                     // the tetrahedron line: 5th of the 8 count lines, scalar column
    for (int i = 0; i < 4; ++i) in >> line;  // text counts
    double time;
    in >> time;
    double total = 0;
    for (int t = 0; t < *count; ++t) {
        std::array<std::array<double, 3>, 4> p{};
        for (int axis = 0; axis < 3; ++axis)
            for (int n = 0; n < 4; ++n) in >> p[n][axis];
        double value;
        for (int n = 0; n < 4; ++n) in >> value;
        std::array<std::array<double, 3>, 3> e{};
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a) e[k][a] = p[k + 1][a] - p[0][a];
        const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                           e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
        total += std::abs(det) / 6;
    }
    return total;
}

TEST(GmshWriter, QuadraticVolumesSplitIntoTetrahedraCoveringThem) {
    for (auto [type, pieces, volume] : {std::tuple{CellType::HEXA20, 24, 1.0}, std::tuple{CellType::HEXA27, 48, 1.0},
                                        std::tuple{CellType::PENTA18, 24, 0.5}}) {
        const ma::Mesh mesh = oneCell(type);
        ma::gmsh::View v{"T_X", ma::gmsh::ViewKind::Scalar, {1.0}, false, {{}}, {0}};
        for (const auto& p : mesh.coords) v.steps[0].push_back(p[0]);
        std::vector<CellType> skipped;
        int count = 0;
        const std::string text = ma::gmsh::view(mesh, v, 2, &skipped);
        EXPECT_NEAR(tetraVolume(text, &count), volume, 1e-6) << ma::cellTypeName(type);
        EXPECT_EQ(count, pieces) << ma::cellTypeName(type);
        EXPECT_TRUE(skipped.empty());
    }
}

TEST(GmshWriter, HeaderAndCountLines) {
    EXPECT_EQ(ma::gmsh::header(2), "$PostFormat\n 1.2 0 8\n$EndPostFormat\n");
    EXPECT_EQ(ma::gmsh::header(1), "$PostFormat\n 1.0 0 8\n$EndPostFormat\n");
    ma::Mesh m;
    for (auto p : std::vector<std::array<double, 3>>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}) m.addNode(p);
    m.addCell(CellType::QUAD4, std::vector<int>{0, 1, 2, 3});
    ma::gmsh::View v{"R_DEPL_VECTEUR", ma::gmsh::ViewKind::Vector, {1.0}, false, {std::vector<double>(12, 0.0)}, {0}};
    // 1.2: one quadrangle in the vector column of the 4th count line; 1.0: two triangles.
    EXPECT_EQ(ma::gmsh::view(m, v, 2).rfind(
                  "$View\nR_DEPL_VECTEUR     1\n       0        0        0 \n       0        0        0 \n"
                  "       0        0        0 \n       0        1        0 \n       0        0        0 \n",
                  0),
              0u);
    EXPECT_NE(ma::gmsh::view(m, v, 1).find(
                  "       0        2        0 \n       0        0        0 \n 1.00000000E+00\n"),
              std::string::npos);
}

}  // namespace
