// DEFI_GROUP and MODI_MAILLAGE on the astest meshes, called through the command registry with
// keyword trees built by hand: exact memberships and orientations.
#include <gtest/gtest.h>

#include <set>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "core/Units.hpp"
#include "med_io/MedReader.hpp"
#include "med_test_support.hpp"
#include "mesh/MeshQueries.hpp"
#include "mesh/SkinOrientation.hpp"
#include "parser/Catalog.hpp"
#include "parser/CommandRegistry.hpp"

using namespace ma;

namespace {

std::shared_ptr<Mesh> load(const char* file) {
    auto m = med::readMesh(test::astest(file));
    m->name = "MAILLAG";
    return m;
}

ConceptPtr call(const std::string& command, const KeywordSet& kw, ConceptPtr reused = nullptr) {
    const auto* fn = CommandRegistry::instance().find(command);
    if (!fn) throw std::runtime_error(command + " is not registered");
    CommandContext ctx;
    ctx.command = command;
    ctx.reused = std::move(reused);
    return (*fn)(validateKeywords(command, kw), ctx);
}

KeywordSet withMesh(const std::shared_ptr<Mesh>& m) {
    KeywordSet kw;
    kw.setValues("MAILLAGE", {ConceptPtr(m)});
    return kw;
}

std::vector<std::string> cellNames(const Mesh& m, const std::string& group) {
    std::vector<std::string> out;
    for (int c : m.cellGroups.get(group)) out.push_back(m.cellNames[c]);
    return out;
}
std::vector<std::string> nodeNames(const Mesh& m, const std::string& group) {
    std::vector<std::string> out;
    for (int n : m.nodeGroups.get(group)) out.push_back(m.nodeNames[n]);
    return out;
}
std::vector<std::string> seq(const char* prefix, int from, int to, int step = 1) {
    std::vector<std::string> out;
    for (int i = from; step > 0 ? i <= to : i >= to; i += step)
        out.push_back(std::string(prefix).append(std::to_string(i)));
    return out;
}

// Names, in mesh order, of the nodes whose coordinates satisfy `on`.
template <class Predicate>
std::vector<std::string> nodesWhere(const Mesh& m, Predicate on) {
    std::vector<std::string> out;
    for (int n = 0; n < m.nodeCount(); ++n)
        if (on(m.coords[n])) out.push_back(m.nodeNames[n]);
    return out;
}

// Indices, in mesh order, of the cells of type `type` whose nodes all satisfy `on`.
template <class Predicate>
std::vector<int> cellsWhere(const Mesh& m, CellType type, Predicate on) {
    std::vector<int> out;
    for (int c = 0; c < m.cellCount(); ++c) {
        if (m.cellTypes[c] != type) continue;
        bool all = true;
        for (int n : m.cellNodes(c)) all = all && on(m.coords[n]);
        if (all) out.push_back(c);
    }
    return out;
}

std::vector<std::string> namesOf(const Mesh& m, const std::vector<int>& cells) {
    std::vector<std::string> out;
    for (int c : cells) out.push_back(m.cellNames[c]);
    return out;
}

void reverse(Mesh& m, int cell) {
    auto order = reversedOrder(m.cellTypes[cell]);
    auto nodes = m.cellNodes(cell);
    std::vector<int> old(nodes.begin(), nodes.end());
    for (size_t k = 0; k < order.size(); ++k) m.connectivity[m.cellOffsets[cell] + k] = old[order[k]];
}

// Outward: the face normal points away from the centroid of the body cell it bounds.
bool outward(const Mesh& m, int face, int bodyDim) {
    auto fn = m.cellNodes(face);
    for (int b = 0; b < m.cellCount(); ++b) {
        if (cellDimension(m.cellTypes[b]) != bodyDim) continue;
        auto bn = m.cellNodes(b);
        bool all = true;
        for (int k = 0; k < vertexCount(m.cellTypes[face]) && all; ++k)
            all = std::find(bn.begin(), bn.end(), fn[k]) != bn.end();
        if (!all) continue;
        auto gb = vertexCentroid(m, b), gf = vertexCentroid(m, face);
        Vec3 g{gf[0] - gb[0], gf[1] - gb[1], gf[2] - gb[2]};
        return dot(cellNormal(m, face), g) > 0;
    }
    return false;
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const UserError& e) { return e.what(); }
    return "(no error)";
}

class MeshCommands : public ::testing::Test {
protected:
    void SetUp() override { msg().setEcho(false); }
};

}  // namespace

