// DEFI_GROUP's OPTION= selections (ENV_SPHERE, ENV_CYLINDRE, PLAN, SEGM_DROI_ORDO, NOEUD_ORDO,
// SPHERE, CYLINDRE, FISS_XFEM) and COPIER, called through the command registry on generated
// meshes (tools/scenes, N = 4 on [-5,5]^2: grid lines every 2.5): memberships counted by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.hpp"
#include "fe/Model.hpp"
#include "fe/Result.hpp"
#include "mesh/GeometricSelection.hpp"
#include "parser/Catalog.hpp"
#include "parser/CommandRegistry.hpp"
#include "scenes/Ssnv511Mesh.hpp"
#include "xfem/Crack.hpp"

using namespace ma;

namespace {

ConceptPtr call(const std::string& command, const KeywordSet& kw) {
    const auto* fn = CommandRegistry::instance().find(command);
    if (!fn) throw std::runtime_error(command + " is not registered");
    CommandContext ctx;
    ctx.command = command;
    return (*fn)(validateKeywords(command, kw), ctx);
}

std::shared_ptr<Mesh> generated(Ssnv511MeshOptions::Kind kind) {
    Ssnv511MeshOptions o;
    o.kind = kind;
    o.divisions = 4;
    auto m = buildSsnv511Mesh(o);
    m->name = "MA";
    return m;
}

// One DEFI_GROUP occurrence built by the caller; returns the members of group `name`.
template <class Fill>
std::vector<int> defineGroup(const std::shared_ptr<Mesh>& m, const char* factor, const std::string& name, Fill fill) {
    KeywordSet kw;
    kw.setValues("MAILLAGE", {ConceptPtr(m)});
    auto& occ = kw.addOccurrence(factor);
    occ.setValues("NOM", {name});
    fill(occ);
    call("DEFI_GROUP", kw);
    const GroupSet& groups = std::string(factor) == "CREA_GROUP_MA" ? m->cellGroups : m->nodeGroups;
    return groups.has(name) ? groups.get(name) : std::vector<int>{};
}

std::vector<int> nodeGroup(const std::shared_ptr<Mesh>& m, const std::string& name, const std::string& option,
                           const std::function<void(KeywordSet&)>& fill) {
    return defineGroup(m, "CREA_GROUP_NO", name, [&](KeywordSet& o) {
        o.setValues("OPTION", {option});
        fill(o);
    });
}
std::vector<int> cellGroup(const std::shared_ptr<Mesh>& m, const std::string& name, const std::string& option,
                           const std::function<void(KeywordSet&)>& fill) {
    return defineGroup(m, "CREA_GROUP_MA", name, [&](KeywordSet& o) {
        o.setValues("OPTION", {option});
        o.setValues("TYPE_MAILLE", {std::string("3D")});
        fill(o);
    });
}

std::vector<std::array<double, 3>> coordinates(const Mesh& m, const std::vector<int>& nodes) {
    std::vector<std::array<double, 3>> out;
    for (int n : nodes) out.push_back(m.coords[size_t(n)]);
    return out;
}

}  // namespace

// HEXA8, z in {0, 1}: 50 nodes. Sphere |x| = 2.5 around the origin: the 4 axis nodes of z = 0;
// with PRECISION 0.5 also those of z = 1 (|x| = sqrt(7.25) = 2.69). GROUP_NO_CENTRE gives the
// centre through a one-node group made the ssnv195a way.
TEST(DefiGroupOptions, EnvSphere) {
    auto m = generated(Ssnv511MeshOptions::Kind::Hexa8);
    auto sphere = [&](const std::string& name, double precision) {
        return nodeGroup(m, name, "ENV_SPHERE", [&](KeywordSet& o) {
            o.setValues("POINT", {0.0, 0.0, 0.0});
            o.setValues("RAYON", {2.5});
            o.setValues("PRECISION", {precision});
        });
    };
    EXPECT_EQ(sphere("S1", 0.01).size(), 4u);
    EXPECT_EQ(sphere("S2", 0.5).size(), 8u);
    const auto origin = nodeGroup(m, "O", "ENV_SPHERE", [](KeywordSet& o) {
        o.setValues("POINT", {0.0, 0.0, 0.0});
        o.setValues("RAYON", {1e-3});
        o.setValues("PRECISION", {2e-3});
    });
    ASSERT_EQ(origin.size(), 1u);
    EXPECT_EQ(m->coords[size_t(origin[0])], (std::array<double, 3>{0, 0, 0}));
    const auto around = nodeGroup(m, "S3", "ENV_SPHERE", [](KeywordSet& o) {
        o.setValues("GROUP_NO_CENTRE", {std::string("O")});
        o.setValues("RAYON", {2.5});
        o.setValues("PRECISION", {0.01});
    });
    EXPECT_EQ(around, m->nodeGroups.get("S1"));
    // A 3D mesh wants three coordinates, as code_aster reads them.
    EXPECT_THROW(nodeGroup(m, "S4", "ENV_SPHERE",
                           [](KeywordSet& o) {
                               o.setValues("POINT", {0.0, 0.0});
                               o.setValues("RAYON", {2.5});
                               o.setValues("PRECISION", {0.01});
                           }),
                 UserError);
}

