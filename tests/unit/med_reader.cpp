// MED reading: the astest meshes against an independent reader (meshio), a file from another
// writer with quadratic cells and multi-group families, and bad input.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "med_io/MedCellOrder.hpp"
#include "med_io/MedReader.hpp"
#include "med_io/MedWriter.hpp"
#include "med_test_support.hpp"

using namespace ma;

namespace {

// Everything the independent reader sees must be what we read.
void expectSameAsProbe(const Mesh& mesh, const std::string& path) {
    auto probe = test::probeMesh(path);
    ASSERT_EQ(mesh.nodeCount(), int(probe.nodes.size()));
    for (int i = 0; i < mesh.nodeCount(); ++i)
        for (int d = 0; d < 3; ++d) ASSERT_EQ(mesh.coords[i][d], probe.nodes[i][d]) << "node " << i;
    ASSERT_EQ(mesh.cellCount(), int(probe.cells.size()));
    for (int c = 0; c < mesh.cellCount(); ++c) {
        ASSERT_EQ(int(mesh.cellTypes[c]), probe.cellType[c]) << "cell " << c;
        auto nodes = mesh.cellNodes(c);
        std::vector<int> med(nodes.size());
        med::internalToMed(mesh.cellTypes[c], nodes, med);
        ASSERT_EQ(med, probe.cells[c]) << "cell " << c;
    }
    EXPECT_EQ(mesh.cellGroups.size(), probe.cellGroups.size());
    for (const auto& [name, members] : probe.cellGroups) {
        std::string kept = name.substr(0, 24);
        ASSERT_TRUE(mesh.cellGroups.has(kept)) << kept;
        EXPECT_EQ(mesh.cellGroups.get(kept), members) << name;
    }
    EXPECT_EQ(mesh.nodeGroups.size(), probe.nodeGroups.size());
    for (const auto& [name, members] : probe.nodeGroups) {
        ASSERT_TRUE(mesh.nodeGroups.has(name)) << name;
        EXPECT_EQ(mesh.nodeGroups.get(name), members) << name;
    }
}

int countType(const Mesh& m, CellType t) {
    int n = 0;
    for (auto x : m.cellTypes) n += x == t;
    return n;
}

double signedVolumeTetra(const Mesh& m, int c) {
    auto n = m.cellNodes(c);
    auto a = m.coords[n[0]], b = m.coords[n[1]], cc = m.coords[n[2]], d = m.coords[n[3]];
    double u[3], v[3], w[3];
    for (int i = 0; i < 3; ++i) u[i] = b[i] - a[i], v[i] = cc[i] - a[i], w[i] = d[i] - a[i];
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
            u[2] * (v[0] * w[1] - v[1] * w[0])) /
           6.0;
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const UserError& e) { return e.what(); } catch (const NotImplemented& e) {
        return std::string("NotImplemented: ") + e.what();
    }
    return "(no error)";
}

}  // namespace

TEST(MedReader, AstestQuad4MeshAsREADME) {
    const auto path = test::astest("ssnv511a.mmed");
    med::MeshReadReport rep;
    auto m = med::readMesh(path, "", &rep);
    EXPECT_EQ(rep.meshName, "MA");  // code_aster's own file (written by code_aster 11 from GIBI)
    EXPECT_EQ(m->dim, 2);
    EXPECT_EQ(m->nodeCount(), 36);
    EXPECT_EQ(countType(*m, CellType::QUAD4), 25);
    EXPECT_EQ(countType(*m, CellType::SEG2), 20);
    // SEG2 (102) come first in code_aster numbering (cells in file order, by MED type: lrmmma),
    // then QUAD4 (204); the names are the file's: the quadrangles are M1..M25.
    EXPECT_EQ(m->cellTypes.front(), CellType::SEG2);
    EXPECT_EQ(m->cellNames[0], "M26");
    EXPECT_EQ(m->cellNames[20], "M1");
    EXPECT_EQ(m->nodeNames[35], "N36");
    for (const char* g : {"LB", "LD", "LH", "LG"}) EXPECT_EQ(m->cellGroups.get(g).size(), 5u) << g;
    EXPECT_EQ(m->cellGroups.get("SURF").size(), 25u);
    EXPECT_EQ(m->cellGroups.get("MAILLE").size(), 25u);
    EXPECT_EQ(m->nodeGroups.size(), 4u);  // P1..P4, one corner node each
    for (const char* g : {"P1", "P2", "P3", "P4"}) EXPECT_EQ(m->nodeGroups.get(g).size(), 1u) << g;
    expectSameAsProbe(*m, path);
}

