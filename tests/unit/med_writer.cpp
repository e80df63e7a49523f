// MedWriter node orders: one cell of every quadratic/linear volume type built in the internal
// (code_aster) order from its geometry, written, then checked against MED's documented numbering
// on the raw connectivity read with h5py (no permutation), and read back by our reader.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>

#include "med_io/MedReader.hpp"
#include "med_io/MedWriter.hpp"
#include "med_test_support.hpp"
#include "mesh/MeshQueries.hpp"

using namespace ma;

namespace {

using Edges = std::vector<std::pair<int, int>>;  // 1-based vertex pairs
using Faces = std::vector<std::vector<int>>;     // 1-based vertex lists

// Builds a cell from its vertices plus the centres of `edges`, `faces` and optionally the cell.
int addCell(Mesh& m, CellType t, const std::vector<Vec3>& vertices, const Edges& edges, const Faces& faces, bool centre,
            const std::string& group) {
    std::vector<int> nodes;
    for (const auto& v : vertices) nodes.push_back(m.addNode(v));
    auto mean = [&](const std::vector<int>& ids) {
        Vec3 g{0, 0, 0};
        for (int id : ids)
            for (int d = 0; d < 3; ++d) g[d] += vertices[id - 1][d] / static_cast<double>(ids.size());
        return g;
    };
    for (auto [a, b] : edges) nodes.push_back(m.addNode(mean({a, b})));
    for (const auto& f : faces) nodes.push_back(m.addNode(mean(f)));
    if (centre) {
        std::vector<int> all;
        for (size_t k = 1; k <= vertices.size(); ++k) all.push_back(int(k));
        nodes.push_back(m.addNode(mean(all)));
    }
    EXPECT_EQ(int(nodes.size()), nodeCount(t)) << cellTypeName(t);
    const int c = m.addCell(t, nodes);
    m.cellGroups.set(group, {c});
    return c;
}

Vec3 shift(Vec3 v, double dx) { return {v[0] + dx, v[1], v[2]}; }

std::vector<std::vector<int>> rawConnectivity(const std::string& path, const std::string& medType) {
    std::istringstream in(
        test::runCommand("/usr/bin/python3 " + test::probeScript() + " rawconn '" + path + "' " + medType));
    std::vector<std::vector<int>> rows;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream ls(line);
        std::vector<int> row;
        int v;
        while (ls >> v) row.push_back(v);
        rows.push_back(row);
    }
    return rows;
}

// MED's numbering (MED-fichier reference): checks on one written row (1-based node numbers).
struct MedRule {
    const char* medType;
    int vertices;
    Edges edges;
    Faces faces;
    bool centre;
    // First-face orientation: sign of (V2-V1)x(V_k-V1).(V_apex-V1) expected negative (outward).
    int second, third, apex;
};

}  // namespace

