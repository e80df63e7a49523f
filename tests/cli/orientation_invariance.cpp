// Reversed cells change nothing: the ssnv511 originals (no contact: a-d, contact: e-h) on a
// generated mesh and on the same mesh with a random half of its volume cells numbered the other
// way (left-handed volumes, clockwise 2D cells) give the same fields to round-off: the nodal
// displacement, the Heaviside enrichment of every node, and every value the .comm tests (the
// displacement on both sides of the interfaces, from POST_CHAM_XFEM). The interfaces cut cells
// (offset grid), so reversed cut cells, their sub-cells and contact facets are among them.
//
// A node's Heaviside slots are numbered by the order in which its domains first appear in its
// cells' sub-cells (code_aster's order, docs/xfem.md), and a reversed cell cuts into other
// sub-cells: at a junction node the same enrichments may come in another slot order, so they are
// compared as a set per direction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

#include "med_io/MedWriter.hpp"
#include "med_test_support.hpp"
#include "parser_run.hpp"
#include "scenes/Ssnv511Mesh.hpp"

using namespace ma;
using Kind = Ssnv511MeshOptions::Kind;

namespace {

// A node permutation that turns the cell inside out (mirror numbering).
std::vector<int> mirrored(CellType type) {
    switch (type) {
        case CellType::TRIA3: return {0, 2, 1};
        case CellType::QUAD4: return {0, 3, 2, 1};
        case CellType::TETRA4: return {0, 2, 1, 3};
        case CellType::HEXA8: return {0, 3, 2, 1, 4, 7, 6, 5};
        default: return {};
    }
}

// Reverses about half of the volume cells (fixed seed); returns how many.
int reverseHalf(Mesh& mesh, int dim) {
    std::mt19937 rng(20261203);
    int reversed = 0;
    for (int c = 0; c < mesh.cellCount(); ++c) {
        const auto order = mirrored(mesh.cellTypes[c]);
        if (order.empty() || cellDimension(mesh.cellTypes[c]) != dim || rng() % 2 == 0) continue;
        auto nodes = mesh.cellNodes(c);
        const std::vector<int> old(nodes.begin(), nodes.end());
        for (size_t k = 0; k < order.size(); ++k) mesh.connectivity[mesh.cellOffsets[c] + k] = old[order[k]];
        ++reversed;
    }
    return reversed;
}

void writeMesh(const Mesh& mesh, const std::string& path) {
    med::MedWriter w(path, false);
    w.writeMesh(mesh, "MA");
    w.commit();
}

std::string withDisplacementOutput(const std::string& original) {
    std::ifstream in(test::astest(original));
    std::stringstream text;
    text << in.rdbuf();
    std::string comm = text.str();
    const auto fin = comm.rfind("FIN(");
    const bool steps = comm.find("STAT_NON_LINE") != std::string::npos;
    comm.insert(fin, std::string("IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(RESULTAT=UTOT1, NOM_CHAM='DEPL'") +
                         (steps ? ", INST=1.0" : "") + "))\n");
    return comm;
}

// The computed values of the TEST lines of a .resu, in order.
std::vector<double> testedValues(const std::string& resu) {
    std::vector<double> out;
    std::istringstream in(resu);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string status, kind, legend, reference, computed;
        if (!(words >> status >> kind >> legend >> reference >> computed) || (status != "OK" && status != "NOOK"))
            continue;
        out.push_back(std::stod(computed));
    }
    return out;
}

// Largest difference of the nodal fields: the displacement (first `dim` components) as it is,
// the Heaviside slots (then `dim` components each) as a set per direction.
double fieldDifference(const std::vector<std::vector<double>>& a, const std::vector<std::vector<double>>& b, int dim) {
    double diff = 0.0;
    for (size_t n = 0; n < a.size(); ++n) {
        EXPECT_EQ(a[n].size(), b[n].size());
        const size_t slots = (a[n].size() - size_t(dim)) / size_t(dim);
        for (int j = 0; j < dim; ++j) {
            diff = std::max(diff, std::abs(a[n][size_t(j)] - b[n][size_t(j)]));
            std::vector<double> ha, hb;
            for (size_t k = 1; k <= slots; ++k)
                ha.push_back(a[n][k * size_t(dim) + size_t(j)]), hb.push_back(b[n][k * size_t(dim) + size_t(j)]);
            std::sort(ha.begin(), ha.end());
            std::sort(hb.begin(), hb.end());
            for (size_t k = 0; k < ha.size(); ++k) diff = std::max(diff, std::abs(ha[k] - hb[k]));
        }
    }
    return diff;
}

