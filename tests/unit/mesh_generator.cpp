// The ssnv511 mesh generator: counts and groups for several N, measures summing to the domain,
// positive cells, outward and conforming skins, offsets, and the MED file it writes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <numeric>
#include <set>

#include "core/Error.hpp"
#include "med_io/MedReader.hpp"
#include "med_io/MedWriter.hpp"
#include "med_test_support.hpp"
#include "mesh/MeshQueries.hpp"
#include "scenes/Ssnv511Mesh.hpp"

using namespace ma;
using Kind = Ssnv511MeshOptions::Kind;

namespace {

std::shared_ptr<Mesh> build(Kind kind, int n, double ox = 0, double oy = 0) {
    Ssnv511MeshOptions o;
    o.kind = kind;
    o.divisions = n;
    o.offsetX = ox;
    o.offsetY = oy;
    return buildSsnv511Mesh(o);
}

int count(const Mesh& m, CellType t) {
    int k = 0;
    for (auto c : m.cellTypes) k += c == t;
    return k;
}

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Signed area (2D cells, z up) or volume (3D cells, split in tetrahedra); positive = well oriented.
double measure(const Mesh& m, int c) {
    auto n = m.cellNodes(c);
    auto X = [&](int k) { return m.coords[n[k]]; };
    switch (m.cellTypes[c]) {
        case CellType::TRIA3: return 0.5 * cross(sub(X(1), X(0)), sub(X(2), X(0)))[2];
        case CellType::QUAD4:
            return 0.5 * (cross(sub(X(1), X(0)), sub(X(2), X(0)))[2] + cross(sub(X(2), X(0)), sub(X(3), X(0)))[2]);
        case CellType::TETRA4: return dot(cross(sub(X(1), X(0)), sub(X(2), X(0))), sub(X(3), X(0))) / 6.0;
        case CellType::HEXA8: {
            // Six tetrahedra around the diagonal 0-6: all positive for a well-oriented hexahedron.
            double v = 0;
            const int tets[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
            for (const auto& t : tets) {
                const double part =
                    dot(cross(sub(X(t[1]), X(t[0])), sub(X(t[2]), X(t[0]))), sub(X(t[3]), X(t[0]))) / 6.0;
                if (!(part > 0)) return -1.0;
                v += part;
            }
            return v;
        }
        default: return 0;
    }
}

// Faces of the volume cells that belong to one cell only (sorted vertex lists).
std::multiset<std::vector<int>> boundaryFaces(const Mesh& m) {
    std::map<std::vector<int>, int> seen;
    for (int c = 0; c < m.cellCount(); ++c) {
        auto n = m.cellNodes(c);
        std::vector<std::vector<int>> faces;
        if (m.cellTypes[c] == CellType::TETRA4)
            faces = {{n[0], n[1], n[2]}, {n[0], n[1], n[3]}, {n[1], n[2], n[3]}, {n[0], n[2], n[3]}};
        else if (m.cellTypes[c] == CellType::HEXA8)
            faces = {{n[0], n[1], n[2], n[3]}, {n[4], n[5], n[6], n[7]}, {n[0], n[1], n[5], n[4]},
                     {n[1], n[2], n[6], n[5]}, {n[2], n[3], n[7], n[6]}, {n[3], n[0], n[4], n[7]}};
        for (auto f : faces) {
            std::sort(f.begin(), f.end());
            ++seen[f];
        }
    }
    std::multiset<std::vector<int>> out;
    for (const auto& [f, k] : seen) {
        EXPECT_LE(k, 2) << "a face shared by more than two cells";
        if (k == 1) out.insert(f);
    }
    return out;
}

// Outward normal at a boundary point of the box [-5,5]^2 x [0,1].
Vec3 outwardAt(const Vec3& g) {
    if (std::abs(g[0] - 5) < 1e-12) return {1, 0, 0};
    if (std::abs(g[0] + 5) < 1e-12) return {-1, 0, 0};
    if (std::abs(g[1] - 5) < 1e-12) return {0, 1, 0};
    if (std::abs(g[1] + 5) < 1e-12) return {0, -1, 0};
    if (std::abs(g[2]) < 1e-12) return {0, 0, -1};
    return {0, 0, 1};
}

}  // namespace

TEST(Ssnv511Mesh, TwoDimensionalCountsGroupsAreaOrientation) {
    for (Kind kind : {Kind::Quad4, Kind::Tria3})
        for (int n : {1, 2, 5, 8, 51}) {
            auto m = build(kind, n);
            const int per = kind == Kind::Quad4 ? 1 : 2;
            const CellType t = kind == Kind::Quad4 ? CellType::QUAD4 : CellType::TRIA3;
            EXPECT_EQ(m->dim, 2);
            EXPECT_EQ(m->nodeCount(), (n + 1) * (n + 1));
            EXPECT_EQ(count(*m, CellType::SEG2), 4 * n);
            EXPECT_EQ(count(*m, t), per * n * n);
            EXPECT_EQ(m->cellGroups.names(), (std::vector<std::string>{"LB", "LD", "LH", "LG", "SURF"}));
            double area = 0;
            for (int c : m->cellGroups.get("SURF")) {
                const double a = measure(*m, c);
                EXPECT_GT(a, 0.0);
                area += a;
            }
            EXPECT_NEAR(area, 100.0, 1e-11);
            // Edges: the right side, counter-clockwise (outward normal), covering the boundary.
            const std::pair<const char*, Vec3> sides[] = {{"LB", {0, -1, 0}},
                                                          {"LD", {1, 0, 0}},
                                                          {"LH", {0, 1, 0}},
                                                          {"LG", {-1, 0, 0}}};
            for (const auto& [g, out] : sides) {
                double length = 0;
                for (int c : m->cellGroups.get(g)) {
                    const Vec3 nrm = cellNormal(*m, c);
                    EXPECT_NEAR(dot(nrm, out), norm(nrm), 1e-12) << g;
                    length += norm(nrm);
                }
                EXPECT_NEAR(length, 10.0, 1e-12) << g;
            }
            // Cells numbered by type: SEG2 first.
            EXPECT_EQ(m->cellTypes.front(), CellType::SEG2);
        }
}

TEST(Ssnv511Mesh, ThreeDimensionalVolumeSkinAndConformity) {
    for (Kind kind : {Kind::Hexa8, Kind::Tetra4})
        for (int n : {1, 2, 5, 8}) {
            auto m = build(kind, n);
            const bool hexa = kind == Kind::Hexa8;
            EXPECT_EQ(m->nodeCount(), 2 * (n + 1) * (n + 1));
            const CellType vol = hexa ? CellType::HEXA8 : CellType::TETRA4;
            const CellType face = hexa ? CellType::QUAD4 : CellType::TRIA3;
            EXPECT_EQ(count(*m, vol), (hexa ? 1 : 6) * n * n);
            const int skin = hexa ? 2 * n * n + 4 * n : 4 * n * n + 8 * n;
            EXPECT_EQ(count(*m, face), skin);
            EXPECT_EQ(m->cellGroups.get("ENV").size(), size_t(skin));
            EXPECT_EQ(m->cellGroups.get("VOLU").size(), size_t(count(*m, vol)));
            double volume = 0;
            for (int c : m->cellGroups.get("VOLU")) {
                const double v = measure(*m, c);
                EXPECT_GT(v, 0.0);
                volume += v;
            }
            EXPECT_NEAR(volume, 100.0, 1e-11);
            // The skin is exactly the set of faces that bound one volume cell (conforming mesh),
            // and every skin normal points outward.
            std::multiset<std::vector<int>> env;
            for (int c : m->cellGroups.get("ENV")) {
                auto nodes = m->cellNodes(c);
                std::vector<int> f(nodes.begin(), nodes.end());
                std::sort(f.begin(), f.end());
                env.insert(f);
                const Vec3 nrm = cellNormal(*m, c);
                EXPECT_NEAR(dot(nrm, outwardAt(vertexCentroid(*m, c))), norm(nrm), 1e-12);
            }
            EXPECT_EQ(env, boundaryFaces(*m));
            if (hexa) {
                EXPECT_EQ(m->cellGroups.names(), (std::vector<std::string>{"ENV", "SD", "SG", "VOLU"}));
                for (int c : m->cellGroups.get("SD"))
                    for (int v : m->cellNodes(c)) EXPECT_EQ(m->coords[v][0], 5.0);
                for (int c : m->cellGroups.get("SG"))
                    for (int v : m->cellNodes(c)) EXPECT_EQ(m->coords[v][0], -5.0);
                EXPECT_EQ(m->cellGroups.get("SD").size(), size_t(n));
            } else {
                EXPECT_EQ(m->cellGroups.names(), (std::vector<std::string>{"ENV", "VOLU"}));
                EXPECT_FALSE(m->nodeGroups.has("SD"));
            }
        }
}

// HEXA8 in several layers (the 3D block of `study solvers`): counts, the volume of [-5,5]^2 x [0,10],
// positive cells, a conforming outward skin with SD/SG on every layer; other kinds refuse layers.
TEST(Ssnv511Mesh, Hexa8LayersMakeAConformingBlock) {
    for (auto [n, layers] : {std::pair{1, 2}, std::pair{4, 3}, std::pair{5, 5}}) {
        Ssnv511MeshOptions o;
        o.kind = Kind::Hexa8, o.divisions = n, o.layers = layers, o.zmax = 10.0;
        auto m = buildSsnv511Mesh(o);
        EXPECT_EQ(m->nodeCount(), (layers + 1) * (n + 1) * (n + 1));
        EXPECT_EQ(count(*m, CellType::HEXA8), n * n * layers);
        const int skin = 2 * n * n + 4 * n * layers;
        EXPECT_EQ(count(*m, CellType::QUAD4), skin);
        double volume = 0;
        for (int c : m->cellGroups.get("VOLU")) {
            EXPECT_GT(measure(*m, c), 0.0);
            volume += measure(*m, c);
        }
        EXPECT_NEAR(volume, 1000.0, 1e-9);
        std::multiset<std::vector<int>> env;
        for (int c : m->cellGroups.get("ENV")) {
            auto nodes = m->cellNodes(c);
            std::vector<int> f(nodes.begin(), nodes.end());
            std::sort(f.begin(), f.end());
            env.insert(f);
            const Vec3 g = vertexCentroid(*m, c), nrm = cellNormal(*m, c);
            const Vec3 out = std::abs(g[2] - 10.0) < 1e-12 ? Vec3{0, 0, 1} : outwardAt(g);
            EXPECT_NEAR(dot(nrm, out), norm(nrm), 1e-9);
        }
        EXPECT_EQ(env, boundaryFaces(*m));
        EXPECT_EQ(m->cellGroups.get("SD").size(), size_t(n * layers));
        EXPECT_EQ(m->cellGroups.get("SG").size(), size_t(n * layers));
    }
    Ssnv511MeshOptions t;
    t.kind = Kind::Tetra4, t.layers = 2;
    EXPECT_THROW(buildSsnv511Mesh(t), UserError);
}

TEST(Ssnv511Mesh, OffsetsMoveInteriorLinesOnly) {
    auto m = build(Kind::Quad4, 4, 0.3, -0.25);
    std::set<double> xs, ys;
    for (const auto& x : m->coords) xs.insert(x[0]), ys.insert(x[1]);
    EXPECT_EQ(xs, (std::set<double>{-5.0, -5.0 + 1.3 * 2.5, -5.0 + 2.3 * 2.5, -5.0 + 3.3 * 2.5, 5.0}));
    EXPECT_EQ(ys, (std::set<double>{-5.0, -5.0 + 0.75 * 2.5, -5.0 + 1.75 * 2.5, -5.0 + 2.75 * 2.5, 5.0}));
    EXPECT_EQ(xs.count(0.0), 0u);  // x = 0 no longer on a grid line (N even)
    Ssnv511MeshOptions bad;
    bad.offsetX = 1.0;
    EXPECT_THROW(buildSsnv511Mesh(bad), UserError);
    bad.offsetX = 0;
    bad.divisions = 0;
    EXPECT_THROW(buildSsnv511Mesh(bad), UserError);
}

// A cell as the sorted coordinates of its nodes: the same cell whatever the numbering of the
// mesh's nodes and the cell's node order (orientation).
std::vector<std::array<double, 3>> geometricCell(const Mesh& m, int c) {
    std::vector<std::array<double, 3>> x;
    for (int n : m.cellNodes(c)) x.push_back(m.coords[n]);
    std::sort(x.begin(), x.end());
    return x;
}

std::multiset<std::pair<int, std::vector<std::array<double, 3>>>> geometricCells(const Mesh& m,
                                                                                 const std::vector<int>& cells) {
    std::multiset<std::pair<int, std::vector<std::array<double, 3>>>> out;
    for (int c : cells) out.emplace(int(m.cellTypes[c]), geometricCell(m, c));
    return out;
}

TEST(Ssnv511Mesh, SameCellsAndGroupsAsCodeAstersMeshes) {
    // N = 5 QUAD4 and HEXA8 are code_aster's ssnv511a and ssnv511g meshes up to numbering: the same
    // nodes, cells and groups (code_aster's files number them as GIBI did, add a group MAILLE of the
    // volume cells, and their HEXA8 are left-handed where the generator's are right-handed). The HEXA8
    // file also holds 10 SEG2 edges in groups LD and LG that no .comm of the family uses: the
    // generator makes faces and volumes only in 3D.
    const std::pair<Kind, const char*> cases[] = {{Kind::Quad4, "ssnv511a.mmed"}, {Kind::Hexa8, "ssnv511g.mmed"}};
    for (const auto& [kind, file] : cases) {
        auto m = build(kind, 5);
        auto ref = med::readMesh(test::astest(file));
        auto nodes = m->coords, refNodes = ref->coords;
        std::sort(nodes.begin(), nodes.end());
        std::sort(refNodes.begin(), refNodes.end());
        EXPECT_EQ(nodes, refNodes) << file;
        const std::set<std::string> onlyInCodeAsters =
            kind == Kind::Quad4 ? std::set<std::string>{"MAILLE"} : std::set<std::string>{"MAILLE", "LD", "LG"};
        auto cellsOf = [&](const Mesh& mesh) {
            std::vector<int> cells;
            for (int c = 0; c < mesh.cellCount(); ++c)
                if (kind == Kind::Quad4 || mesh.cellTypes[c] != CellType::SEG2) cells.push_back(c);
            return cells;
        };
        EXPECT_EQ(geometricCells(*m, cellsOf(*m)), geometricCells(*ref, cellsOf(*ref))) << file;
        for (const auto& g : ref->cellGroups.names()) {
            if (onlyInCodeAsters.count(g)) continue;
            ASSERT_TRUE(m->cellGroups.has(g)) << file << " " << g;
            EXPECT_EQ(geometricCells(*m, m->cellGroups.get(g)), geometricCells(*ref, ref->cellGroups.get(g))) << g;
        }
        EXPECT_EQ(ref->cellGroups.get("MAILLE"), ref->cellGroups.get(kind == Kind::Quad4 ? "SURF" : "VOLU"));
        EXPECT_EQ(m->cellGroups.size() + onlyInCodeAsters.size(), ref->cellGroups.size()) << file;
    }
}

TEST(Ssnv511Mesh, WrittenFileIsReadByMeshioAndByTheTool) {
    const auto dir = test::scratchDir("generator");
    auto m = build(Kind::Tetra4, 3);
    {
        med::MedWriter w(dir + "/t.med", false);
        w.writeMesh(*m, "MAILLAGE");
        w.commit();
    }
    auto probe = test::probeMesh(dir + "/t.med");
    EXPECT_EQ(int(probe.nodes.size()), m->nodeCount());
    EXPECT_EQ(int(probe.cells.size()), m->cellCount());
    EXPECT_EQ(probe.cellGroups["ENV"], m->cellGroups.get("ENV"));
    EXPECT_EQ(probe.cellGroups["VOLU"], m->cellGroups.get("VOLU"));

    const auto tool = std::filesystem::path(MINIASTER_BINARY).parent_path() / "tools" / "ssnv511_mesh";
    ASSERT_TRUE(std::filesystem::exists(tool)) << "tool not built: " << tool;  // part of the build
    const auto out = test::runCommand(tool.string() + " --type tria3 --n 7 --offset 0.2 0.2 -o " + dir + "/b.med");
    EXPECT_NE(out.find("64 nodes, 126 cells"), std::string::npos) << out;
    auto back = med::readMesh(dir + "/b.med");
    EXPECT_EQ(back->cellGroups.get("SURF").size(), 98u);
    int status = 0;
    test::runCommand(tool.string() + " --type cube --n 7 -o " + dir + "/c.med", &status);
    EXPECT_NE(status, 0);
    EXPECT_FALSE(std::filesystem::exists(dir + "/c.med"));
    std::filesystem::remove_all(dir);
}