TEST(MedWriter, VolumeNodeOrdersFollowTheMedNumbering) {
    Mesh m;
    m.dim = 3;
    m.name = "CELLS";
    const Edges hexEdges{{1, 2}, {2, 3}, {3, 4}, {4, 1}, {1, 5}, {2, 6},
                         {3, 7}, {4, 8}, {5, 6}, {6, 7}, {7, 8}, {8, 5}};
    const Faces hexFaces{{1, 2, 3, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 4, 8, 7}, {4, 1, 5, 8}, {5, 6, 7, 8}};
    const std::vector<Vec3> hex{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    const Edges penEdges{{1, 2}, {2, 3}, {3, 1}, {1, 4}, {2, 5}, {3, 6}, {4, 5}, {5, 6}, {6, 4}};
    const Faces penFaces{{1, 2, 5, 4}, {2, 3, 6, 5}, {3, 1, 4, 6}};
    const std::vector<Vec3> pen{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
    const Edges tetEdges{{1, 2}, {2, 3}, {3, 1}, {1, 4}, {2, 4}, {3, 4}};
    const std::vector<Vec3> tet{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const Edges pyrEdges{{1, 2}, {2, 3}, {3, 4}, {4, 1}, {1, 5}, {2, 5}, {3, 5}, {4, 5}};
    const std::vector<Vec3> pyr{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}};
    auto moved = [](std::vector<Vec3> v, double dx) {
        for (auto& p : v) p = shift(p, dx);
        return v;
    };
    // Internal (code_aster) orders: positive volumes, quadratic nodes bottom / vertical / top.
    addCell(m, CellType::HEXA8, moved(hex, 0), {}, {}, false, "HE8");
    addCell(m, CellType::HEXA20, moved(hex, 2), hexEdges, {}, false, "H20");
    addCell(m, CellType::HEXA27, moved(hex, 4), hexEdges, hexFaces, true, "H27");
    addCell(m, CellType::PENTA6, moved(pen, 6), {}, {}, false, "PE6");
    addCell(m, CellType::PENTA15, moved(pen, 8), penEdges, {}, false, "P15");
    addCell(m, CellType::PENTA18, moved(pen, 10), penEdges, penFaces, false, "P18");
    addCell(m, CellType::TETRA4, moved(tet, 12), {}, {}, false, "TE4");
    addCell(m, CellType::TETRA10, moved(tet, 14), tetEdges, {}, false, "T10");
    addCell(m, CellType::PYRA5, moved(pyr, 16), {}, {}, false, "PY5");
    addCell(m, CellType::PYRA13, moved(pyr, 18), pyrEdges, {}, false, "P13");

    const auto dir = test::scratchDir("med_writer");
    const std::string path = dir + "/cells.med";
    {
        med::MedWriter w(path, false);
        w.writeMesh(m, "CELLS");
        w.commit();
    }

    // MED numbering, from the MED-fichier reference element descriptions.
    const Edges medHexEdges{{1, 2}, {2, 3}, {3, 4}, {4, 1}, {5, 6}, {6, 7},
                            {7, 8}, {8, 5}, {1, 5}, {2, 6}, {3, 7}, {4, 8}};
    const Faces medHexFaces{{1, 2, 3, 4}, {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 8, 4}, {4, 8, 5, 1}, {5, 8, 7, 6}};
    const Edges medPenEdges{{1, 2}, {2, 3}, {3, 1}, {4, 5}, {5, 6}, {6, 4}, {1, 4}, {2, 5}, {3, 6}};
    const Faces medPenFaces{{1, 2, 5, 4}, {2, 3, 6, 5}, {3, 1, 4, 6}};
    const std::vector<MedRule> rules{
        {"HE8", 8, {}, {}, false, 2, 4, 5},
        {"H20", 8, medHexEdges, {}, false, 2, 4, 5},
        {"H27", 8, medHexEdges, medHexFaces, true, 2, 4, 5},
        {"PE6", 6, {}, {}, false, 2, 3, 4},
        {"P15", 6, medPenEdges, {}, false, 2, 3, 4},
        {"P18", 6, medPenEdges, medPenFaces, false, 2, 3, 4},
        {"TE4", 4, {}, {}, false, 2, 3, 4},
        {"T10", 4, tetEdges, {}, false, 2, 3, 4},
        {"PY5", 5, {}, {}, false, 2, 4, 5},
        {"P13", 5, pyrEdges, {}, false, 2, 4, 5},
    };
    for (const auto& r : rules) {
        auto rows = rawConnectivity(path, r.medType);
        ASSERT_EQ(rows.size(), 1u) << r.medType;
        const auto& row = rows[0];
        auto X = [&](int k) { return m.coords[row[k - 1] - 1]; };
        auto near = [&](const Vec3& a, const Vec3& b) {
            return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) < 1e-12;
        };
        auto mean = [&](const std::vector<int>& ids) {
            Vec3 g{0, 0, 0};
            for (int id : ids)
                for (int d = 0; d < 3; ++d) g[d] += X(id)[d] / static_cast<double>(ids.size());
            return g;
        };
        const Vec3 p1 = X(1);
        auto d = [&](int k) { return Vec3{X(k)[0] - p1[0], X(k)[1] - p1[1], X(k)[2] - p1[2]}; };
        const Vec3 u = d(r.second), v = d(r.third);
        const Vec3 n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        EXPECT_LT(dot(n, d(r.apex)), 0.0) << r.medType << ": MED's first face must be oriented outward";
        int k = r.vertices + 1;
        for (auto [a, b] : r.edges) EXPECT_TRUE(near(X(k++), mean({a, b}))) << r.medType << " node " << k - 1;
        for (const auto& f : r.faces) EXPECT_TRUE(near(X(k++), mean(f))) << r.medType << " node " << k - 1;
        if (r.centre) {
            std::vector<int> all;
            for (int i = 1; i <= r.vertices; ++i) all.push_back(i);
            EXPECT_TRUE(near(X(k++), mean(all))) << r.medType << " centre";
        }
        EXPECT_EQ(k - 1, int(row.size())) << r.medType;
    }

    // And our reader gives back the internal orders.
    auto back = med::readMesh(path);
    ASSERT_EQ(back->cellCount(), m.cellCount());
    for (int c = 0; c < m.cellCount(); ++c) {
        const int b = back->cellGroups.get(m.cellGroups.names()[c])[0];  // one group per cell
        auto x = m.cellNodes(c), y = back->cellNodes(b);
        EXPECT_EQ(std::vector<int>(x.begin(), x.end()), std::vector<int>(y.begin(), y.end()))
            << cellTypeName(m.cellTypes[c]);
    }
    std::filesystem::remove_all(dir);
}
