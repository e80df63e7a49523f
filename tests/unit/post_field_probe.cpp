// TEST_RESU's value selection (post/FieldProbe) and the checks it shares with TEST_TABLE
// (post/TestCheck runChecks): a nodal field whose nodes carry different components (X-FEM: H1X only
// on the enriched nodes) and a field at integration points with elements of different point counts.
#include <gtest/gtest.h>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "core/TestReport.hpp"
#include "post/FieldProbe.hpp"

using namespace ma;

namespace {

std::shared_ptr<Mesh> threeNodes() {
    auto mesh = std::make_shared<Mesh>();
    mesh->name = "MA";
    for (int i = 0; i < 3; ++i) mesh->addNode({double(i), 0.0, 0.0});
    const int nodes[] = {0, 1, 2};
    mesh->addCell(CellType::TRIA3, nodes);
    mesh->addCell(CellType::TRIA3, nodes);
    return mesh;
}

// DX at every node, H1X at the second one only.
NodalField enrichedField() {
    NodalField f;
    f.mesh = threeNodes();
    f.resize(f.mesh, {"DX", "DY", "H1X"});
    f.set(0, 0, -0.25);
    f.set(1, 0, 0.5);
    f.set(2, 0, -1.0);
    f.set(1, 2, 3.0);
    f.at(0, 2) = 100.0;  // not carried: never read
    return f;
}

// Two elements, 1 and 3 points, components SIXX, SIYY.
GaussField gaussField() {
    GaussField f;
    f.mesh = threeNodes();
    f.components = {"SIXX", "SIYY"};
    f.cells = {1, 0};
    f.pointOffsets = {0, 1, 4};
    f.pointWeights.assign(4, 1.0);
    f.values = {1.0, -2.0, 3.0, 4.0, -5.0, 6.0, 7.0, -8.0};
    return f;
}

}  // namespace

TEST(FieldProbe, NodalValueNeedsTheComponentAtTheNode) {
    const NodalField f = enrichedField();
    EXPECT_EQ(nodalValue(f, 1, "DX", "RESU[1]"), 0.5);
    EXPECT_EQ(nodalValue(f, 1, "H1X", "RESU[1]"), 3.0);
    EXPECT_THROW(nodalValue(f, 0, "H1X", "RESU[1]"), UserError);  // N1 is not enriched
    EXPECT_THROW(nodalValue(f, 0, "DZ", "RESU[1]"), UserError);
    EXPECT_THROW(nodalValue(f, 0, "DY", "RESU[1]"), UserError);  // DY is set nowhere
}

TEST(FieldProbe, ReductionsOverWhatTheNodesCarry) {
    const NodalField f = enrichedField();
    EXPECT_EQ(reduceField(f, Reduction::Min, std::string("DX"), "w"), -1.0);
    EXPECT_EQ(reduceField(f, Reduction::Max, std::string("DX"), "w"), 0.5);
    EXPECT_EQ(reduceField(f, Reduction::Sum, std::string("DX"), "w"), -0.75);
    EXPECT_EQ(reduceField(f, Reduction::SumAbs, std::string("DX"), "w"), 1.75);
    EXPECT_EQ(reduceField(f, Reduction::SumAbs, std::nullopt, "w"), 4.75);  // H1X of N2 only
    EXPECT_EQ(reduceField(f, Reduction::Max, std::nullopt, "w"), 3.0);
    EXPECT_THROW(reduceField(f, Reduction::Max, std::string("DY"), "w"), UserError);  // no value
    EXPECT_EQ(reduceField(f, Reduction::Sum, std::string("DY"), "w"), 0.0);
}

TEST(FieldProbe, GaussPointsOfTheElementOnTheCell) {
    const GaussField f = gaussField();
    EXPECT_EQ(gaussValue(f, 1, 1, "SIYY", "w"), -2.0);  // cell M2: element 0, one point
    EXPECT_EQ(gaussValue(f, 0, 3, "SIXX", "w"), 7.0);   // cell M1: element 1, its third point
    EXPECT_THROW(gaussValue(f, 0, 4, "SIXX", "w"), UserError);
    EXPECT_THROW(gaussValue(f, 0, 0, "SIXX", "w"), UserError);
    EXPECT_THROW(gaussValue(f, 0, 1, "SIZZ", "w"), UserError);
    EXPECT_EQ(reduceField(f, Reduction::Sum, std::string("SIXX"), "w"), 1.0 + 3.0 - 5.0 + 7.0);
    EXPECT_EQ(reduceField(f, Reduction::Min, std::nullopt, "w"), -8.0);
    EXPECT_EQ(reduceField(f, Reduction::SumAbs, std::nullopt, "w"), 36.0);
}

// runChecks prints the label line and the NON_REGRESSION / reference lines, and records them with
// the caller's description.
TEST(FieldProbe, ChecksOfATestedValue) {
    msg().setEcho(false);
    msg().reset();
    testReport().reset();
    TestChecks checks;
    checks.calc = {Cell(0.5)};
    checks.refe = {Cell(0.6)};
    checks.reference = "ANALYTIQUE";
    checks.precision = 1e-3;
    checks.where = "TEST_RESU (t.comm line 3)";
    const auto lines = runChecks(checks, checkScale(checks), Cell(0.5), true, "RESULTAT=U NOM_CMP=DX");
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0].status, TestLine::Status::Ok);
    EXPECT_EQ(lines[1].status, TestLine::Status::Nook);
    EXPECT_EQ(lines[1].description.rfind("RESULTAT=U NOM_CMP=DX: computed 0.5, expected 0.6", 0), 0u)
        << lines[1].description;
    const std::string text = msg().resuText();
    EXPECT_NE(text.find("\n OK   NON_REGRESSION   XXXX             0.5                0.5 "), std::string::npos)
        << text;
    EXPECT_NE(text.find("\nNOOK  ANALYTIQUE       XXXX             0.6                0.5 "), std::string::npos)
        << text;
    EXPECT_EQ(testReport().nookCount(), 1);
}
