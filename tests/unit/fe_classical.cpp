// The fixed-size classical element path (fe/ClassicalElement.hpp) gives the same bits as the
// general path (classicalIntegration + computePointGeometry) on distorted cells of every type,
// and reports an inverted cell with the same message. The threaded pattern and assembly give the
// same bits with 1, 2 and 3 threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/Error.hpp"
#include "fe/ClassicalElement.hpp"
#include "fe/ElementKinematics.hpp"
#include "fe/MechanicalProblem.hpp"
#include "fe/Parallel.hpp"
#include "fe_test_support.hpp"

using namespace ma;

namespace {

// A cell of `type` made from its reference nodes, scaled, sheared and perturbed node by node.
Mesh distortedCell(CellType type, double seed) {
    Mesh mesh;
    mesh.dim = referenceDimension(type);
    std::vector<int> nodes;
    int i = 0;
    for (const auto& xi : referenceNodes(type)) {
        const double px = 0.07 * std::sin(seed + 1.3 * i), py = 0.05 * std::cos(seed + 2.1 * i),
                     pz = 0.04 * std::sin(seed * 0.7 + 0.9 * i);
        std::array<double, 3> x{1.7 * xi[0] + 0.3 * xi[1] + px + 10.0, 0.9 * xi[1] - 0.2 * xi[0] + py - 3.0,
                                mesh.dim == 3 ? 1.1 * xi[2] + 0.1 * xi[0] + pz + 0.5 : 0.0};
        nodes.push_back(mesh.addNode(x));
        ++i;
    }
    mesh.addCell(type, nodes);
    return mesh;
}

template <class Ref>
void expectSameBits(const Ref& ref, CellType type) {
    for (double seed : {0.0, 0.37, 1.9, 4.2}) {
        const Mesh mesh = distortedCell(type, seed);
        ElementIntegration ei;
        classicalIntegration(mesh, 0, false, ei);
        PointGeometry geo;
        computePointGeometry(mesh, 0, Ref::dim, false, ei, geo);
        classical::Geometry<Ref> g;
        classical::computeGeometry(ref, mesh, 0, g);
        ASSERT_EQ(int(ei.refPoints.size()), Ref::points) << cellTypeName(type);
        for (int p = 0; p < Ref::points; ++p) {
            EXPECT_EQ(g.weight[p], geo.weight[p]) << cellTypeName(type) << " point " << p;
            EXPECT_GT(g.weight[p], 0.0);
            for (int i = 0; i < 3; ++i) EXPECT_EQ(g.xyz[p][i], geo.xyz[p][i]);
            EXPECT_EQ(ref.point[p], ei.refPoints[p]);
            for (int a = 0; a < Ref::nodes; ++a) {
                EXPECT_EQ(ref.N[p][a], geo.N[p * Ref::nodes + a]);
                for (int j = 0; j < Ref::dim; ++j)
                    EXPECT_EQ(g.grad[p][a][j], geo.gradN[(p * Ref::nodes + a) * 3 + j])
                        << cellTypeName(type) << " point " << p << " node " << a << " direction " << j;
            }
        }
    }
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const NumericalError& e) { return e.what(); }
    return "no error";
}

}  // namespace

TEST(FeClassical, FixedSizeGeometryHasTheGeneralPathsBits) {
    expectSameBits(classical::tria3(), CellType::TRIA3);
    expectSameBits(classical::quad4(), CellType::QUAD4);
    expectSameBits(classical::tetra4(), CellType::TETRA4);
    expectSameBits(classical::hexa8(), CellType::HEXA8);
}

TEST(FeClassical, DispatchCoversTheModelDimensionsOnly) {
    int seen = 0;
    auto count = [&](const auto& ref) { seen += ref.points; };
    EXPECT_TRUE(classical::dispatch(CellType::QUAD4, 2, count));
    EXPECT_TRUE(classical::dispatch(CellType::TRIA3, 2, count));
    EXPECT_TRUE(classical::dispatch(CellType::HEXA8, 3, count));
    EXPECT_TRUE(classical::dispatch(CellType::TETRA4, 3, count));
    EXPECT_EQ(seen, 4 + 1 + 8 + 1);
    EXPECT_FALSE(classical::dispatch(CellType::QUAD4, 3, count));  // a face in a 3D model
    EXPECT_FALSE(classical::dispatch(CellType::SEG2, 2, count));   // a skin cell
    EXPECT_FALSE(classical::dispatch(CellType::QUAD8, 2, count));  // no element for it
    EXPECT_EQ(seen, 14);
}