TEST_F(MeshCommands, PlaneNodeGroupsOfSsnv511d) {
    auto m = load("ssnv511d.mmed");
    KeywordSet kw = withMesh(m);
    auto& sg = kw.addOccurrence("CREA_GROUP_NO");
    sg.setValues("NOM", {std::string("SG")});
    sg.setValues("OPTION", {std::string("PLAN")});
    sg.setValues("POINT", {-5.0, 0.0, 0.0});
    sg.setValues("VECT_NORMALE", {1.0, 0.0, 0.0});
    sg.setValues("PRECISION", {0.1});
    auto& sd = kw.addOccurrence("CREA_GROUP_NO");
    sd.setValues("NOM", {std::string("SD")});
    sd.setValues("OPTION", {std::string("PLAN")});
    sd.setValues("POINT", {5.0, 0.0, 0.0});
    sd.setValues("VECT_NORMALE", {1.0, 0.0, 0.0});
    sd.setValues("PRECISION", {0.1});
    auto out = call("DEFI_GROUP", kw, m);
    EXPECT_EQ(out, m);
    // Both layers (38 nodes each) of the x = -5 and x = +5 columns, from the coordinates.
    const auto left = nodesWhere(*m, [](const auto& x) { return std::abs(x[0] + 5.0) <= 0.1; });
    const auto right = nodesWhere(*m, [](const auto& x) { return std::abs(x[0] - 5.0) <= 0.1; });
    EXPECT_EQ(left.size(), 12u);
    EXPECT_EQ(nodeNames(*m, "SG"), left);
    EXPECT_EQ(right.size(), 12u);
    EXPECT_EQ(nodeNames(*m, "SD"), right);
}

TEST_F(MeshCommands, OriePeau3dThenFaceNormaleOnSsnv511g) {
    auto m = load("ssnv511g.mmed");
    double zmin = 1e300, zmax = -1e300;
    for (const auto& x : m->coords) zmin = std::min(zmin, x[2]), zmax = std::max(zmax, x[2]);
    auto plane = [&](int axis, double value) {
        return cellsWhere(*m, CellType::QUAD4, [=](const auto& x) { return x[axis] == value; });
    };
    const auto bottom = plane(2, zmin), top = plane(2, zmax), high = plane(1, 5.0), low = plane(1, -5.0);
    const auto right = plane(0, 5.0);
    ASSERT_EQ(bottom.size(), 25u);
    ASSERT_EQ(top.size(), 25u);
    ASSERT_EQ(high.size(), 5u);
    ASSERT_EQ(low.size(), 5u);
    ASSERT_EQ(right.size(), 5u);
    // Turn three skin faces (one bottom, one top, one of SD): code_aster's skin is not all
    // outward to start with, so this only makes the mix surer.
    for (int c : {bottom[0], top[5], right[2]}) reverse(*m, c);
    std::set<int> skin;
    for (const char* g : {"ENV", "SD", "SG"})
        for (int c : m->cellGroups.get(g)) skin.insert(c);
    int inward = 0;
    for (int c : skin) inward += outward(*m, c, 3) ? 0 : 1;
    EXPECT_GT(inward, 3);
    {
        // Before orientation, FACE_NORMALE with VERI_SIGNE takes the faces whose node order
        // turns about -z, whatever side of the body they bound.
        KeywordSet kw = withMesh(m);
        auto& f = kw.addOccurrence("CREA_GROUP_MA");
        f.setValues("NOM", {std::string("FACE0")});
        f.setValues("OPTION", {std::string("FACE_NORMALE")});
        f.setValues("VECT_NORMALE", {0.0, 0.0, -1.0});
        call("DEFI_GROUP", kw, m);
        std::vector<int> expected;
        for (int c : bottom)
            if (cellNormal(*m, c)[2] < 0.0) expected.push_back(c);
        for (int c : top)
            if (cellNormal(*m, c)[2] < 0.0) expected.push_back(c);
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(cellNames(*m, "FACE0"), namesOf(*m, expected));
        EXPECT_LT(expected.size(), 25u);
    }
    KeywordSet kw = withMesh(m);
    kw.addOccurrence("ORIE_PEAU_3D").setValues("GROUP_MA", {std::string("ENV"), std::string("SD"), std::string("SG")});
    call("MODI_MAILLAGE", kw, m);
    EXPECT_NE(msg().messText().find("NOMBRE DE MAILLES REORIENTEES : " + std::to_string(inward) + "\n"),
              std::string::npos)
        << msg().messText();
    for (int c : m->cellGroups.get("ENV")) EXPECT_TRUE(outward(*m, c, 3)) << m->cellNames[c];

    KeywordSet dg = withMesh(m);
    const std::vector<std::pair<std::string, std::vector<double>>> wanted{{"FACE", {0, 0, -1}},
                                                                          {"SH", {0, 1, 0}},
                                                                          {"SB", {0, -1, 0}},
                                                                          {"TOP", {0, 0, 1}}};
    for (const auto& [name, v] : wanted) {
        auto& occ = dg.addOccurrence("CREA_GROUP_MA");
        occ.setValues("NOM", {name});
        occ.setValues("OPTION", {std::string("FACE_NORMALE")});
        occ.setValues("VECT_NORMALE", {v[0], v[1], v[2]});
    }
    call("DEFI_GROUP", dg, m);
    EXPECT_EQ(cellNames(*m, "FACE"), namesOf(*m, bottom));
    EXPECT_EQ(cellNames(*m, "TOP"), namesOf(*m, top));
    EXPECT_EQ(cellNames(*m, "SH"), namesOf(*m, high));
    EXPECT_EQ(cellNames(*m, "SB"), namesOf(*m, low));
}