TEST(MedReader, AstestTria3Mesh) {
    const auto path = test::astest("ssnv511b.mmed");
    auto m = med::readMesh(path);
    EXPECT_EQ(m->nodeCount(), 38);
    EXPECT_EQ(countType(*m, CellType::TRIA3), 54);
    EXPECT_EQ(countType(*m, CellType::SEG2), 20);
    EXPECT_EQ(m->cellGroups.get("SURF").size(), 54u);
    expectSameAsProbe(*m, path);
}

TEST(MedReader, AstestHexa8MeshesAreLeftHanded) {
    for (const char* file : {"ssnv511c.mmed", "ssnv511g.mmed"}) {
        const auto path = test::astest(file);
        auto m = med::readMesh(path);
        EXPECT_EQ(m->dim, 3);
        EXPECT_EQ(m->nodeCount(), 72);
        EXPECT_EQ(countType(*m, CellType::HEXA8), 25);
        EXPECT_EQ(m->cellGroups.get("VOLU").size(), 25u);
        EXPECT_EQ(m->cellGroups.get("SD").size(), 5u);
        EXPECT_EQ(m->cellGroups.get("SG").size(), 5u);
        expectSameAsProbe(*m, path);
        // code_aster's own meshes: in its node order the tetra (1,2,4,5) of every hexahedron is
        // negative (left-handed cells, which code_aster integrates with |det J|).
        for (int c = 0; c < m->cellCount(); ++c) {
            if (m->cellTypes[c] != CellType::HEXA8) continue;
            auto n = m->cellNodes(c);
            Mesh t;
            for (int k : {0, 1, 3, 4}) t.addNode(m->coords[n[k]]);
            std::vector<int> tet{0, 1, 2, 3};
            t.addCell(CellType::TETRA4, tet);
            EXPECT_LT(signedVolumeTetra(t, 0), 0.0) << file << " cell " << c;
        }
    }
    auto g = med::readMesh(test::astest("ssnv511g.mmed"));
    EXPECT_EQ(countType(*g, CellType::QUAD4), 70);
    EXPECT_EQ(g->cellGroups.get("ENV").size(), 70u);
    auto c = med::readMesh(test::astest("ssnv511c.mmed"));
    EXPECT_EQ(countType(*c, CellType::QUAD4), 10);
}

TEST(MedReader, AstestTetra4MeshesArePositive) {
    for (const char* file : {"ssnv511d.mmed", "ssnv511h.mmed"}) {
        const auto path = test::astest(file);
        auto m = med::readMesh(path);
        EXPECT_EQ(m->nodeCount(), 76);
        EXPECT_EQ(countType(*m, CellType::TETRA4), 162);
        EXPECT_EQ(m->cellGroups.get("VOLU").size(), 162u);
        EXPECT_FALSE(m->nodeGroups.has("SD"));  // ssnv511d creates GROUP_NO SD/SG itself
        expectSameAsProbe(*m, path);
        for (int c = 0; c < m->cellCount(); ++c)
            if (m->cellTypes[c] == CellType::TETRA4) { EXPECT_GT(signedVolumeTetra(*m, c), 0.0) << file << c; }
    }
    auto h = med::readMesh(test::astest("ssnv511h.mmed"));
    EXPECT_EQ(countType(*h, CellType::TRIA3), 216);
    EXPECT_EQ(h->cellGroups.get("ENV").size(), 216u);
}