// A clockwise cell is the same element as its counter-clockwise numbering (|det J|, code_aster's
// dfdm2d): the same weights and, node for node, the same gradients, on both paths.
TEST(FeClassical, ClockwiseCellIsTheSameElement) {
    Mesh mesh;
    mesh.dim = 2;
    for (const auto& x : {std::array<double, 3>{0, 0, 0}, {0.2, 1.1, 0}, {1.3, 0.9, 0}, {1, -0.1, 0}}) mesh.addNode(x);
    mesh.addCell(CellType::QUAD4, std::vector<int>{0, 1, 2, 3});  // clockwise: negative Jacobian
    mesh.addCell(CellType::QUAD4, std::vector<int>{0, 3, 2, 1});  // the same cell, counter-clockwise
    classical::Geometry<classical::Quad4> g[2];
    PointGeometry geo[2];
    for (int c = 0; c < 2; ++c) {
        classical::computeGeometry(classical::quad4(), mesh, c, g[c]);
        ElementIntegration ei;
        classicalIntegration(mesh, c, false, ei);
        computePointGeometry(mesh, c, 2, false, ei, geo[c]);
    }
    const int nodeOf[2][4] = {{0, 1, 2, 3}, {0, 3, 2, 1}};
    double area[2] = {0, 0};
    for (int c = 0; c < 2; ++c)
        for (int p = 0; p < 4; ++p) {
            EXPECT_GT(g[c].weight[p], 0.0);
            EXPECT_EQ(g[c].weight[p], geo[c].weight[p]);
            area[c] += g[c].weight[p];
        }
    EXPECT_NEAR(area[0], area[1], 1e-15);
    EXPECT_NEAR(area[0], 1.14, 1e-14);  // shoelace formula of the four corners
    // Gradients of the same node at the same physical point: point p of cell 0 is, in cell 1's
    // reference frame, the point with xi and eta swapped (rule points are symmetric).
    for (int p = 0; p < 4; ++p) {
        int q = -1;
        for (int k = 0; k < 4; ++k)
            if (std::abs(g[1].xyz[k][0] - g[0].xyz[p][0]) < 1e-14 && std::abs(g[1].xyz[k][1] - g[0].xyz[p][1]) < 1e-14)
                q = k;
        ASSERT_GE(q, 0);
        EXPECT_NEAR(g[0].weight[p], g[1].weight[q], 1e-15);
        for (int a = 0; a < 4; ++a)
            for (int b = 0; b < 4; ++b)
                if (nodeOf[0][a] == nodeOf[1][b]) {
                    for (int i = 0; i < 2; ++i) EXPECT_NEAR(g[0].grad[p][a][i], g[1].grad[q][b][i], 1e-14);
                }
    }
}

// A degenerate cell (its nodes aligned: det J round-off for its size) is an error naming the
// cell, the same on both paths; a thin but well-shaped one is not.
TEST(FeClassical, DegenerateCellIsReportedAsByTheGeneralPath) {
    Mesh mesh;
    mesh.dim = 2;
    for (const auto& x :
         {std::array<double, 3>{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 1e-20, 0}, {0, 1e-9, 0}, {1, 1e-9, 0}})
        mesh.addNode(x);
    mesh.addCell(CellType::QUAD4, std::vector<int>{0, 1, 2, 3});  // flat: aligned nodes
    mesh.addCell(CellType::QUAD4, std::vector<int>{0, 1, 5, 4});  // 1 x 1e-9: thin, not degenerate
    ElementIntegration ei;
    classicalIntegration(mesh, 0, false, ei);
    PointGeometry geo;
    const std::string general = errorOf([&] { computePointGeometry(mesh, 0, 2, false, ei, geo); });
    classical::Geometry<classical::Quad4> g;
    const std::string fixed = errorOf([&] { classical::computeGeometry(classical::quad4(), mesh, 0, g); });
    EXPECT_EQ(fixed, general);
    EXPECT_EQ(fixed.substr(0, 45), "cell M1 (QUAD4) is degenerate: its Jacobian (") << fixed;
    EXPECT_EQ(errorOf([&] { classical::computeGeometry(classical::quad4(), mesh, 1, g); }), "no error");
    double area = 0.0;
    for (double w : g.weight) area += w;
    EXPECT_NEAR(area, 1e-9, 1e-24);
}