TEST_F(MeshCommands, BandeIntersectedWithFaceNormaleOnSsnv511h) {
    auto m = load("ssnv511h.mmed");
    KeywordSet orient = withMesh(m);
    orient.addOccurrence("ORIE_PEAU_3D").setValues("GROUP_MA", {std::string("ENV")});
    call("MODI_MAILLAGE", orient, m);
    for (int c : m->cellGroups.get("ENV")) ASSERT_TRUE(outward(*m, c, 3)) << m->cellNames[c];

    KeywordSet kw = withMesh(m);
    auto& b = kw.addOccurrence("CREA_GROUP_MA");
    b.setValues("NOM", {std::string("SD1")});
    b.setValues("OPTION", {std::string("BANDE")});
    b.setValues("POINT", {5.0, 0.0, 0.0});
    b.setValues("VECT_NORMALE", {1.0, 0.0, 0.0});
    b.setValues("DIST", {0.1});
    auto& f = kw.addOccurrence("CREA_GROUP_MA");
    f.setValues("NOM", {std::string("SD2")});
    f.setValues("OPTION", {std::string("FACE_NORMALE")});
    f.setValues("VECT_NORMALE", {1.0, 0.0, 0.0});
    auto& i = kw.addOccurrence("CREA_GROUP_MA");
    i.setValues("NOM", {std::string("SD")});
    i.setValues("INTERSEC", {std::string("SD1"), std::string("SD2")});
    call("DEFI_GROUP", kw, m);

    // Every cell touching x = 5: expected from the coordinates.
    std::vector<int> band;
    for (int c = 0; c < m->cellCount(); ++c) {
        bool touches = false;
        for (int n : m->cellNodes(c)) touches |= m->coords[n][0] == 5.0;
        if (touches) band.push_back(c);
    }
    EXPECT_EQ(m->cellGroups.get("SD1"), band);
    // The x = +5 side: 5 squares of the extruded 2D mesh, 2 triangles each.
    const auto& sd = m->cellGroups.get("SD");
    EXPECT_EQ(sd.size(), 10u);
    for (int c : sd) {
        EXPECT_EQ(m->cellTypes[c], CellType::TRIA3);
        for (int n : m->cellNodes(c)) EXPECT_EQ(m->coords[n][0], 5.0);
    }
    EXPECT_EQ(m->cellGroups.get("SD2"), sd);
}