// Planes through the origin node: z = 0 (25 nodes), x = 0 and y = 0 (5 x 2 nodes each), the
// normals given by ANGL_NAUT: (0, 0) -> x, (90, 0) -> y, (0, -90) -> z.
TEST(DefiGroupOptions, PlanWithCentreAndNauticalAngles) {
    auto m = generated(Ssnv511MeshOptions::Kind::Hexa8);
    m->nodeGroups.set("O", {12});  // node (0, 0, 0): i = j = 2
    ASSERT_EQ(m->coords[12], (std::array<double, 3>{0, 0, 0}));
    auto plan = [&](const std::string& name, std::vector<double> angles) {
        return nodeGroup(m, name, "PLAN", [&](KeywordSet& o) {
            o.setValues("GROUP_NO_CENTRE", {std::string("O")});
            std::vector<KeywordValue> v(angles.begin(), angles.end());
            o.setValues("ANGL_NAUT", v);
            o.setValues("PRECISION", {1e-3});
        });
    };
    const auto x0 = plan("X0", {0, 0}), y0 = plan("Y0", {90, 0}), z0 = plan("Z0", {0, -90});
    EXPECT_EQ(x0.size(), 10u);
    EXPECT_EQ(y0.size(), 10u);
    EXPECT_EQ(z0.size(), 25u);
    for (int n : x0) EXPECT_EQ(m->coords[size_t(n)][0], 0.0);
    for (int n : y0) EXPECT_NEAR(m->coords[size_t(n)][1], 0.0, 1e-15);
    const auto byVector = nodeGroup(m, "Z1", "PLAN", [](KeywordSet& o) {
        o.setValues("NOEUD_CENTRE", {std::string("N13")});
        o.setValues("VECT_NORMALE", {0.0, 0.0, 2.0});
        o.setValues("PRECISION", {1e-3});
    });
    EXPECT_EQ(byVector, z0);
}

// Cylinder of axis z through the origin: radius 2.5 holds the 4 axis nodes of both layers,
// radius sqrt(12.5) the 4 diagonal ones of both layers. A plane mesh is refused.
TEST(DefiGroupOptions, EnvCylindre) {
    auto m = generated(Ssnv511MeshOptions::Kind::Hexa8);
    auto cylinder = [&](const std::string& name, double radius, bool angles) {
        return nodeGroup(m, name, "ENV_CYLINDRE", [&](KeywordSet& o) {
            o.setValues("POINT", {0.0, 0.0, 0.0});
            if (angles) o.setValues("ANGL_NAUT", {0.0, -90.0});
            else o.setValues("VECT_NORMALE", {0.0, 0.0, 1.0});
            o.setValues("RAYON", {radius});
            o.setValues("PRECISION", {0.01});
        });
    };
    EXPECT_EQ(cylinder("C1", 2.5, false).size(), 8u);
    EXPECT_EQ(cylinder("C2", 2.5, true), m->nodeGroups.get("C1"));
    const auto diagonal = cylinder("C3", std::sqrt(12.5), false);
    ASSERT_EQ(diagonal.size(), 8u);
    for (int n : diagonal) EXPECT_EQ(std::abs(m->coords[size_t(n)][0]), 2.5);
    auto plane = generated(Ssnv511MeshOptions::Kind::Quad4);
    EXPECT_THROW(nodeGroup(plane, "C", "ENV_CYLINDRE",
                           [](KeywordSet& o) {
                               o.setValues("POINT", {0.0, 0.0, 0.0});
                               o.setValues("VECT_NORMALE", {0.0, 0.0, 1.0});
                               o.setValues("RAYON", {2.5});
                               o.setValues("PRECISION", {0.01});
                           }),
                 UserError);
}