struct Case {
    Kind kind;
    int dim;
    const char* comm;
};

class OrientationInvariance : public ::testing::TestWithParam<Case> {};

TEST_P(OrientationInvariance, SameFieldsWithHalfTheCellsReversed) {
    const Case c = GetParam();
    Ssnv511MeshOptions o;
    o.kind = c.kind;
    o.divisions = 7;
    o.offsetX = o.offsetY = 0.2;
    auto mesh = buildSsnv511Mesh(o);
    const auto dir = test::freshDir();
    writeMesh(*mesh, (dir / "right.med").string());
    const int reversed = reverseHalf(*mesh, c.dim);
    writeMesh(*mesh, (dir / "mixed.med").string());
    test::writeText(dir / "t.comm", withDisplacementOutput(c.comm));

    std::vector<std::vector<double>> fields[2];
    std::vector<double> tested[2];
    for (int k = 0; k < 2; ++k) {
        const std::string meshFile = k == 0 ? "right.med" : "mixed.med";
        const auto r = test::runMiniaster(dir, "t.comm", "--mesh " + meshFile);
        // The references are exact on any mesh; e-h's non-regression values are code_aster's.
        EXPECT_TRUE(r.status == 0 || r.status == 2) << r.output;
        const std::string mess = r.file("out/t.mess");
        EXPECT_NE(mess.find("reference checks OK"), std::string::npos) << mess.substr(mess.size() - 2000);
        const bool alarm = mess.find("<MAILLAGE_ORIENTATION>") != std::string::npos;
        EXPECT_EQ(alarm, k == 1) << meshFile;
        if (k == 1) {
            EXPECT_NE(mess.find(std::to_string(reversed) + " cells are " + (c.dim == 3 ? "left-handed" : "clockwise")),
                      std::string::npos);
        }
        fields[k] = test::probeField((dir / "out" / "fort.80").string(), "UTOT1___DEPL");
        tested[k] = testedValues(r.file("out/t.resu"));
        std::filesystem::rename(dir / "out", dir / ("out_" + meshFile));
    }
    ASSERT_EQ(fields[0].size(), fields[1].size());
    ASSERT_FALSE(fields[0].empty());
    double scale = 0.0;
    for (const auto& row : fields[0])
        for (double v : row) scale = std::max(scale, std::abs(v));
    EXPECT_GT(scale, 0.1);
    EXPECT_LE(fieldDifference(fields[0], fields[1], c.dim), 1e-11 * scale)
        << c.comm << ": " << reversed << " cells reversed";
    ASSERT_EQ(tested[0].size(), tested[1].size());
    EXPECT_GE(tested[0].size(), 18u);
    for (size_t t = 0; t < tested[0].size(); ++t)
        EXPECT_NEAR(tested[0][t], tested[1][t], 1e-11 * std::max(scale, std::abs(tested[0][t])))
            << c.comm << " TEST line " << t + 1;
    EXPECT_GT(reversed, 0);
}

INSTANTIATE_TEST_SUITE_P(Ssnv511, OrientationInvariance,
                         ::testing::Values(Case{Kind::Quad4, 2, "ssnv511a.comm"}, Case{Kind::Tria3, 2, "ssnv511b.comm"},
                                           Case{Kind::Hexa8, 3, "ssnv511c.comm"},
                                           Case{Kind::Tetra4, 3, "ssnv511d.comm"},
                                           Case{Kind::Quad4, 2, "ssnv511e.comm"}, Case{Kind::Tria3, 2, "ssnv511f.comm"},
                                           Case{Kind::Hexa8, 3, "ssnv511g.comm"},
                                           Case{Kind::Tetra4, 3, "ssnv511h.comm"}),
                         [](const auto& testInfo) { return std::string(testInfo.param.comm).substr(0, 8); });

}  // namespace