TEST_F(MeshCommands, SetOperationsNodeGroupsAndTypeFilter) {
    auto m = load("ssnv511a.mmed");
    KeywordSet kw = withMesh(m);
    auto add = [&](const char* name, const char* op, std::vector<std::string> groups) {
        auto& occ = kw.addOccurrence("CREA_GROUP_MA");
        occ.setValues("NOM", {std::string(name)});
        std::vector<KeywordValue> v(groups.begin(), groups.end());
        occ.setValues(op, v);
    };
    add("BD", "UNION", {"LD", "LB"});
    add("B", "DIFFE", {"BD", "LD"});
    add("VIDE", "INTERSEC", {"LB", "LD"});
    auto& all2d = kw.addOccurrence("CREA_GROUP_MA");
    all2d.setValues("NOM", {std::string("S2D")});
    all2d.setValues("TOUT", {std::string("OUI")});
    all2d.setValues("TYPE_MAILLE", {std::string("2D")});
    auto& nodes = kw.addOccurrence("CREA_GROUP_NO");
    nodes.setValues("GROUP_MA", {std::string("LB"), std::string("LD")});
    const int alarms = msg().alarmCount();
    call("DEFI_GROUP", kw, m);

    // LD is x = 5, LB y = -5 (their cells from the coordinates); the union keeps LD's order first.
    const auto ld = namesOf(*m, cellsWhere(*m, CellType::SEG2, [](const auto& x) { return x[0] == 5.0; }));
    const auto lb = namesOf(*m, cellsWhere(*m, CellType::SEG2, [](const auto& x) { return x[1] == -5.0; }));
    ASSERT_EQ(ld.size(), 5u);
    ASSERT_EQ(lb.size(), 5u);
    auto bd = ld;
    bd.insert(bd.end(), lb.begin(), lb.end());
    EXPECT_EQ(cellNames(*m, "BD"), bd);
    EXPECT_EQ(cellNames(*m, "B"), lb);
    EXPECT_FALSE(m->cellGroups.has("VIDE"));
    EXPECT_EQ(msg().alarmCount(), alarms + 1);
    EXPECT_EQ(cellNames(*m, "S2D"), namesOf(*m, cellsWhere(*m, CellType::QUAD4, [](const auto&) { return true; })));
    EXPECT_EQ(cellNames(*m, "S2D"), seq("M", 1, 25));  // code_aster named its quadrangles first
    EXPECT_EQ(nodeNames(*m, "LB"), nodesWhere(*m, [](const auto& x) { return x[1] == -5.0; }));
    EXPECT_EQ(nodeNames(*m, "LD"), nodesWhere(*m, [](const auto& x) { return x[0] == 5.0; }));
}

TEST_F(MeshCommands, OriePeau2dTurnsEdgesOutward) {
    auto m = load("ssnv511a.mmed");
    reverse(*m, 0);
    reverse(*m, 12);
    EXPECT_FALSE(outward(*m, 0, 2));
    KeywordSet kw = withMesh(m);
    kw.addOccurrence("ORIE_PEAU_2D")
        .setValues("GROUP_MA", {std::string("LB"), std::string("LD"), std::string("LH"), std::string("LG")});
    call("MODI_MAILLAGE", kw, m);
    for (int c = 0; c < 20; ++c) EXPECT_TRUE(outward(*m, c, 2)) << c;
    EXPECT_NE(msg().messText().find("NOMBRE DE MAILLES REORIENTEES : 2"), std::string::npos);
}

TEST_F(MeshCommands, MissingOrExistingGroupsAreUserErrors) {
    auto m = load("ssnv511a.mmed");
    KeywordSet kw = withMesh(m);
    auto& occ = kw.addOccurrence("CREA_GROUP_MA");
    occ.setValues("NOM", {std::string("X")});
    occ.setValues("INTERSEC", {std::string("LB"), std::string("NOPE")});
    EXPECT_EQ(errorOf([&] { call("DEFI_GROUP", kw, m); }),
              "CREA_GROUP_MA[1]/INTERSEC: the mesh MAILLAG has no cell group 'NOPE'");

    KeywordSet no = withMesh(m);
    no.addOccurrence("CREA_GROUP_NO").setValues("GROUP_MA", {std::string("SURF"), std::string("ABSENT")});
    EXPECT_EQ(errorOf([&] { call("DEFI_GROUP", no, m); }),
              "CREA_GROUP_NO[1]/GROUP_MA: the mesh MAILLAG has no cell group 'ABSENT'");

    KeywordSet twice = withMesh(m);
    auto& t = twice.addOccurrence("CREA_GROUP_MA");
    t.setValues("NOM", {std::string("SURF")});
    t.setValues("UNION", {std::string("LB")});
    EXPECT_EQ(errorOf([&] { call("DEFI_GROUP", twice, m); }),
              "CREA_GROUP_MA[1]/NOM: the cell group 'SURF' already exists in mesh MAILLAG");

    KeywordSet orient = withMesh(m);
    orient.addOccurrence("ORIE_PEAU_2D").setValues("GROUP_MA", {std::string("SURF")});
    EXPECT_EQ(errorOf([&] { call("MODI_MAILLAGE", orient, m); }),
              "cell M1 (QUAD4) is not a boundary cell of a 2D mesh");
}