// The 5 nodes of the line y = z = 0 (PLAN y = 0 and PLAN z = 0 intersected), sorted from x = 5
// to x = -5; a node off the line stops the command.
TEST(DefiGroupOptions, SegmDroiOrdo) {
    auto m = generated(Ssnv511MeshOptions::Kind::Hexa8);
    m->nodeGroups.set("AXE", {10, 11, 12, 13, 14});  // j = 2, z = 0: x = -5 .. 5
    m->nodeGroups.set("A", {14});
    auto segment = [&](const std::string& name, std::vector<std::string> groups) {
        return nodeGroup(m, name, "SEGM_DROI_ORDO", [&](KeywordSet& o) {
            std::vector<KeywordValue> g(groups.begin(), groups.end());
            o.setValues("GROUP_NO", g);
            o.setValues("GROUP_NO_ORIG", {std::string("A")});
            o.setValues("NOEUD_EXTR", {std::string("N11")});
            o.setValues("PRECISION", {1e-6});
            o.setValues("CRITERE", {std::string("ABSOLU")});
        });
    };
    const auto sorted = segment("AXE_ORDO", {"AXE"});
    EXPECT_EQ(coordinates(*m, sorted),
              (std::vector<std::array<double, 3>>{{5, 0, 0}, {2.5, 0, 0}, {0, 0, 0}, {-2.5, 0, 0}, {-5, 0, 0}}));
    m->nodeGroups.set("OFF", {15});  // (-5, 2.5, 0)
    EXPECT_THROW(segment("BAD", {"AXE", "OFF"}), UserError);
}

// Quad4 edges (LB: N1 -> N5 along y = -5, then LD, LH, LG counter-clockwise).
TEST(DefiGroupOptions, NoeudOrdo) {
    auto m = generated(Ssnv511MeshOptions::Kind::Quad4);
    auto line = [&](const std::string& name, std::vector<std::string> groups,
                    const std::function<void(KeywordSet&)>& more) {
        return nodeGroup(m, name, "NOEUD_ORDO", [&](KeywordSet& o) {
            std::vector<KeywordValue> g(groups.begin(), groups.end());
            o.setValues("GROUP_MA", g);
            more(o);
        });
    };
    auto names = [&](const std::vector<int>& nodes) {
        std::vector<std::string> out;
        for (int n : nodes) out.push_back(m->nodeNames[size_t(n)]);
        return out;
    };
    // Open line: the first free end (N1) is the origin unless NOEUD_ORIG says otherwise.
    EXPECT_EQ(names(line("B1", {"LB"}, [](KeywordSet&) {})), (std::vector<std::string>{"N1", "N2", "N3", "N4", "N5"}));
    EXPECT_EQ(names(line("B2", {"LB"}, [](KeywordSet& o) { o.setValues("NOEUD_ORIG", {std::string("N5")}); })),
              (std::vector<std::string>{"N5", "N4", "N3", "N2", "N1"}));
    // Two edges in one line, through the corner N5.
    EXPECT_EQ(names(line("B3", {"LD", "LB"}, [](KeywordSet&) {})),
              (std::vector<std::string>{"N1", "N2", "N3", "N4", "N5", "N10", "N15", "N20", "N25"}));
    // Closed line: no origin is an error, ORIGINE='SANS' starts at the first node of the first cell,
    // and VECT_ORIE picks the direction of a loop whose origin is its extremity.
    const std::vector<std::string> loop{"LB", "LD", "LH", "LG"};
    EXPECT_THROW(line("L0", loop, [](KeywordSet&) {}), UserError);
    const auto any = names(line("L1", loop, [](KeywordSet& o) { o.setValues("ORIGINE", {std::string("SANS")}); }));
    ASSERT_EQ(any.size(), 17u);
    EXPECT_EQ(any.front(), "N1");
    EXPECT_EQ(any[1], "N2");
    EXPECT_EQ(any.back(), "N1");
    const auto up = names(line("L2", loop, [](KeywordSet& o) {
        o.setValues("NOEUD_ORIG", {std::string("N1")});
        o.setValues("NOEUD_EXTR", {std::string("N1")});
        o.setValues("VECT_ORIE", {0.0, 1.0, 0.0});
    }));
    ASSERT_EQ(up.size(), 17u);
    EXPECT_EQ(up[1], "N6");
    EXPECT_EQ(up[16], "N1");
    // A line with a branch (three edges at a corner would be one; here LB twice plus a quad is not a line).
    EXPECT_THROW(line("Q", {"SURF"}, [](KeywordSet&) {}), UserError);
}