TEST(FeClassical, ThreadsDoNotChangeABit) {
    using namespace fetest;
    msg().setEcho(false);
    auto mesh = planeMesh(130, 130, false);  // 16900 QUAD4: several assembly batches
    auto model = affeModele(mesh, "D_PLAN", {"ALL", "RIGHT", "TOP"});
    auto mat = material(model, 2.0e5, 0.3);
    KeywordSet kw;
    set(kw, "MODELE", model);
    auto& d = kw.addOccurrence("DDL_IMPO");
    setTexts(d, "GROUP_MA", {"LEFT"});
    set(d, "DX", ConceptPtr(std::make_shared<LambdaFunction>([](double, double, double) { return 0.0; })));
    set(d, "DY", ConceptPtr(std::make_shared<LambdaFunction>([](double, double y, double) { return 1e-3 * y * y; })));
    auto& p = kw.addOccurrence("PRES_REP");
    setTexts(p, "GROUP_MA", {"RIGHT", "TOP"});
    set(p, "PRES",
        ConceptPtr(std::make_shared<LambdaFunction>([](double x, double y, double) { return 10.0 * y - x; })));
    auto& f = kw.addOccurrence("FORCE_INTERNE");
    set(f, "TOUT", std::string("OUI"));
    set(f, "FX",
        ConceptPtr(std::make_shared<LambdaFunction>([](double x, double y, double) { return std::sin(x * y); })));
    set(f, "FY", ConceptPtr(std::make_shared<LambdaFunction>([](double, double, double) { return -2.0; })));
    auto load = std::dynamic_pointer_cast<MechanicalLoad>(run("AFFE_CHAR_MECA_F", kw, "CHAR"));
    SolverOptions eigen;
    eigen.method = "LDLT";  // deterministic ordering: differences can only come from the assembly
    std::vector<double> u[3], fint[3];
    std::vector<double> sigma[3];
    for (int threads : {1, 2, 3}) {
        setWorkerCount(threads);
        MechanicalProblem problem(model, mat, {{load, nullptr}}, eigen);
        ConvergenceOptions conv;
        conv.maxIterations = 0;
        conv.resiGlobRela = -1.0;
        problem.solveIncrement(0.0, conv);
        u[threads - 1] = problem.state();
        problem.internalForces(problem.state(), fint[threads - 1]);
        sigma[threads - 1] = problem.stressField()->values;
    }
    setWorkerCount(0);
    double umax = 0.0;
    for (double v : u[0]) umax = std::max(umax, std::abs(v));
    EXPECT_GT(umax, 1e-4);
    for (int t : {1, 2}) {
        EXPECT_EQ(u[t], u[0]) << t + 1 << " threads";
        EXPECT_EQ(fint[t], fint[0]) << t + 1 << " threads";
        EXPECT_EQ(sigma[t], sigma[0]) << t + 1 << " threads";
    }
}

// Degenerate cells in both workers' shares of a batch: the error names the first one in element
// order, as the serial loop does, whatever the number of threads.
TEST(FeClassical, ThreadedLoopsReportTheFirstBadElement) {
    using namespace fetest;
    msg().setEcho(false);
    auto mesh = planeMesh(100, 100, false);  // 10000 QUAD4: two workers when 2 threads are allowed
    for (int cell : {7000, 5000}) {          // collapse two cells onto their first edge: zero Jacobians
        auto* nodes = mesh->connectivity.data() + mesh->cellOffsets[cell];
        nodes[2] = nodes[1], nodes[3] = nodes[0];
    }
    auto model = affeModele(mesh, "D_PLAN", {"ALL"});
    auto mat = material(model, 2.0e5, 0.3);
    KeywordSet kw;
    set(kw, "MODELE", model);
    auto& d = kw.addOccurrence("DDL_IMPO");
    setTexts(d, "GROUP_MA", {"LEFT"});
    set(d, "DX", ConceptPtr(std::make_shared<LambdaFunction>([](double, double, double) { return 0.0; })));
    set(d, "DY", ConceptPtr(std::make_shared<LambdaFunction>([](double, double, double) { return 0.0; })));
    auto load = std::dynamic_pointer_cast<MechanicalLoad>(run("AFFE_CHAR_MECA_F", kw, "CHAR"));
    for (int threads : {1, 2}) {
        setWorkerCount(threads);
        MechanicalProblem problem(model, mat, {{load, nullptr}}, SolverOptions{});
        ConvergenceOptions conv;
        conv.maxIterations = 0;
        conv.resiGlobRela = -1.0;
        try {
            problem.solveIncrement(0.0, conv);
            ADD_FAILURE() << threads << " thread(s): no error";
        } catch (const NumericalError& e) {
            EXPECT_EQ(std::string(e.what()).substr(0, 33), "cell M5001 (QUAD4) is degenerate:") << threads;
        }
    }
    setWorkerCount(0);
}

