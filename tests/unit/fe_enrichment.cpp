// The engine's generic (enriched) path: a test Enrichment describes some elements with explicit
// psi values and gives nodes Heaviside slots. With psi = 1 on slot 0 and psi = 0 on slot 1 the
// generic kernel must reproduce the classical one exactly, the unused Heaviside dofs must be
// neutralised (value 0), and the numbering must expose DX DY H1X H1Y.
#include <gtest/gtest.h>

#include "fe/DofNumbering.hpp"
#include "fe/ElementKinematics.hpp"
#include "fe/Enrichment.hpp"
#include "fe/FieldSampling.hpp"
#include "fe/MechanicalProblem.hpp"
#include "fe_test_support.hpp"

using namespace ma;
using namespace fetest;

namespace {

class TestEnrichment : public Enrichment {
public:
    // psi = `heaviside` on slot 1 (0: the slot is unused).
    TestEnrichment(std::shared_ptr<const Mesh> mesh, std::vector<int> cells, double heaviside = 0.0)
        : mesh_(std::move(mesh)), cells_(std::move(cells)), heaviside_(heaviside) {
        enrichedNode_.assign(mesh_->nodeCount(), 0);
        for (int c : cells_)
            for (int n : mesh_->cellNodes(c)) enrichedNode_[n] = 1;
    }
    int nodeSlots(int node) const override { return enrichedNode_[node] ? 2 : 1; }
    bool isEnriched(int cell) const override { return std::find(cells_.begin(), cells_.end(), cell) != cells_.end(); }
    void integration(int cell, ElementIntegration& out) const override {
        classicalIntegration(*mesh_, cell, false, out);
        out.maxSlots = 2;
        out.slots.assign(out.nodeCount, 2);
        out.psi.assign(size_t(out.nodeCount) * 2, 0.0);  // one sub-cell (pointSubcell 0 at every point)
        for (int a = 0; a < out.nodeCount; ++a) out.psi.mut()[size_t(a) * 2] = 1.0;  // slot 0: psi = 1
        for (int a = 0; a < out.nodeCount; ++a) out.psi.mut()[size_t(a) * 2 + 1] = heaviside_;
    }

private:
    std::shared_ptr<const Mesh> mesh_;
    std::vector<int> cells_;
    std::vector<char> enrichedNode_;
    double heaviside_;
};

// LEFT clamped (H1X = 5 where a node carries it), a linear pressure on RIGHT and a body force.
std::shared_ptr<MechanicalLoad> clampedAndLoaded(const std::shared_ptr<Model>& model) {
    KeywordSet kw;
    set(kw, "MODELE", model);
    auto& d = kw.addOccurrence("DDL_IMPO");
    setTexts(d, "GROUP_MA", {"LEFT"});
    auto constant = [](double v) {
        return ConceptPtr(std::make_shared<LambdaFunction>([v](double, double, double) { return v; }));
    };
    set(d, "DX", constant(0.0)), set(d, "DY", constant(0.0));
    set(d, "H1X", constant(5.0));  // skipped on the nodes that do not carry H1X
    auto& p = kw.addOccurrence("PRES_REP");
    setTexts(p, "GROUP_MA", {"RIGHT"});
    set(p, "PRES", ConceptPtr(std::make_shared<LambdaFunction>([](double, double y, double) { return 10.0 * y; })));
    auto& f = kw.addOccurrence("FORCE_INTERNE");
    set(f, "TOUT", std::string("OUI"));
    set(f, "FX", ConceptPtr(std::make_shared<LambdaFunction>([](double x, double, double) { return 3.0 + x; })));
    set(f, "FY", constant(-2.0));
    return std::dynamic_pointer_cast<MechanicalLoad>(run("AFFE_CHAR_MECA_F", kw, "CHAR"));
}

}  // namespace

