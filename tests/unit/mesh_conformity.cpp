// LIRE_MAILLAGE's conformity check (mesh/MeshConformity): faces of one cell only that overlap
// another such face, counted by hand on small meshes and on code_aster's own meshes.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "med_io/MedReader.hpp"
#include "med_test_support.hpp"
#include "mesh/MeshConformity.hpp"

using namespace ma;

namespace {

void addCell(Mesh& m, CellType t, std::vector<int> nodes) {
    m.cellTypes.push_back(t);
    m.connectivity.insert(m.connectivity.end(), nodes.begin(), nodes.end());
    m.cellOffsets.push_back(int(m.connectivity.size()));
    m.cellNames.push_back(fmt::format("M{}", m.cellCount()));
}

void addNode(Mesh& m, double x, double y, double z) {
    m.coords.push_back({x, y, z});
    m.nodeNames.push_back(fmt::format("N{}", m.nodeCount()));
}

// Two prisms on the triangles (0,1,2) and (1,3,2) of the unit square, extruded to z = 1 (nodes
// 4..7 above 0..3), each cut into three TETRA4. The first cuts their common quadrangle 1-2-6-5
// along 1-6; the second along 1-6 too (conforming) or along 2-5.
Mesh twoPrisms(bool sameDiagonal) {
    Mesh m;
    for (double z : {0.0, 1.0})
        for (auto [x, y] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {1.0, 1.0}}) addNode(m, x, y, z);
    for (auto t : {std::vector{0, 1, 2, 6}, {0, 1, 5, 6}, {0, 4, 5, 6}}) addCell(m, CellType::TETRA4, t);
    if (sameDiagonal)
        for (auto t : {std::vector{1, 2, 3, 7}, {1, 2, 6, 7}, {1, 5, 6, 7}}) addCell(m, CellType::TETRA4, t);
    else
        for (auto t : {std::vector{2, 1, 3, 7}, {2, 1, 5, 7}, {2, 6, 5, 7}}) addCell(m, CellType::TETRA4, t);
    return m;
}

}  // namespace

TEST(MeshConformity, QuadrangleSplitAlongOneDiagonalIsConforming) {
    const auto r = meshConformity(twoPrisms(true));
    EXPECT_EQ(r.dimension, 3);
    EXPECT_EQ(r.unsharedFaces, 12);  // 2 x (bottom, top, two outer quadrangles of 2 triangles)
    EXPECT_EQ(r.overlappingFaces, 0);
    EXPECT_TRUE(r.faultCells.empty());
}

TEST(MeshConformity, QuadrangleSplitAlongTwoDiagonalsIsFound) {
    const auto r = meshConformity(twoPrisms(false));
    EXPECT_EQ(r.unsharedFaces, 16);    // the 12 of the skin and both halves of each side's cut
    EXPECT_EQ(r.overlappingFaces, 4);  // (1,2,6), (1,5,6) against (1,2,5), (2,5,6)
    EXPECT_EQ(r.faultCells, (std::vector<int>{0, 1, 4, 5}));
}

TEST(MeshConformity, HangingNodeIn2DIsFound) {
    Mesh m;
    m.dim = 2;
    for (auto [x, y] :
         {std::pair{0.0, 0.0}, {1.0, 0.0}, {2.0, 0.0}, {0.0, 0.5}, {1.0, 0.5}, {0.0, 1.0}, {1.0, 1.0}, {2.0, 1.0}})
        addNode(m, x, y, 0.0);
    addCell(m, CellType::QUAD4, {0, 1, 4, 3});
    addCell(m, CellType::QUAD4, {3, 4, 6, 5});
    addCell(m, CellType::QUAD4, {1, 2, 7, 6});  // its edge 6-1 passes through node 4
    addCell(m, CellType::SEG2, {0, 1});         // cells of lower dimension are not examined
    const auto r = meshConformity(m);
    EXPECT_EQ(r.dimension, 2);
    EXPECT_EQ(r.unsharedFaces, 10);    // 12 edges, 3-4 shared
    EXPECT_EQ(r.overlappingFaces, 3);  // 1-4, 4-6 against 6-1
    EXPECT_EQ(r.faultCells, (std::vector<int>{0, 1, 2}));
}

// ssnv511d and ssnv511h share one Gibi mesh: a layer of prisms cut into TETRA4 whose neighbours cut
// 34 common quadrangles along different diagonals. An independent count (faces of one TETRA4 only
// that lie on none of the six planes of the box) gives the same 68 faces, each of another cell.
TEST(MeshConformity, CodeAsterTetraMeshOfSsnv511hIsNotConforming) {
    for (const char* file : {"ssnv511d.mmed", "ssnv511h.mmed"}) {
        const auto r = meshConformity(*med::readMesh(test::astest(file)));
        EXPECT_EQ(r.overlappingFaces, 68) << file;
        EXPECT_EQ(r.faultCells.size(), 68u) << file;
        EXPECT_EQ(r.unsharedFaces, 68 + 148) << file;  // 148: its skin (54 + 54 + 4 x 10 triangles)
    }
    for (const char* file : {"ssnv511a.mmed", "ssnv511c.mmed", "ssnv511g.mmed", "ssnv512c.mmed"})
        EXPECT_EQ(meshConformity(*med::readMesh(test::astest(file))).overlappingFaces, 0) << file;
}