TEST(MedReader, QuadraticCellsAndMultiGroupFamiliesFromAnotherWriter) {
    const auto dir = test::scratchDir("med_mixed");
    const auto path = dir + "/mixed.med";
    test::runCommand("/usr/bin/python3 " + test::probeScript() + " write-mixed " + path);
    msg().setEcho(false);
    const int alarmsBefore = msg().alarmCount();
    auto m = med::readMesh(path);
    EXPECT_EQ(msg().alarmCount(), alarmsBefore + 1);  // the 29-character group name
    expectSameAsProbe(*m, path);

    ASSERT_EQ(m->cellCount(), 5);
    EXPECT_EQ(m->cellTypes[0], CellType::SEG3);
    EXPECT_EQ(m->cellTypes[1], CellType::SEG3);
    EXPECT_EQ(m->cellTypes[2], CellType::TRIA6);
    EXPECT_EQ(m->cellTypes[3], CellType::QUAD8);
    EXPECT_EQ(m->cellTypes[4], CellType::HEXA20);
    // HEXA20, internal order: bottom face counter-clockwise from +z, edges 9-12 bottom,
    // 13-16 vertical, 17-20 top (code_aster).
    auto h = m->cellNodes(4);
    auto X = [&](int k) { return m->coords[h[k]]; };
    auto isMid = [&](int mNode, int a, int b) {
        for (int d = 0; d < 3; ++d)
            if (std::abs(X(mNode)[d] - 0.5 * (X(a)[d] + X(b)[d])) > 1e-14) return false;
        return true;
    };
    const double cross = (X(1)[0] - X(0)[0]) * (X(3)[1] - X(0)[1]) - (X(1)[1] - X(0)[1]) * (X(3)[0] - X(0)[0]);
    EXPECT_GT(cross, 0.0);
    EXPECT_EQ(X(4)[2], 1.0);
    const int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5},
                              {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
    for (int e = 0; e < 12; ++e) EXPECT_TRUE(isMid(8 + e, edges[e][0], edges[e][1])) << "edge " << e;
    // 2D cells keep MED's order: QUAD8 mid-nodes follow the edges.
    auto q = m->cellNodes(3);
    for (int e = 0; e < 4; ++e)
        for (int d = 0; d < 3; ++d)
            EXPECT_DOUBLE_EQ(m->coords[q[4 + e]][d], 0.5 * (m->coords[q[e]][d] + m->coords[q[(e + 1) % 4]][d]));

    // Groups from multi-group families; a node group and a cell group share the name BAS.
    EXPECT_EQ(m->cellGroups.get("FACES"), (std::vector<int>{2, 3}));
    EXPECT_EQ(m->cellGroups.get("BAS"), (std::vector<int>{3}));
    EXPECT_EQ(m->cellGroups.get("TRI"), (std::vector<int>{2}));
    EXPECT_EQ(m->cellGroups.get("ARETES"), (std::vector<int>{0, 1}));
    EXPECT_TRUE(m->cellGroups.has("A_VERY_LONG_GROUP_NAME_O"));
    EXPECT_EQ(m->nodeGroups.get("ORIGINE").size(), 1u);
    EXPECT_EQ(m->nodeGroups.get("BAS").size(), 11u);
    // No names in a meshio file: generated like code_aster.
    EXPECT_EQ(m->nodeNames[0], "N1");
    EXPECT_EQ(m->cellNames[4], "M5");
    std::filesystem::remove_all(dir);
}

TEST(MedCellOrder, TablesArePermutationsAndRoundTrip) {
    for (CellType t :
         {CellType::TETRA4, CellType::TETRA10, CellType::PYRA5, CellType::PYRA13, CellType::PENTA6, CellType::PENTA15,
          CellType::PENTA18, CellType::HEXA8, CellType::HEXA20, CellType::HEXA27, CellType::QUAD9, CellType::SEG3}) {
        const int n = nodeCount(t);
        std::vector<int> med(n), internal(n), back(n);
        for (int i = 0; i < n; ++i) med[i] = 100 + i;
        med::medToInternal(t, med, internal);
        auto sorted = internal;
        std::sort(sorted.begin(), sorted.end());
        EXPECT_EQ(sorted, med) << cellTypeName(t);
        med::internalToMed(t, internal, back);
        EXPECT_EQ(back, med) << cellTypeName(t);
    }
    // The documented linear permutations (med_notes §7).
    auto order = [](CellType t) {
        auto s = med::medNodeOf(t);
        return std::vector<int>(s.begin(), s.end());
    };
    EXPECT_EQ(order(CellType::TETRA4), (std::vector<int>{0, 2, 1, 3}));
    EXPECT_EQ(order(CellType::PYRA5), (std::vector<int>{0, 3, 2, 1, 4}));
    EXPECT_EQ(order(CellType::PENTA6), (std::vector<int>{0, 2, 1, 3, 5, 4}));
    EXPECT_EQ(order(CellType::HEXA8), (std::vector<int>{0, 3, 2, 1, 4, 7, 6, 5}));
}