TEST(FeEnrichment, GenericKernelMatchesClassicalAndUnusedSlotsAreNeutralised) {
    msg().setEcho(false);
    auto mesh = planeMesh(4, 4, false);
    auto classical = affeModele(mesh, "D_PLAN", {"ALL", "RIGHT"});
    auto enriched = std::make_shared<Model>(*classical);
    enriched->name = "MODX";
    const std::vector<int> cells{5, 6, 9};
    enriched->enrichment = std::make_shared<TestEnrichment>(mesh, cells);

    const DofNumbering numbering(*enriched);
    EXPECT_EQ(numbering.componentNames(), (std::vector<std::string>{"DX", "DY", "H1X", "H1Y"}));
    const int node = mesh->cellNodes(5)[0];
    EXPECT_EQ(numbering.slots(node), 2);
    EXPECT_EQ(numbering.dofOf(node, "H1Y"), numbering.first(node) + 3);
    EXPECT_EQ(numbering.componentOf(numbering.dofOf(node, "H1X")), "H1X");
    EXPECT_EQ(numbering.dofOf(0, "H1X"), -1);  // corner node: not enriched
    EXPECT_THROW(numbering.dofOf(0, "FOO"), UserError);

    std::shared_ptr<NodalField> u[2];
    std::shared_ptr<GaussField> s[2];
    int i = 0;
    for (const auto& model : {classical, enriched}) {
        auto mat = material(model, 2.0e5, 0.25);
        MechanicalProblem problem(model, mat, {{clampedAndLoaded(model), nullptr}}, SolverOptions{});
        ConvergenceOptions conv;
        conv.maxIterations = 10;
        conv.resiGlobRela = 1e-12;
        const auto report = problem.solveIncrement(0.0, conv);
        EXPECT_TRUE(report.converged);
        u[i] = problem.displacementField();
        s[i] = problem.stressField();
        ++i;
    }
    // Same standard displacements and stresses; Heaviside dofs present only on enriched nodes, 0.
    const int hx = u[1]->componentIndex("H1X");
    ASSERT_GE(hx, 0);
    double scale = 0;
    for (double v : u[0]->values) scale = std::max(scale, std::abs(v));
    ASSERT_GT(scale, 0.0);
    for (int n = 0; n < mesh->nodeCount(); ++n) {
        for (int c = 0; c < 2; ++c) EXPECT_NEAR(u[0]->at(n, c), u[1]->at(n, c), 1e-12 * scale);
        EXPECT_EQ(u[1]->has(n, hx), numbering.slots(n) == 2);
        if (u[1]->has(n, hx)) { EXPECT_EQ(u[1]->at(n, hx), 0.0); }
    }
    ASSERT_EQ(s[0]->values.size(), s[1]->values.size());
    double smax = 0;
    for (double v : s[0]->values) smax = std::max(smax, std::abs(v));
    for (size_t k = 0; k < s[0]->values.size(); ++k) EXPECT_NEAR(s[0]->values[k], s[1]->values[k], 1e-11 * smax);
    // Displacement sampling at the elements' own points: both models agree, weights sum to 4.
    const auto a = sampleDisplacement(*classical, *u[0], {});
    const auto b = sampleDisplacement(*enriched, *u[1], {});
    ASSERT_EQ(a.size(), b.size());
    double area = 0;
    for (size_t k = 0; k < a.size(); ++k) {
        area += a[k].weight;
        for (int c = 0; c < 2; ++c) EXPECT_NEAR(a[k].u[c], b[k].u[c], 1e-12 * scale);
    }
    EXPECT_NEAR(area, 4.0, 1e-12);
    EXPECT_EQ(sampleDisplacement(*classical, *u[0], {5}).size(), 4u);
}

namespace {
// A grounded spring k on one dof, and a spring of stiffness k between two dofs.
class Springs : public AdditionalTerms {
public:
    Springs(int ground, int a, int b, double k) : ground_(ground), a_(a), b_(b), k_(k) {}
    void couplings(std::vector<std::pair<int, int>>& pairs) const override {
        pairs.emplace_back(ground_, ground_);
        pairs.emplace_back(a_, b_);
    }
    void tangent(const std::vector<double>&, const std::function<void(int, int, double)>& add) const override {
        add(ground_, ground_, k_);
        add(a_, a_, k_), add(b_, b_, k_), add(a_, b_, -k_), add(b_, a_, -k_);
    }
    void residual(const std::vector<double>& u, std::vector<double>& R) const override {
        R[ground_] += k_ * u[ground_];
        R[a_] += k_ * (u[a_] - u[b_]);
        R[b_] -= k_ * (u[a_] - u[b_]);
    }

private:
    int ground_, a_, b_;
    double k_;
};
}  // namespace

