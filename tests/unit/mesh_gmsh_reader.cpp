// LIRE_MAILLAGE FORMAT='GMSH' reader on hand-written MSH 2 texts: what code_aster's PRE_GMSH makes
// of them (docs/mesh.md): node and cell names, cells by element type, GM<tag> groups, unused nodes
// dropped, quadratic node renumbering, and the refusals with their line.
#include <gtest/gtest.h>

#include <sstream>

#include "core/Error.hpp"
#include "mesh/GmshMeshReader.hpp"

using namespace ma;

namespace {

// The plate [0,2]x[0,1]: two QUAD4 (physical 1), the bottom edges (2), the right edge (4), the left
// edge (5), the point at the origin (6); node 99 belongs to no element.
const char* kPlate = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
1
2 1 "plate"
$EndPhysicalNames
$Nodes
7
1 0 0 0
2 1 0 0
3 2 0 0
4 0 1 0
5 1 1 0
6 2 1 0
99 5 5 5
$EndNodes
$Elements
7
10 3 2 1 1 1 2 5 4
11 3 2 1 1 2 3 6 5
1 1 2 2 2 1 2
2 1 2 2 2 2 3
3 1 2 4 4 3 6
4 1 2 5 5 4 1
20 15 2 6 6 1
$EndElements
)";

std::shared_ptr<Mesh> parse(const std::string& text) {
    std::istringstream in(text);
    return parseGmshMesh(in, "t.msh");
}

std::string errorOf(const std::string& text) {
    try {
        parse(text);
    } catch (const UserError& e) { return e.what(); }
    return "";
}

std::vector<std::string> names(const std::vector<std::string>& all, const std::vector<int>& members) {
    std::vector<std::string> out;
    for (int m : members) out.push_back(all[size_t(m)]);
    return out;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    return text.replace(text.find(from), from.size(), to);
}

}  // namespace

TEST(GmshMeshReader, PlateAsPreGmshConvertsIt) {
    auto m = parse(kPlate);
    EXPECT_EQ(m->dim, 3);
    EXPECT_EQ(m->nodeNames, (std::vector<std::string>{"N1", "N2", "N3", "N4", "N5", "N6"}));
    EXPECT_EQ(m->coords[5], (std::array<double, 3>{2, 1, 0}));
    // SEG2 (type 1) first, then QUAD4 (3), then POI1 (15); file order inside a type.
    EXPECT_EQ(m->cellNames, (std::vector<std::string>{"M1", "M2", "M3", "M4", "M10", "M11", "M20"}));
    EXPECT_EQ(m->cellTypes[4], CellType::QUAD4);
    EXPECT_EQ(m->cellTypes[6], CellType::POI1);
    const auto q = m->cellNodes(5);
    EXPECT_EQ(names(m->nodeNames, {q.begin(), q.end()}), (std::vector<std::string>{"N2", "N3", "N6", "N5"}));
    EXPECT_EQ(m->cellGroups.names(), (std::vector<std::string>{"GM1", "GM2", "GM4", "GM5", "GM6"}));
    EXPECT_EQ(names(m->cellNames, m->cellGroups.get("GM1")), (std::vector<std::string>{"M10", "M11"}));
    EXPECT_EQ(names(m->cellNames, m->cellGroups.get("GM2")), (std::vector<std::string>{"M1", "M2"}));
    // A group that is one point element is also a node group.
    EXPECT_EQ(m->nodeGroups.names(), (std::vector<std::string>{"GM6"}));
    EXPECT_EQ(names(m->nodeNames, m->nodeGroups.get("GM6")), (std::vector<std::string>{"N1"}));
}

// TETRA10: code_aster's nodes 9 and 10 are gmsh's 10 and 9 (inigms).
TEST(GmshMeshReader, Tetra10Renumbering) {
    std::ostringstream t;
    t << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n10\n";
    const double x[10][3] = {{0, 0, 0},     {1, 0, 0},   {0, 1, 0},   {0, 0, 1},     {0.5, 0, 0},
                             {0.5, 0.5, 0}, {0, 0.5, 0}, {0, 0, 0.5}, {0, 0.5, 0.5}, {0.5, 0, 0.5}};
    for (int i = 0; i < 10; ++i) t << i + 1 << ' ' << x[i][0] << ' ' << x[i][1] << ' ' << x[i][2] << '\n';
    t << "$EndNodes\n$Elements\n1\n7 11 2 3 1 1 2 3 4 5 6 7 8 9 10\n$EndElements\n";
    auto m = parse(t.str());
    ASSERT_EQ(m->cellCount(), 1);
    EXPECT_EQ(m->cellTypes[0], CellType::TETRA10);
    const auto c = m->cellNodes(0);
    EXPECT_EQ(names(m->nodeNames, {c.begin(), c.end()}),
              (std::vector<std::string>{"N1", "N2", "N3", "N4", "N5", "N6", "N7", "N8", "N10", "N9"}));
    EXPECT_EQ(m->cellGroups.names(), (std::vector<std::string>{"GM3"}));
}

TEST(GmshMeshReader, RefusalsNameTheLine) {
    EXPECT_EQ(errorOf(replaced(kPlate, "2.2 0 8", "4.1 0 8")),
              "mesh file 't.msh', line 2: MSH version 4.1: miniaster reads MSH 2 text files (gmsh -format msh2, or "
              "Mesh.MshFileVersion = 2.2)");
    EXPECT_EQ(errorOf(replaced(kPlate, "2.2 0 8", "2.2 1 8")),
              "mesh file 't.msh', line 2: a binary MSH file: save the mesh as text (Mesh.Binary = 0)");
    EXPECT_EQ(errorOf(replaced(kPlate, "3 1 2 4 4 3 6", "3 1 2 4 4 3 7")),
              "mesh file 't.msh', line 24: element 3 names node 7, which $Nodes does not define");
    EXPECT_EQ(errorOf(replaced(kPlate, "20 15 2 6 6 1", "20 15 0 1")),
              "mesh file 't.msh', line 26: element 20 has no physical group (first tag 0 or absent): give every "
              "element a physical group, as code_aster's PRE_GMSH needs");
    EXPECT_EQ(errorOf(replaced(kPlate, "11 3 2 1 1", "10 3 2 1 1")),
              "mesh file 't.msh', line 21: element 10 is defined twice (line 20)");
    EXPECT_EQ(errorOf(replaced(kPlate, "20 15 2 6 6 1", "20 14 2 6 6 1")),
              "mesh file 't.msh', line 26: element 20: gmsh type 14 has 14 nodes");
    EXPECT_EQ(errorOf(replaced(kPlate, "20 15 2 6 6 1", "20 31 2 6 6 1")),
              "mesh file 't.msh', line 26: element 20: gmsh type 31 is not one PRE_GMSH reads (1 to 19)");
    EXPECT_EQ(errorOf(replaced(kPlate, "$EndElements\n", "")),
              "mesh file 't.msh', line 26: the file ends before $EndElements");
}