TEST(MedReader, BadInputIsAClearUserError) {
    const auto dir = test::scratchDir("med_bad");
    auto missing = dir + "/absent.med";
    EXPECT_EQ(errorOf([&] { med::readMesh(missing); }), "MED file '" + missing + "' does not exist");

    auto text = dir + "/text.med";
    std::ofstream(text) << "this is not a MED file\n";
    EXPECT_EQ(errorOf([&] { med::readMesh(text); }), "file '" + text + "' is not a MED file: it is not in HDF5 format");

    auto truncated = dir + "/truncated.med";
    std::filesystem::copy_file(test::astest("ssnv511g.mmed"), truncated);
    std::filesystem::resize_file(truncated, std::filesystem::file_size(truncated) / 2);
    auto err = errorOf([&] { med::readMesh(truncated); });
    EXPECT_EQ(err, "MED file '" + truncated + "' is damaged or truncated: HDF5 cannot open it");

    auto plainHdf5 = dir + "/plain.h5";
    test::runCommand("/usr/bin/python3 -c \"import h5py; f = h5py.File('" + plainHdf5 + "', 'w'); f['x'] = [1, 2]\"");
    EXPECT_EQ(errorOf([&] { med::readMesh(plainHdf5); }),
              "file '" + plainHdf5 + "' is an HDF5 file but not a MED file (no MED header /INFOS_GENERALES)");

    auto damaged = dir + "/damaged.med";
    std::filesystem::copy_file(test::astest("ssnv511a.mmed"), damaged);
    std::filesystem::permissions(damaged, std::filesystem::perms::owner_write, std::filesystem::perm_options::add);
    test::runCommand("/usr/bin/python3 -c \"import h5py; f = h5py.File('" + damaged +
                     "', 'r+'); del f['/ENS_MAA/MA/-0000000000000000001-0000000000000000001/MAI/QU4/NOD']\"");
    EXPECT_EQ(errorOf([&] { med::readMesh(damaged); }),
              "MED file '" + damaged +
                  "' is damaged or truncated: cannot read the connectivity of the QUAD4 cells "
                  "of mesh 'MA'");

    auto empty = dir + "/empty.med";
    {
        med::MedWriter w(empty, false);
        w.commit();
    }
    EXPECT_EQ(errorOf([&] { med::readMesh(empty); }), "MED file '" + empty + "' contains no mesh");

    EXPECT_EQ(errorOf([&] { med::readMesh(test::astest("ssnv511a.mmed"), "MAIL"); }),
              "NOM_MED='MAIL': MED file '" + test::astest("ssnv511a.mmed") +
                  "' has no mesh of that name; meshes in the file: 'MA'");
    std::filesystem::remove_all(dir);
}

TEST(MedReader, FirstMeshOrTheOneNamedByNomMed) {
    const auto dir = test::scratchDir("med_two");
    const auto path = dir + "/two.med";
    auto a = med::readMesh(test::astest("ssnv511a.mmed"));
    auto g = med::readMesh(test::astest("ssnv511g.mmed"));
    {
        med::MedWriter w(path, false);
        w.writeMesh(*a, "PLAN");
        w.writeMesh(*g, "VOLUME");
        w.commit();
    }
    EXPECT_EQ(med::meshNames(path), (std::vector<std::string>{"PLAN", "VOLUME"}));
    med::MeshReadReport rep;
    auto first = med::readMesh(path, "", &rep);
    EXPECT_EQ(rep.meshName, "PLAN");
    EXPECT_EQ(first->nodeCount(), 36);
    auto second = med::readMesh(path, "VOLUME", &rep);
    EXPECT_EQ(rep.meshName, "VOLUME");
    EXPECT_EQ(second->nodeCount(), 72);
    EXPECT_EQ(second->connectivity, g->connectivity);
    EXPECT_EQ(errorOf([&] { med::readMesh(path, "X"); }),
              "NOM_MED='X': MED file '" + path + "' has no mesh of that name; meshes in the file: 'PLAN', 'VOLUME'");
    std::filesystem::remove_all(dir);
}