// A scratch description reused across elements (CALC_G's crown loop): a classical cell described
// after a crack-tip one keeps none of its tip slot, psi or points.
TEST(FeEnrichment, ClassicalDescriptionResetsAScratchThatHeldATipElement) {
    auto mesh = planeMesh(2, 2, false);
    ElementIntegration scratch;
    scratch.tip.assign(4, 1);
    scratch.tipA.assign(ElementIntegration::kTipStride, 1.0);
    scratch.tipB = scratch.tipA;
    scratch.tipPhi = scratch.tipA;
    scratch.psi.assign(8, 1.0);
    scratch.maxSlots = 2;
    classicalIntegration(*mesh, 0, false, scratch);
    EXPECT_FALSE(scratch.hasTip());
    EXPECT_FALSE(scratch.tipAt(0));
    EXPECT_TRUE(scratch.tipA.empty() && scratch.tipB.empty() && scratch.tipPhi.empty() && scratch.psi.empty());
    EXPECT_EQ(scratch.refPoints.size(), 4u);  // QUAD4's 2 x 2 Gauss rule
    EXPECT_EQ(scratch.pointSubcell, (std::vector<int>(4, 0)));
    EXPECT_EQ(scratch.multiplier(3, 2, 0), 1.0);
    EXPECT_EQ(scratch.multiplier(3, 2, 1), 0.0);
}

// Terms of another engine (AdditionalTerms): a grounded spring k holds a plate under a vertical
// volume force f (area 4): by equilibrium it carries 4f, so the solution equals the one with
// DY = 4f/k imposed at that node. A spring between two nodes that share no element (outside the
// element pattern) joins the pattern, the matrix and the residual.
TEST(FeAdditionalTerms, SpringsJoinMatrixAndResidual) {
    msg().setEcho(false);
    auto mesh = planeMesh(3, 3, false);
    auto model = affeModele(mesh, "D_PLAN", {"ALL", "RIGHT"});
    auto mat = material(model, 2.0e5, 0.3);
    const int corner = mesh->nodeGroups.get("CORNER")[0];
    auto makeLoad = [&](bool pin) {
        KeywordSet kw;
        set(kw, "MODELE", model);
        auto& d = kw.addOccurrence("DDL_IMPO");
        setTexts(d, "GROUP_MA", {"LEFT"});
        set(d, "DX", 0.0);
        if (pin) {
            auto& c = kw.addOccurrence("DDL_IMPO");
            setTexts(c, "GROUP_NO", {"CORNER"});
            set(c, "DY", 4.0 * 50.0 / 1.0e4);
        }
        auto& f = kw.addOccurrence("FORCE_INTERNE");
        set(f, "TOUT", std::string("OUI"));
        set(f, "FY", 50.0);
        auto& p = kw.addOccurrence("PRES_REP");
        setTexts(p, "GROUP_MA", {"RIGHT"});
        set(p, "PRES", -30.0);
        return std::dynamic_pointer_cast<MechanicalLoad>(run("AFFE_CHAR_MECA", kw, "CHAR"));
    };
    MechanicalProblem pinned(model, mat, {{makeLoad(true), nullptr}}, SolverOptions{});
    MechanicalProblem sprung(model, mat, {{makeLoad(false), nullptr}}, SolverOptions{});
    const int dy = sprung.numbering().dof(corner, 0, 1);
    // The second spring links the two ends of the right side (no common element), horizontally.
    // Both problems get it; in the pinned one the grounded spring sits on an imposed dof.
    const auto& right = mesh->cellGroups.get("RIGHT");
    const int n1 = mesh->cellNodes(right.front())[0], n2 = mesh->cellNodes(right.back())[1];
    auto springs =
        std::make_shared<Springs>(dy, sprung.numbering().dof(n1, 0, 0), sprung.numbering().dof(n2, 0, 0), 1.0e4);
    sprung.setAdditionalTerms(springs);
    pinned.setAdditionalTerms(springs);
    pinned.solveIncrement(0.0, ConvergenceOptions{});
    ConvergenceOptions conv;
    conv.maxIterations = 10;
    conv.resiGlobRela = 1e-12;
    EXPECT_TRUE(sprung.solveIncrement(0.0, conv).converged);
    double scale = 0;
    for (double v : pinned.state()) scale = std::max(scale, std::abs(v));
    ASSERT_GT(scale, 0.0);
    for (size_t i = 0; i < pinned.state().size(); ++i)
        EXPECT_NEAR(pinned.state()[i], sprung.state()[i], 1e-11 * scale) << i;
}