namespace {

// A 2 x 2 plate clamped on its left, pressed on its right: the stress field of one solve of `model`.
std::shared_ptr<GaussField> solvedStress(const std::shared_ptr<Model>& model) {
    using namespace fetest;
    auto mat = material(model, 2.0e5, 0.3);
    KeywordSet kw;
    set(kw, "MODELE", model);
    auto& d = kw.addOccurrence("DDL_IMPO");
    setTexts(d, "GROUP_MA", {"LEFT"});
    const auto zero = ConceptPtr(std::make_shared<LambdaFunction>([](double, double, double) { return 0.0; }));
    set(d, "DX", zero);
    set(d, "DY", zero);
    auto& p = kw.addOccurrence("PRES_REP");
    setTexts(p, "GROUP_MA", {"RIGHT"});
    set(p, "PRES", ConceptPtr(std::make_shared<LambdaFunction>([](double, double y, double) { return y; })));
    auto load = std::dynamic_pointer_cast<MechanicalLoad>(run("AFFE_CHAR_MECA_F", kw, "CHAR"));
    SolverOptions eigen;
    eigen.method = "LDLT";
    MechanicalProblem problem(model, mat, {{load, nullptr}}, eigen);
    ConvergenceOptions conv;
    conv.maxIterations = 0;
    conv.resiGlobRela = -1.0;
    problem.solveIncrement(0.0, conv);
    return problem.stressField();
}

double pointArea(const GaussField& f) {
    double a = 0.0;
    for (double w : f.pointWeights) a += w;
    return a;
}

bool sameGeometryStorage(const GaussField& a, const GaussField& b) {
    return a.pointCoords.watch().lock() == b.pointCoords.watch().lock() &&
           a.pointWeights.watch().lock() == b.pointWeights.watch().lock() &&
           a.pointSubcell.watch().lock() == b.pointSubcell.watch().lock() &&
           a.pointRefCoords.watch().lock() == b.pointRefCoords.watch().lock();
}

}  // namespace

// Successive stress fields of a model on the same points share one copy of their point geometry
// (ssnv185c's three results); after its mesh moved (as many points elsewhere) a field keeps its
// own, and the first is untouched.
TEST(FeClassical, StressFieldsShareThePointGeometryOfTheSamePointsOnly) {
    using namespace fetest;
    msg().setEcho(false);
    auto mesh = planeMesh(6, 6, false, 2.0);
    auto model = affeModele(mesh, "D_PLAN", {"ALL", "RIGHT"});
    const auto first = solvedStress(model);
    const auto again = solvedStress(model);
    EXPECT_TRUE(sameGeometryStorage(*first, *again));
    for (auto& x : mesh->coords) x = {1.5 * x[0], 1.5 * x[1], x[2]};
    const auto elsewhere = solvedStress(model);
    ASSERT_EQ(elsewhere->pointCount(), first->pointCount());
    EXPECT_NE(elsewhere->pointCoords.watch().lock(), first->pointCoords.watch().lock());
    EXPECT_NEAR(pointArea(*elsewhere), 9.0, 1e-12);
    EXPECT_NEAR(pointArea(*first), 4.0, 1e-12);
    EXPECT_NEAR(pointArea(*again), 4.0, 1e-12);
    double xmax = 0.0;
    for (const auto& x : elsewhere->pointCoords) xmax = std::max(xmax, x[0]);
    EXPECT_GT(xmax, 2.5);
    const auto moved = solvedStress(model);  // the moved points are now the model's latest
    EXPECT_TRUE(sameGeometryStorage(*moved, *elsewhere));
}

// Two models of the same mesh (identical points) never share a geometry: each shares with its own
// earlier fields only, whatever the other solved in between; a model's copy (MODI_MODELE_XFEM's
// start) begins with nothing of the original's.
TEST(FeClassical, StressFieldsOfTwoModelsKeepTheirOwnPointGeometry) {
    using namespace fetest;
    msg().setEcho(false);
    auto mesh = planeMesh(6, 6, false, 2.0);
    auto one = affeModele(mesh, "D_PLAN", {"ALL", "RIGHT"});
    auto other = affeModele(mesh, "D_PLAN", {"ALL", "RIGHT"});
    const auto oneFirst = solvedStress(one);
    const auto otherFirst = solvedStress(other);
    const auto oneAgain = solvedStress(one);
    const auto otherAgain = solvedStress(other);
    EXPECT_EQ(oneFirst->pointCoords.get(), otherFirst->pointCoords.get());  // the same points, by value
    EXPECT_EQ(oneFirst->pointWeights.get(), otherFirst->pointWeights.get());
    EXPECT_FALSE(oneFirst->pointCoords.watch().lock() == otherFirst->pointCoords.watch().lock());
    EXPECT_FALSE(oneFirst->pointWeights.watch().lock() == otherFirst->pointWeights.watch().lock());
    EXPECT_TRUE(sameGeometryStorage(*oneFirst, *oneAgain));
    EXPECT_TRUE(sameGeometryStorage(*otherFirst, *otherAgain));
    auto copy = std::make_shared<Model>(*one);
    const auto ofCopy = solvedStress(copy);
    EXPECT_EQ(ofCopy->pointCoords.get(), oneFirst->pointCoords.get());
    EXPECT_NE(ofCopy->pointCoords.watch().lock(), oneFirst->pointCoords.watch().lock());
    EXPECT_TRUE(sameGeometryStorage(*solvedStress(copy), *ofCopy));
    EXPECT_NEAR(pointArea(*otherAgain), 4.0, 1e-12);
}