// HEXA8 cells (TYPE_MAILLE='3D') near the origin. Nodes within 2.6 of it: the origin and its 4
// axis neighbours at z = 0, and (0, 0, 1). AU_MOINS_UN: the 4 cells around the origin and the 2
// beyond each axis neighbour (12); MAJORITE (4 of 8 nodes): the 4 around the origin; TOUS with
// radius 8 (> sqrt(51)): all 16.
TEST(DefiGroupOptions, Sphere) {
    auto m = generated(Ssnv511MeshOptions::Kind::Hexa8);
    auto sphere = [&](const std::string& name, double radius, const char* crit) {
        return cellGroup(m, name, "SPHERE", [&](KeywordSet& o) {
            o.setValues("POINT", {0.0, 0.0, 0.0});
            o.setValues("RAYON", {radius});
            o.setValues("CRIT_NOEUD", {std::string(crit)});
        });
    };
    EXPECT_EQ(sphere("S1", 2.6, "AU_MOINS_UN").size(), 12u);
    EXPECT_EQ(sphere("S2", 2.6, "MAJORITE").size(), 4u);
    EXPECT_EQ(sphere("S3", 8.0, "TOUS").size(), 16u);
    EXPECT_TRUE(sphere("S4", 2.6, "TOUS").empty());  // not created: ALARME
    EXPECT_FALSE(m->cellGroups.has("S4"));
}

// Cylinder of axis z, radius 2.6: the axis node columns (x, y) = (0, 0), (+-2.5, 0), (0, +-2.5).
// AU_MOINS_UN 12 cells, MAJORITE (6 of 8) the 4 central ones; TOUS with radius 3.6 (> sqrt(12.5)):
// the 4 central ones.
TEST(DefiGroupOptions, Cylindre) {
    auto m = generated(Ssnv511MeshOptions::Kind::Hexa8);
    auto cylinder = [&](const std::string& name, double radius, const char* crit) {
        return cellGroup(m, name, "CYLINDRE", [&](KeywordSet& o) {
            o.setValues("POINT", {0.0, 0.0, 0.5});
            o.setValues("VECT_NORMALE", {0.0, 0.0, 1.0});
            o.setValues("RAYON", {radius});
            o.setValues("CRIT_NOEUD", {std::string(crit)});
        });
    };
    EXPECT_EQ(cylinder("C1", 2.6, "AU_MOINS_UN").size(), 12u);
    EXPECT_EQ(cylinder("C2", 2.6, "MAJORITE").size(), 4u);
    EXPECT_EQ(cylinder("C3", 3.6, "TOUS"), m->cellGroups.get("C2"));
}

