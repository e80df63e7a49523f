// LIRE_MAILLAGE FORMAT='ASTER' (.mail): every cell type on code_aster's reference elements, the
// layouts code_aster's lexer accepts, and each defect of a file reported with its line.
// (The .export unit and the .comm line in its errors, through the binary: tests/cli/mesh_aster_runs.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/Error.hpp"
#include "med_io/MedCellOrder.hpp"
#include "med_io/MedReader.hpp"
#include "med_io/MedWriter.hpp"
#include "med_test_support.hpp"
#include "mesh/AsterMeshReader.hpp"
#include "mesh/AsterMeshWriter.hpp"

using namespace ma;

namespace {

std::shared_ptr<Mesh> parse(const std::string& text, AsterMeshReport* report = nullptr) {
    std::istringstream in(text);
    return parseAsterMesh(in, "t.mail", report);
}

std::string errorOf(const std::string& text) {
    try {
        parse(text);
    } catch (const UserError& e) { return e.what(); }
    return "(no error)";
}

std::string projectCase(const std::string& file) { return std::string(MINIASTER_SOURCE_DIR) + "/astest/" + file; }

using Vec = std::array<double, 3>;
Vec mean(const std::vector<Vec>& v, const std::vector<int>& oneBased) {
    Vec g{0, 0, 0};
    for (int i : oneBased)
        for (int d = 0; d < 3; ++d) g[size_t(d)] += v[size_t(i - 1)][size_t(d)] / double(oneBased.size());
    return g;
}

// code_aster's local node order (elrfno reference vertices; mid-edge, face and centre nodes in
// the order of docs/mesh.md's table).
struct ReferenceCell {
    CellType type;
    std::vector<Vec> vertices;
    std::vector<std::vector<int>> extra;  // each extra node = mean of these vertices (1-based)
};

std::vector<ReferenceCell> referenceCells() {
    const std::vector<Vec> hex{{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                               {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    const std::vector<std::vector<int>> hexEdges{{1, 2}, {2, 3}, {3, 4}, {4, 1}, {1, 5}, {2, 6},
                                                 {3, 7}, {4, 8}, {5, 6}, {6, 7}, {7, 8}, {8, 5}};
    auto hex27 = hexEdges;
    for (std::vector<int> f : {std::vector<int>{1, 2, 3, 4},
                               {1, 2, 6, 5},
                               {2, 3, 7, 6},
                               {3, 4, 8, 7},
                               {4, 1, 5, 8},
                               {5, 6, 7, 8},
                               {1, 2, 3, 4, 5, 6, 7, 8}})
        hex27.push_back(f);
    const std::vector<Vec> tet{{0, 1, 0}, {0, 0, 1}, {0, 0, 0}, {1, 0, 0}};
    const std::vector<Vec> tri{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::vector<Vec> quad{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    const std::vector<std::vector<int>> quadEdges{{1, 2}, {2, 3}, {3, 4}, {4, 1}};
    auto quad9 = quadEdges;
    quad9.push_back({1, 2, 3, 4});
    return {
        {CellType::POI1, {{0, 0, 0}}, {}},
        {CellType::SEG2, {{-1, 0, 0}, {1, 0, 0}}, {}},
        {CellType::SEG3, {{-1, 0, 0}, {1, 0, 0}}, {{1, 2}}},
        {CellType::TRIA3, tri, {}},
        {CellType::QUAD4, quad, {}},
        {CellType::TRIA6, tri, {{1, 2}, {2, 3}, {3, 1}}},
        {CellType::QUAD8, quad, quadEdges},
        {CellType::QUAD9, quad, quad9},
        {CellType::TETRA4, tet, {}},
        {CellType::PYRA5, {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, 1}}, {}},
        {CellType::PENTA6, {{-1, 1, 0}, {-1, 0, 1}, {-1, 0, 0}, {1, 1, 0}, {1, 0, 1}, {1, 0, 0}}, {}},
        {CellType::HEXA8, hex, {}},
        {CellType::TETRA10, tet, {{1, 2}, {2, 3}, {3, 1}, {1, 4}, {2, 4}, {3, 4}}},
        {CellType::HEXA20, hex, hexEdges},
        {CellType::HEXA27, hex, hex27},
    };
}

bool meshioReads(CellType t) { return t != CellType::QUAD9 && t != CellType::HEXA27; }

// The mesh without the cell types meshio 1.x does not know, written to `path`.
std::string meshioReadable(const Mesh& m, const std::string& path) {
    Mesh copy;
    copy.dim = m.dim;
    copy.coords = m.coords;
    copy.nodeNames = m.nodeNames;
    for (int c = 0; c < m.cellCount(); ++c)
        if (meshioReads(m.cellTypes[size_t(c)]))
            copy.addCell(m.cellTypes[size_t(c)], m.cellNodes(c), m.cellNames[size_t(c)]);
    med::MedWriter w(path, false);
    w.writeMesh(copy, "CELLS");
    w.commit();
    return path;
}

}  // namespace

TEST(AsterMeshReader, EveryCellTypeOnItsReferenceElementInCodeAsterOrder) {
    AsterMeshReport report;
    auto m = readAsterMesh(projectCase("mesh_cells.mail"), &report);
    ASSERT_EQ(m->dim, 3);
    EXPECT_EQ(m->nodeCount(), 116);
    ASSERT_EQ(report.title.size(), 2u);
    EXPECT_EQ(report.title[0], " every cell type of LIRE_MAILLAGE FORMAT='ASTER', each on code_aster's reference");
    EXPECT_TRUE(report.alarms.empty());
    const auto cells = referenceCells();
    ASSERT_EQ(m->cellCount(), int(cells.size()));
    for (int c = 0; c < m->cellCount(); ++c) {
        const auto& ref = cells[size_t(c)];
        ASSERT_EQ(m->cellTypes[size_t(c)], ref.type) << c;
        auto nodes = m->cellNodes(c);
        ASSERT_EQ(int(nodes.size()), nodeCount(ref.type));
        std::vector<Vec> expected = ref.vertices;
        for (const auto& e : ref.extra) expected.push_back(mean(ref.vertices, e));
        for (size_t a = 0; a < nodes.size(); ++a) {
            const Vec x = m->coords[size_t(nodes[a])];
            EXPECT_EQ(x[0] - 4.0 * c, expected[a][0]) << cellTypeName(ref.type) << " node " << a + 1;
            EXPECT_EQ(x[1], expected[a][1]) << cellTypeName(ref.type) << " node " << a + 1;
            EXPECT_EQ(x[2], expected[a][2]) << cellTypeName(ref.type) << " node " << a + 1;
        }
    }
    EXPECT_EQ(m->cellNames[14], "MHS");
    EXPECT_EQ(m->nodeNames[size_t(m->cellNodes(14)[26])], "HS27");
    EXPECT_EQ(m->cellGroups.names(), (std::vector<std::string>{"VOLUMES", "FACES", "EDGES"}));
    EXPECT_EQ(m->cellGroups.get("VOLUMES").size(), 7u);
    EXPECT_EQ(m->cellGroups.get("EDGES"), (std::vector<int>{1, 2}));
    EXPECT_EQ(m->nodeGroups.names(), (std::vector<std::string>{"HEXA27_CENTRE", "Apex_of_the_pyramid", "ALL_POINTS"}));
    EXPECT_EQ(m->nodeGroups.get("HEXA27_CENTRE"), std::vector<int>{m->cellNodes(14)[26]});
}

// IMPR_RESU to MED is how a user converts a .mail: our MED reader and meshio must read the same
// mesh back, in MED's node order on the file.
TEST(AsterMeshReader, MedConversionReadsBackTheSameMesh) {
    auto m = readAsterMesh(projectCase("mesh_cells.mail"));
    const auto dir = test::scratchDir("aster_mesh_med");
    const std::string path = dir + "/cells.med";
    {
        med::MedWriter w(path, false);
        w.writeMesh(*m, "CELLS");
        w.commit();
    }
    auto back = med::readMesh(path);
    EXPECT_EQ(back->dim, m->dim);
    EXPECT_EQ(back->coords, m->coords);
    EXPECT_EQ(back->nodeNames, m->nodeNames);
    EXPECT_EQ(back->cellNames, m->cellNames);
    EXPECT_EQ(back->cellTypes, m->cellTypes);
    EXPECT_EQ(back->connectivity, m->connectivity);
    // MED stores a group as a set (families): members come back in entity order, groups in order
    // of their first entity. Same sets.
    auto sameGroups = [](const GroupSet& a, const GroupSet& b) {
        auto names = a.names(), other = b.names();
        std::sort(names.begin(), names.end());
        std::sort(other.begin(), other.end());
        EXPECT_EQ(names, other);
        for (const auto& g : a.names()) {
            auto x = a.get(g), y = b.get(g);
            std::sort(x.begin(), x.end());
            EXPECT_EQ(x, y) << g;
        }
    };
    sameGroups(m->cellGroups, back->cellGroups);
    sameGroups(m->nodeGroups, back->nodeGroups);
    // mdump4 (MED's own dump) sees one cell of each type.
    const std::string dump = test::runCommand("mdump4 '" + path + "' NODALE FULL_INTERLACE 0");
    for (const char* t : {"POINT1", "SEG2", "SEG3", "TRIA3", "QUAD4", "TRIA6", "QUAD8", "QUAD9", "TETRA4", "PYRA5",
                          "PENTA6", "HEXA8", "TETRA10", "HEXA20", "HEXA27"})
        EXPECT_NE(dump.find(std::string("- Nombre de mailles de type MED_") + t + " : 1 \n"), std::string::npos) << t;
    // meshio (no libmedC; QUAD9 and HEXA27 read with h5py): the file holds MED's node order,
    // the medNodeOf permutation of code_aster's order.
    const auto probe = test::probeMesh(meshioReadable(*m, dir + "/meshio.med"));
    size_t probed = 0;
    for (int c = 0; c < m->cellCount(); ++c) {
        const CellType t = m->cellTypes[size_t(c)];
        std::vector<int> row;
        if (!meshioReads(t)) {
            const std::string medName = t == CellType::QUAD9 ? "QU9" : "H27";
            std::istringstream in(
                test::runCommand("/usr/bin/python3 " + test::probeScript() + " rawconn '" + path + "' " + medName));
            for (int v; in >> v;) row.push_back(v - 1);
        } else {
            EXPECT_EQ(probe.cellType[probed], int(t));
            row = probe.cells[probed++];
        }
        std::vector<int> internal(row.size());
        med::medToInternal(t, row, internal);
        const auto expected = m->cellNodes(c);
        EXPECT_EQ(internal, std::vector<int>(expected.begin(), expected.end())) << cellTypeName(t);
    }
    std::filesystem::remove_all(dir);
}

// IMPR_RESU FORMAT='RESULTAT' / 'ASTER' writes a mesh as code_aster's irmare does; the reader
// gives back the same mesh: every cell type (HEXA27's 27 nodes on continuation lines), names,
// groups, and coordinates to the 15 digits of 1PE21.14.
TEST(AsterMeshWriter, TheReaderReadsBackTheSameMesh) {
    for (const std::string& path :
         {projectCase("mesh_cells.mail"), std::string(MINIASTER_SHARED_DIR) + "/astest/ssnv173d.mail"}) {
        auto m = readAsterMesh(path);
        m->coords[0][0] += 1.0 / 3.0;  // a value 1PE21.14 rounds
        AsterMeshReport report;
        const std::string text = asterMeshText(*m, {" a title line"});
        EXPECT_EQ(text.rfind(" TITRE\n a title line\n FINSF\n %\n COOR_", 0), 0u) << text;
        EXPECT_EQ(text.substr(text.size() - 5), " FIN\n");
        auto back = parse(text, &report);
        EXPECT_EQ(report.title, std::vector<std::string>{" a title line"});
        EXPECT_TRUE(report.alarms.empty());
        EXPECT_EQ(back->dim, m->dim) << path;
        EXPECT_EQ(back->nodeNames, m->nodeNames);
        EXPECT_EQ(back->cellNames, m->cellNames);
        EXPECT_EQ(back->cellTypes, m->cellTypes);
        EXPECT_EQ(back->cellOffsets, m->cellOffsets);
        EXPECT_EQ(back->connectivity, m->connectivity);
        ASSERT_EQ(back->coords.size(), m->coords.size());
        for (size_t n = 0; n < m->coords.size(); ++n)
            for (int j = 0; j < 3; ++j)
                EXPECT_NEAR(back->coords[n][size_t(j)], m->coords[n][size_t(j)],
                            5e-15 * std::max(1.0, std::abs(m->coords[n][size_t(j)])));
        EXPECT_EQ(back->nodeGroups.names(), m->nodeGroups.names());
        EXPECT_EQ(back->cellGroups.names(), m->cellGroups.names());
        for (const auto& g : m->nodeGroups.names()) EXPECT_EQ(back->nodeGroups.get(g), m->nodeGroups.get(g)) << g;
        for (const auto& g : m->cellGroups.names()) EXPECT_EQ(back->cellGroups.get(g), m->cellGroups.get(g)) << g;
    }
}

TEST(AsterMeshReader, FreeLayoutOfCodeAsterLexer) {
    AsterMeshReport report;
    auto m = parse(
        "% a comment line\n"
        "\n"
        " COOR_2D  % keyword after blanks\n"
        "A1 0 0\n"
        "A2 1.D+00, 0.      % D exponent, comma separator\n"
        "A3 10.D-1\n"       // record wrapped onto the next line
        "   2.E 0\n"        // blank between the exponent letter and its digits
        "A4 -.5 + 2.0e0\n"  // lone '+' is a separator
        "FINSF\n"
        "FINSF\n"  // a stray FINSF between blocks
        "TRIA3 NOM=IGNORED\n"
        "T_1 A1 A2\n"
        "    A3\n"
        "t2 A1 A3 A4\n"  // case kept
        "FINSF\n"
        "GROUP_MA NOM=ALL\n"
        "T_1 t2 T_1\n"  // repeated member: alarm, dropped
        "FINSF\n"
        "GROUP_NO\n"
        "corners A1 A2\n"
        " A3\n"
        "FINSF\n"
        "GROUP_NO NOM=NOTHING\n"  // empty group: alarm, not created
        "FINSF\n"
        "FIN\n"
        "after FIN: anything 1E5 #",
        &report);
    EXPECT_EQ(m->dim, 2);
    ASSERT_EQ(m->nodeCount(), 4);
    EXPECT_EQ(m->coords[1], (Vec{1, 0, 0}));
    EXPECT_EQ(m->coords[2], (Vec{1, 2, 0}));
    EXPECT_EQ(m->coords[3], (Vec{-0.5, 2, 0}));
    EXPECT_EQ(m->cellNames, (std::vector<std::string>{"T_1", "t2"}));
    EXPECT_EQ(m->connectivity, (std::vector<int>{0, 1, 2, 0, 2, 3}));
    EXPECT_EQ(m->cellGroups.get("ALL"), (std::vector<int>{0, 1}));
    EXPECT_EQ(m->nodeGroups.get("corners"), (std::vector<int>{0, 1, 2}));
    EXPECT_FALSE(m->nodeGroups.has("NOTHING"));
    ASSERT_EQ(report.alarms.size(), 2u);
    EXPECT_EQ(report.alarms[0].id, "MODELISA4_80");
    EXPECT_EQ(report.alarms[0].text, "mesh t.mail, line 23: GROUP_NO 'NOTHING' is empty and is not created");
    EXPECT_EQ(report.alarms[1].id, "MODELISA5_8");
    EXPECT_EQ(report.alarms[1].text,
              "mesh t.mail, line 17: 'T_1' is repeated in GROUP_MA 'ALL'; the repeat is dropped");
}

TEST(AsterMeshReader, NbligeHeaderLinesAndTitleLinesAreNotParsed) {
    AsterMeshReport report;
    auto m = parse(
        "TITRE ignored on the keyword line\n"
        " % kept verbatim, with 1E5 and #\n"
        "\n"
        "FINSF\n"
        "COOR_3D NOM=INDEFINI NBOBJ=1 NBLIGE=3\n"
        " 1E5 # header lines: skipped\n"
        " @ 2\n"
        "N1 1 2 3\n"
        "FINSF\n"
        "POI1\n"
        "P N1\n"
        "FIN\n",
        &report);
    EXPECT_EQ(report.title, (std::vector<std::string>{" % kept verbatim, with 1E5 and #", ""}));
    EXPECT_EQ(m->coords, (std::vector<Vec>{{1, 2, 3}}));
    EXPECT_EQ(m->cellTypes, std::vector<CellType>{CellType::POI1});
}

// Each defect: the message names the line where it is.
TEST(AsterMeshReader, DefectsAreReportedWithTheirLine) {
    const std::string nodes = "COOR_2D\nN1 0 0\nN2 1 0\nN3 0 1\nFINSF\n";  // lines 1-5
    auto expectError = [&](const std::string& body, const std::string& message) {
        EXPECT_EQ(errorOf(nodes + body), "mesh file 't.mail', " + message) << body;
    };
    // truncated files
    expectError("TRIA3\nM1 N1 N2 N3\n",
                "line 7: end of file inside the TRIA3 block begun at line 6 (no FINSF, no FIN): "
                "the file is truncated");
    expectError("TRIA3\nM1 N1 N2 N3\nFINSF\n", "line 8: end of file before the FIN line: the file is truncated");
    expectError("TRIA3\nM1 N1 N2\nFINSF\nFIN\n",
                "line 8: the record of 'M1' begun at line 7 ends before its node 3 of 3 (TRIA3) (FINSF found)");
    expectError("TRIA3\nM1 N1\n",
                "line 7: the record of 'M1' begun at line 7 ends before its node 2 of 3 (TRIA3) "
                "(end of file found)");
    // unknown cell type, lower-case keyword
    expectError(
        "TRIA4\nM1 N1 N2 N3 N1\nFINSF\nFIN\n",
        "line 6: 'TRIA4' is not a block keyword of a code_aster mesh file (TITRE, COOR_2D, COOR_3D, a cell type "
        "such as QUAD4 or HEXA20, GROUP_NO, GROUP_MA, FINSF, FIN; in upper case)");
    EXPECT_NE(errorOf(nodes + "tria3\nM1 N1 N2 N3\nFINSF\nFIN\n").find("line 6: 'tria3' is not a block keyword"),
              std::string::npos);
    // a node missing, a group naming an unknown cell or node
    expectError("TRIA3\nM1 N1 N2 N3\nM2 N1 N3 N4\nFINSF\nFIN\n",
                "line 8: cell M2 names node 'N4', which no COOR block defines");
    expectError("TRIA3\nM1 N1 N2 N3\nFINSF\nGROUP_MA\nG M1\n  M2\nFINSF\nFIN\n",
                "line 11: GROUP_MA 'G' names cell 'M2', which the file does not define");
    expectError("TRIA3\nM1 N1 N2 N3\nFINSF\nGROUP_NO NOM=G\nN1 M1\nFINSF\nFIN\n",
                "line 10: GROUP_NO 'G' names node 'M1', which the file does not define");
    // duplicates
    expectError("COOR_2D\nN2 5 5\nFINSF\nTRIA3\nM1 N1 N2 N3\nFINSF\nFIN\n",
                "line 7: node name 'N2' is already used at line 3");
    expectError("TRIA3\nM1 N1 N2 N3\nFINSF\nGROUP_MA\nG M1\nFINSF\nGROUP_MA NOM=G\nM1\nFINSF\nFIN\n",
                "line 12: GROUP_MA 'G' is defined twice");
    // records
    expectError(
        "TRIA3\nM1 N1 N2 N3 N1\nFINSF\nFIN\n",
        "line 7: 'N1' follows a complete record of the TRIA3 block (one record per line, each one starting its line)");
    expectError("TRIA3\nM1 N1 N2 3\nFINSF\nFIN\n",
                "line 7: '3' where node 3 of 3 (TRIA3) of cell M1 is expected (a node name)");
    expectError("TRIA3\nCELL_NAME N1 N2 N3\nFINSF\nFIN\n",
                "line 7: cell name 'CELL_NAME' has 9 characters: code_aster's node and cell names have at most 8");
    expectError("COOR_3D\nN9 0 0 0\nFINSF\nFIN\n",
                "line 6: COOR_3D after a COOR_2D block (line 1): a mesh has one space dimension");
    expectError("GROUP_MA\nFINSF\nFIN\n", "line 6: GROUP_MA block without a group name");
    // lexer
    expectError("COOR_2D\nN4 1E5 0\nFINSF\nFIN\n",
                "line 7: '1E5...': a number with an exponent needs a decimal point (write 1.E5, not 1E5)");
    expectError("COOR_2D\nN4 1.5 0 #\nFINSF\nFIN\n",
                "line 7: unexpected character '#' (names are a letter followed by letters, digits or '_')");
    expectError("COOR_2D\nN4 'x' 0\nFINSF\nFIN\n", "line 7: quoted text where a name or a number is expected");
    expectError("COOR_2D\nN4 1.5 0 \x89\nFINSF\nFIN\n",
                "line 7: unexpected character byte 0x89 (names are a letter followed by letters, digits or '_')");
    expectError("COOR_2D\nN4 1.5" + std::string(80, ' ') + "0\nFINSF\nFIN\n",
                "line 7: text beyond column 80 (code_aster reads columns 1 to 80 only and would drop it without a "
                "word): wrap the line");
    EXPECT_EQ(errorOf("FIN\n"), "mesh file 't.mail', line 1: the file defines no node (no COOR_2D or COOR_3D block)");
    expectError("FIN\n", "line 6: the file defines no cell (no cell block such as QUAD4)");
    EXPECT_EQ(errorOf(""), "mesh file 't.mail', line 1: the file is empty");
}

// A MED file given where a .mail is expected is named as such, not lexed as text.
TEST(AsterMeshReader, AMedFileIsNotReadAsText) {
    const std::string med = test::astest("ssnv511a.mmed");
    std::string what = "(no error)";
    try {
        readAsterMesh(med);
    } catch (const UserError& e) { what = e.what(); }
    EXPECT_EQ(what, "mesh file '" + med +
                        "' is a MED (HDF5) file, not a code_aster text mesh: read it with "
                        "LIRE_MAILLAGE(FORMAT='MED')");
}