// Internal forces skip the elements whose nodes' unknowns are all zero (the first residual of a
// solve holds only the imposed values): they add nothing, and any non-zero unknown of a node, a
// Heaviside one alone included, keeps its elements in. By linearity f(u) = f(u_a) + f(u - u_a) for
// u_a equal to u on some nodes and zero elsewhere; f(u) visits every element, the two others skip
// the elements outside their nodes, so a skipped element that counts would break the sum.
TEST(FeEnrichment, InternalForcesSkipOnlyElementsWhoseUnknownsAreAllZero) {
    msg().setEcho(false);
    auto mesh = planeMesh(4, 4, false);
    auto model = affeModele(mesh, "D_PLAN", {"ALL", "RIGHT"});
    auto enriched = std::make_shared<Model>(*model);
    enriched->enrichment = std::make_shared<TestEnrichment>(mesh, std::vector<int>{5, 6, 9}, -1.0);
    MechanicalProblem problem(enriched, material(enriched, 2.0e5, 0.25), {}, SolverOptions{});
    const DofNumbering& numbering = problem.numbering();
    std::vector<double> u(size_t(numbering.size())), kept(u.size(), 0.0), rest(u.size(), 0.0);
    for (size_t d = 0; d < u.size(); ++d) u[d] = std::sin(1.3 * double(d) + 0.2);
    const int heavisideOnly = mesh->cellNodes(6)[2];  // an enriched node: only its H1X, H1Y in `kept`
    for (int node = 0; node < numbering.nodeCount(); ++node)
        for (int d = numbering.first(node); d < numbering.first(node + 1); ++d) {
            const bool heaviside = d - numbering.first(node) >= 2;
            const bool inKept = node == heavisideOnly ? heaviside : mesh->coords[size_t(node)][0] < 0.7;
            (inKept ? kept : rest)[size_t(d)] = u[size_t(d)];
        }
    std::vector<double> f, fKept, fRest;
    problem.internalForces(u, f);
    problem.internalForces(kept, fKept);
    problem.internalForces(rest, fRest);
    double scale = 0.0;
    for (double v : f) scale = std::max(scale, std::abs(v));
    ASSERT_GT(scale, 0.0);
    int zeros = 0;
    for (size_t d = 0; d < f.size(); ++d) {
        EXPECT_NEAR(f[d], fKept[d] + fRest[d], 1e-13 * scale) << "dof " << d;
        zeros += fKept[d] == 0.0;
    }
    EXPECT_GT(zeros, 0);  // elements far from `kept` were skipped: their dofs got nothing
}

TEST(FeEnrichment, LastResidualWritesTheStressesOfTheSeparatePointLoop) {
    msg().setEcho(false);
    auto mesh = planeMesh(4, 4, false);
    auto base = affeModele(mesh, "D_PLAN", {"ALL", "RIGHT"});
    auto enrichedCopy = [&] {  // a copy: its own latest point geometry
        auto model = std::make_shared<Model>(*base);
        model->enrichment = std::make_shared<TestEnrichment>(mesh, std::vector<int>{5, 6, 9});
        return model;
    };
    using After = MechanicalProblem::AfterSolve;
    auto sief = [](const std::shared_ptr<Model>& model, After after) {
        MechanicalProblem problem(model, material(model, 2.0e5, 0.25), {{clampedAndLoaded(model), nullptr}},
                                  SolverOptions{});
        problem.solveIncrement(0.0, ConvergenceOptions{}, after);
        return problem.stressField();
    };
    const auto first = enrichedCopy(), second = enrichedCopy();
    const auto computed = sief(first, After::KeepFactors);              // stressField's own loop
    const auto kept = sief(second, After::ReleaseFactorsKeepStresses);  // the residual's loop
    double smax = 0.0;
    for (double v : computed->values) smax = std::max(smax, std::abs(v));
    ASSERT_GT(smax, 0.0);
    EXPECT_EQ(kept->values, computed->values);
    EXPECT_EQ(kept->pointOffsets, computed->pointOffsets);
    EXPECT_EQ(kept->pointCoords, computed->pointCoords);
    EXPECT_EQ(kept->pointWeights, computed->pointWeights);
    EXPECT_EQ(kept->pointSubcell, computed->pointSubcell);
    EXPECT_EQ(kept->pointRefCoords, computed->pointRefCoords);
    // Again on the first model: its latest geometry adopted (compared, not written), the same values.
    const auto again = sief(first, After::ReleaseFactorsKeepStresses);
    EXPECT_EQ(again->values, computed->values);
    EXPECT_EQ(again->pointWeights.data(), computed->pointWeights.data());
    MechanicalProblem newton(first, material(first, 2.0e5, 0.25), {}, SolverOptions{});
    EXPECT_THROW(newton.solveIncrement(0.0, ConvergenceOptions{.maxIterations = 3}, After::ReleaseFactors),
                 std::logic_error);  // freed factors are for an increment's one solve
}