// Interfaces x = 1.25 and y = 1.25 on the QUAD4 mesh. Enriched nodes: those of the cut cells,
// x in {0, 2.5} (10 nodes) for the first. Its Heaviside cells: every cell with such a node, 12
// quadrangles (3 columns) and 6 edges of LB/LH; FISSUREE: those whose nodes are all enriched, 4
// quadrangles and 2 edges. Two interfaces list their nodes one after the other (20, 4 of them
// twice). CRACKTIP has no node or cell on an interface: the group is not created.
TEST(DefiGroupOptions, FissXfem) {
    auto m = generated(Ssnv511MeshOptions::Kind::Quad4);
    std::vector<double> lsx, lsy;
    for (const auto& x : m->coords) lsx.push_back(x[0] - 1.25), lsy.push_back(x[1] - 1.25);
    auto fx = xfem::buildCrack(m, lsx, nullptr), fy = xfem::buildCrack(m, lsy, nullptr);
    auto xfemGroup = [&](const char* factor, const std::string& name, const char* type, bool both) {
        return defineGroup(m, factor, name, [&](KeywordSet& o) {
            o.setValues("OPTION", {std::string("FISS_XFEM")});
            o.setValues("TYPE_GROUP", {std::string(type)});
            if (both) o.setValues("FISSURE", {ConceptPtr(fx), ConceptPtr(fy)});
            else o.setValues("FISSURE", {ConceptPtr(fx)});
        });
    };
    const auto heavisideNodes = xfemGroup("CREA_GROUP_NO", "NH", "HEAVISIDE", false);
    ASSERT_EQ(heavisideNodes.size(), 10u);
    for (int n : heavisideNodes) EXPECT_TRUE(m->coords[size_t(n)][0] == 0.0 || m->coords[size_t(n)][0] == 2.5);
    EXPECT_EQ(xfemGroup("CREA_GROUP_NO", "NX", "XFEM", false), heavisideNodes);
    EXPECT_EQ(xfemGroup("CREA_GROUP_NO", "N2", "HEAVISIDE", true).size(), 20u);
    EXPECT_TRUE(xfemGroup("CREA_GROUP_NO", "NT", "CRACKTIP", false).empty());
    EXPECT_TRUE(xfemGroup("CREA_GROUP_MA", "MT", "MIXTE", false).empty());
    EXPECT_FALSE(m->cellGroups.has("MT"));
    const auto heaviside = xfemGroup("CREA_GROUP_MA", "MH", "HEAVISIDE", false);
    int quads = 0;
    for (int c : heaviside) quads += m->cellTypes[size_t(c)] == CellType::QUAD4;
    EXPECT_EQ(heaviside.size(), 18u);
    EXPECT_EQ(quads, 12);
    EXPECT_EQ(xfemGroup("CREA_GROUP_MA", "MX", "XFEM", false), heaviside);
    EXPECT_EQ(xfemGroup("CREA_GROUP_MA", "MF", "FISSUREE", false).size(), 6u);
}

// COPIER: DEFI_GROUP on the copy leaves the original without the new group (ssnv201a's pattern).
TEST(DefiGroupOptions, CopierMakesAnIndependentMesh) {
    auto m = generated(Ssnv511MeshOptions::Kind::Quad4);
    KeywordSet kw;
    kw.setValues("CONCEPT", {ConceptPtr(m)});
    auto copy = std::dynamic_pointer_cast<Mesh>(call("COPIER", kw));
    ASSERT_TRUE(copy);
    ASSERT_NE(copy, m);
    EXPECT_EQ(copy->coords, m->coords);
    EXPECT_EQ(copy->connectivity, m->connectivity);
    EXPECT_EQ(copy->cellGroups.names(), m->cellGroups.names());
    const auto corner = nodeGroup(copy, "C", "ENV_SPHERE", [](KeywordSet& o) {
        o.setValues("POINT", {-5.0, -5.0});
        o.setValues("RAYON", {1e-3});
        o.setValues("PRECISION", {2e-3});
    });
    EXPECT_EQ(corner, std::vector<int>{0});
    EXPECT_FALSE(m->nodeGroups.has("C"));
}

// COPIER of a model and of a result: same type, same mesh and model, own step list.
TEST(DefiGroupOptions, CopierOfModelsAndResults) {
    auto m = generated(Ssnv511MeshOptions::Kind::Quad4);
    auto model = std::make_shared<Model>();
    model->mesh = m;
    model->dim = 2;
    model->modelisation = Modelisation::C_PLAN;
    KeywordSet kw;
    kw.setValues("CONCEPT", {ConceptPtr(model)});
    auto copy = std::dynamic_pointer_cast<Model>(call("COPIER", kw));
    ASSERT_TRUE(copy);
    EXPECT_NE(copy, model);
    EXPECT_EQ(copy->mesh, m);
    EXPECT_EQ(copy->modelisation, Modelisation::C_PLAN);
    auto result = std::make_shared<Result>("evol_noli");
    result->model = model;
    result->steps.resize(3);
    KeywordSet rk;
    rk.setValues("CONCEPT", {ConceptPtr(result)});
    auto resultCopy = std::dynamic_pointer_cast<Result>(call("COPIER", rk));
    ASSERT_TRUE(resultCopy);
    EXPECT_EQ(resultCopy->typeName(), "evol_noli");
    EXPECT_EQ(resultCopy->model, model);
    resultCopy->steps.pop_back();
    EXPECT_EQ(result->steps.size(), 3u);
}
