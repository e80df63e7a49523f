// DEFI_GROUP and MODI_MAILLAGE on the astest meshes, called through the command registry with
// keyword trees built by hand: exact memberships and orientations.
#include <gtest/gtest.h>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "core/Units.hpp"
#include "med_io/MedReader.hpp"
#include "mesh/MeshQueries.hpp"
#include "mesh/SkinOrientation.hpp"
#include "med_test_support.hpp"
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
    for (int i = from; step > 0 ? i <= to : i >= to; i += step) out.push_back(std::string(prefix).append(std::to_string(i)));
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
    } catch (const UserError& e) {
        return e.what();
    }
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
    // Both layers (38 nodes each) of the x = -5 and x = +5 columns.
    EXPECT_EQ(nodeNames(*m, "SG"), (std::vector<std::string>{"N1", "N7", "N13", "N19", "N25", "N31", "N39", "N45",
                                                             "N51", "N57", "N63", "N69"}));
    EXPECT_EQ(nodeNames(*m, "SD"), (std::vector<std::string>{"N6", "N12", "N18", "N24", "N30", "N36", "N44", "N50",
                                                             "N56", "N62", "N68", "N74"}));
}

TEST_F(MeshCommands, OriePeau3dThenFaceNormaleOnSsnv511g) {
    auto m = load("ssnv511g.mmed");
    // Turn three skin faces inward (one bottom, one top, one of SD).
    for (int c : {0, 30, 52}) reverse(*m, c);
    {
        // Before orientation, FACE_NORMALE with VERI_SIGNE misses the turned bottom face and
        // takes the turned top face.
        KeywordSet kw = withMesh(m);
        auto& f = kw.addOccurrence("CREA_GROUP_MA");
        f.setValues("NOM", {std::string("FACE0")});
        f.setValues("OPTION", {std::string("FACE_NORMALE")});
        f.setValues("VECT_NORMALE", {0.0, 0.0, -1.0});
        call("DEFI_GROUP", kw, m);
        auto expected = seq("M", 2, 25);
        expected.push_back("M31");
        EXPECT_EQ(cellNames(*m, "FACE0"), expected);
    }
    KeywordSet kw = withMesh(m);
    kw.addOccurrence("ORIE_PEAU_3D").setValues("GROUP_MA", {std::string("ENV"), std::string("SD"), std::string("SG")});
    call("MODI_MAILLAGE", kw, m);
    EXPECT_NE(msg().messText().find("NOMBRE DE MAILLES REORIENTEES : 3"), std::string::npos);
    for (int c : m->cellGroups.get("ENV")) EXPECT_TRUE(outward(*m, c, 3)) << m->cellNames[c];

    KeywordSet dg = withMesh(m);
    const std::vector<std::pair<std::string, std::vector<double>>> wanted{
        {"FACE", {0, 0, -1}}, {"SH", {0, 1, 0}}, {"SB", {0, -1, 0}}, {"TOP", {0, 0, 1}}};
    for (const auto& [name, v] : wanted) {
        auto& occ = dg.addOccurrence("CREA_GROUP_MA");
        occ.setValues("NOM", {name});
        occ.setValues("OPTION", {std::string("FACE_NORMALE")});
        occ.setValues("VECT_NORMALE", {v[0], v[1], v[2]});
    }
    call("DEFI_GROUP", dg, m);
    EXPECT_EQ(cellNames(*m, "FACE"), seq("M", 1, 25));
    EXPECT_EQ(cellNames(*m, "TOP"), seq("M", 26, 50));
    EXPECT_EQ(cellNames(*m, "SH"), seq("M", 61, 65));
    EXPECT_EQ(cellNames(*m, "SB"), seq("M", 66, 70));
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

    auto ld = seq("M", 6, 10), lb = seq("M", 1, 5);
    auto bd = ld;
    bd.insert(bd.end(), lb.begin(), lb.end());
    EXPECT_EQ(cellNames(*m, "BD"), bd);
    EXPECT_EQ(cellNames(*m, "B"), lb);
    EXPECT_FALSE(m->cellGroups.has("VIDE"));
    EXPECT_EQ(msg().alarmCount(), alarms + 1);
    EXPECT_EQ(cellNames(*m, "S2D"), seq("M", 21, 45));
    EXPECT_EQ(nodeNames(*m, "LB"), seq("N", 1, 6));
    EXPECT_EQ(nodeNames(*m, "LD"), (std::vector<std::string>{"N6", "N12", "N18", "N24", "N30", "N36"}));
}

TEST_F(MeshCommands, OriePeau2dTurnsEdgesOutward) {
    auto m = load("ssnv511a.mmed");
    reverse(*m, 0);
    reverse(*m, 12);
    EXPECT_FALSE(outward(*m, 0, 2));
    KeywordSet kw = withMesh(m);
    kw.addOccurrence("ORIE_PEAU_2D").setValues(
        "GROUP_MA", {std::string("LB"), std::string("LD"), std::string("LH"), std::string("LG")});
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
              "CREA_GROUP_MA[1]/INTERSEC: the cell group 'NOPE' does not exist in mesh MAILLAG");

    KeywordSet no = withMesh(m);
    no.addOccurrence("CREA_GROUP_NO").setValues("GROUP_MA", {std::string("SURF"), std::string("ABSENT")});
    EXPECT_EQ(errorOf([&] { call("DEFI_GROUP", no, m); }),
              "CREA_GROUP_NO[1]/GROUP_MA: the cell group 'ABSENT' does not exist in mesh MAILLAG");

    KeywordSet twice = withMesh(m);
    auto& t = twice.addOccurrence("CREA_GROUP_MA");
    t.setValues("NOM", {std::string("SURF")});
    t.setValues("UNION", {std::string("LB")});
    EXPECT_EQ(errorOf([&] { call("DEFI_GROUP", twice, m); }),
              "CREA_GROUP_MA[1]/NOM: the cell group 'SURF' already exists in mesh MAILLAG");

    KeywordSet orient = withMesh(m);
    orient.addOccurrence("ORIE_PEAU_2D").setValues("GROUP_MA", {std::string("SURF")});
    EXPECT_EQ(errorOf([&] { call("MODI_MAILLAGE", orient, m); }),
              "cell M21 (QUAD4) is not a boundary cell of a 2D mesh");
}
