// LIRE_MAILLAGE and IMPR_RESU through the command registry: round trips read back by mdump4 and
// meshio, DEPL values, appending to a unit, Gauss-point fields, bad input.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "core/Units.hpp"
#include "fe/Result.hpp"
#include "med_io/MedReader.hpp"
#include "med_test_support.hpp"
#include "parser/Catalog.hpp"
#include "parser/CommandRegistry.hpp"

using namespace ma;

namespace {

class MedCommands : public ::testing::Test {
protected:
    void SetUp() override {
        msg().setEcho(false);
        dir = test::scratchDir(::testing::UnitTest::GetInstance()->current_test_info()->name());
        units.setOutputDir(dir);
    }
    void TearDown() override { std::filesystem::remove_all(dir); }

    ConceptPtr call(const std::string& command, const KeywordSet& kw, const std::string& resultName = {}) {
        const auto* fn = CommandRegistry::instance().find(command);
        if (!fn) throw std::runtime_error(command + " is not registered");
        CommandContext ctx;
        ctx.command = command;
        ctx.resultName = resultName;
        ctx.units = &units;
        auto out = (*fn)(validateKeywords(command, kw), ctx);
        if (out) out->name = resultName;
        return out;
    }

    std::shared_ptr<Mesh> lire(const std::string& file, const std::string& name = "MAILLAG") {
        units.setInput(20, file);
        KeywordSet kw;
        kw.setValues("FORMAT", {std::string("MED")});
        return std::dynamic_pointer_cast<Mesh>(call("LIRE_MAILLAGE", kw, name));
    }

    std::string dir;
    Units units;
};

// mdump4's full dump without the lines that name the file, the mesh or its description. With
// `numbering` false, also without what code_aster does not read back: the MED cell numbers (it
// numbers cells in file order, lrmmma), the family numbers (groups are read by family name) and the
// axis units (code_aster 11 wrote INCONNUE, miniaster writes INCONNU); the families are then
// compared by the groups they hold (their names and order in the file are the writer's choice).
std::string familiesByGroups(const std::string& dump) {
    const auto first = dump.find("- Famille ");
    if (first == std::string::npos) return dump;
    std::vector<std::string> families;
    std::istringstream in(dump.substr(first));
    std::string line;
    std::vector<std::string> groups;
    auto flush = [&] {
        std::sort(groups.begin(), groups.end());
        std::string family = "family:";
        for (const auto& g : groups) family += " " + g;
        families.push_back(family + "\n");
        groups.clear();
    };
    bool open = false;
    while (std::getline(in, line)) {
        if (line.rfind("- Famille ", 0) == 0) {
            if (open) flush();
            open = true;
        } else if (line.find("gro = ") != std::string::npos) {
            groups.push_back(line.substr(line.find("gro = ") + 6));
        }
    }
    if (open) flush();
    std::sort(families.begin(), families.end());
    std::string out = dump.substr(0, first);
    for (const auto& f : families) out += f;
    return out;
}

std::string mdumpBody(const std::string& path, bool numbering = true) {
    std::istringstream in(test::runCommand("mdump4 '" + path + "' NODALE FULL_INTERLACE 0"));
    std::string line, out;
    bool skipNext = false;
    while (std::getline(in, line)) {
        if (line.find("DUMP DU FICHIER") != std::string::npos || line.find("En-tete du fichier") != std::string::npos ||
            line.find("Description associee") != std::string::npos ||
            line.find("Nom du maillage") != std::string::npos ||
            line.find("MAILLAGE DE CALCUL |") != std::string::npos || line.find("(**") == 0)
            continue;
        if (!numbering) {
            if (skipNext) {
                skipNext = false;
                continue;
            }
            if (line.find("- Numeros :") != std::string::npos || line.find("ros de familles") != std::string::npos ||
                line.find("Numeros des familles") != std::string::npos ||
                line.find("Unites des coordonnees") != std::string::npos)
                skipNext = true;
            const auto at = line.find(" et de numero ");
            if (at != std::string::npos) line = line.substr(0, at);
        }
        out += line + "\n";
    }
    return numbering ? out : familiesByGroups(out);
}

std::shared_ptr<Result> makeResult(const std::shared_ptr<Mesh>& mesh, const std::string& name, int steps) {
    auto res = std::make_shared<Result>("evol_elas");
    res->name = name;
    res->mesh = mesh;
    for (int s = 1; s <= steps; ++s) {
        ResultStep step;
        step.order = s;
        step.inst = 0.5 * s;
        auto depl = std::make_shared<NodalField>();
        depl->resize(mesh, {"DX", "DY", "H1X"});
        for (int i = 0; i < mesh->nodeCount(); ++i) {
            depl->set(i, 0, s * (0.1 * mesh->coords[i][0] + 1.0 / 3.0));
            depl->set(i, 1, -std::sqrt(2.0) * mesh->coords[i][1] * mesh->coords[i][0]);
            if (i % 4 == 0) depl->set(i, 2, 1e-3 * i);  // enriched nodes only
        }
        step.nodalFields.emplace_back("DEPL", depl);
        res->steps.push_back(step);
    }
    return res;
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const UserError& e) { return e.what(); }
    return "(no error)";
}

// The mesh as a .mail text in IMPR_RESU(FORMAT='ASTER')'s layout: 1PE21.14 coordinates, one
// block per run of cells of one type, 7 nodes or members per line.
std::string asMailText(const Mesh& m) {
    std::string out =
        "TITRE\n written by the miniaster tests\nFINSF\n" + std::string(m.dim == 2 ? "COOR_2D" : "COOR_3D") + "\n";
    for (int i = 0; i < m.nodeCount(); ++i) {
        out += fmt::format(" {}", m.nodeNames[size_t(i)]);
        for (int d = 0; d < m.dim; ++d) out += fmt::format(" {:.16E}", m.coords[size_t(i)][size_t(d)]);
        out += "\n";
    }
    out += "FINSF\n";
    auto wrapped = [&](const std::string& head, const std::vector<std::string>& items) {
        out += head;
        for (size_t k = 0; k < items.size(); ++k) out += (k > 0 && k % 7 == 0 ? "\n          " : " ") + items[k];
        out += "\n";
    };
    for (int c = 0; c < m.cellCount(); ++c) {
        if (c == 0 || m.cellTypes[size_t(c)] != m.cellTypes[size_t(c - 1)])
            out += (c == 0 ? "" : "FINSF\n") + cellTypeName(m.cellTypes[size_t(c)]) + "\n";
        std::vector<std::string> nodes;
        for (int n : m.cellNodes(c)) nodes.push_back(m.nodeNames[size_t(n)]);
        wrapped(fmt::format(" {:8}", m.cellNames[size_t(c)]), nodes);
    }
    out += "FINSF\n";
    for (const auto* groups : {&m.nodeGroups, &m.cellGroups})
        for (const auto& g : groups->names()) {
            std::vector<std::string> members;
            for (int e : groups->get(g))
                members.push_back(groups == &m.nodeGroups ? m.nodeNames[size_t(e)] : m.cellNames[size_t(e)]);
            out += std::string(groups == &m.nodeGroups ? "GROUP_NO" : "GROUP_MA") + "\n " + g + "\n";
            wrapped("", members);
            out += "FINSF\n";
        }
    return out + "FIN\n";
}

}  // namespace

TEST_F(MedCommands, LireMaillageLogsCountsAndGroups) {
    auto m = lire(test::astest("ssnv511g.mmed"));
    ASSERT_TRUE(m);
    EXPECT_EQ(m->nodeCount(), 72);
    const auto& mess = msg().messText();
    EXPECT_NE(mess.find("NOMBRE DE NOEUDS                          72\n"), std::string::npos) << mess;
    EXPECT_NE(mess.find("NOMBRE DE MAILLES                        105\n"), std::string::npos) << mess;
    EXPECT_NE(mess.find(" SEG2                  10\n"), std::string::npos) << mess;
    EXPECT_NE(mess.find(" HEXA8                 25\n"), std::string::npos) << mess;
    EXPECT_NE(mess.find(" QUAD4                 70\n"), std::string::npos) << mess;
    EXPECT_NE(mess.find("NOMBRE DE GROUPES DE MAILLES               7\n"), std::string::npos) << mess;
    EXPECT_NE(mess.find(" ENV                             70\n"), std::string::npos) << mess;
    EXPECT_NE(mess.find(" MAILLE                          25\n"), std::string::npos) << mess;
    // code_aster's own mesh: every HEXA8 is left-handed in its node order, reported once.
    EXPECT_NE(mess.find("mesh MAILLAG: 25 cells are left-handed in code_aster's node order (negative Jacobian): 25 of "
                        "25 HEXA8"),
              std::string::npos)
        << mess;
}

TEST_F(MedCommands, RoundTripGivesTheSameFileForMdump4AndMeshio) {
    for (const char* file :
         {"ssnv511a.mmed", "ssnv511b.mmed", "ssnv511c.mmed", "ssnv511d.mmed", "ssnv511g.mmed", "ssnv511h.mmed"}) {
        const std::string original = test::astest(file);
        auto m = lire(original);
        KeywordSet kw;
        kw.setValues("UNITE", {81LL});
        kw.addOccurrence("RESU").setValues("MAILLAGE", {ConceptPtr(m)});
        units.setOutput(81, dir + "/" + file + ".rmed");
        call("IMPR_RESU", kw);
        const std::string written = dir + "/" + file + ".rmed";
        ASSERT_TRUE(std::filesystem::exists(written));
        EXPECT_FALSE(std::filesystem::exists(temporaryPathFor(written)));
        // mdump4: nodes, names, cells, families and groups identical to the original (code_aster's
        // own file); a second round trip gives the same file to the byte, numbers included.
        EXPECT_EQ(mdumpBody(written, false), mdumpBody(original, false)) << file;
        auto again = lire(written);
        KeywordSet kw2;
        kw2.setValues("UNITE", {82LL});
        kw2.addOccurrence("RESU").setValues("MAILLAGE", {ConceptPtr(again)});
        units.setOutput(82, written + ".again.rmed");
        call("IMPR_RESU", kw2);
        EXPECT_EQ(mdumpBody(written + ".again.rmed"), mdumpBody(written)) << file;
        // meshio: same nodes, cells and groups.
        auto a = test::probeMesh(original), b = test::probeMesh(written);
        EXPECT_EQ(a.nodes, b.nodes) << file;
        EXPECT_EQ(a.cells, b.cells) << file;
        EXPECT_EQ(a.cellGroups, b.cellGroups) << file;
        EXPECT_EQ(a.nodeGroups, b.nodeGroups) << file;
        // The mesh is named after the concept.
        EXPECT_EQ(med::meshNames(written), std::vector<std::string>{"MAILLAG"});
    }
}

// The same mesh as a .mail text (LIRE_MAILLAGE FORMAT='ASTER') gives the same concept: written
// to MED, the same mdump4 dump as the original MED file.
TEST_F(MedCommands, MailTextOfAMedMeshGivesTheSameMesh) {
    for (const char* file : {"ssnv511a.mmed", "ssnv511b.mmed", "ssnv511d.mmed", "ssnv511g.mmed", "ssnv511h.mmed"}) {
        const std::string original = test::astest(file);
        auto fromMed = lire(original);
        const std::string mail = dir + "/" + file + ".mail";
        std::ofstream(mail) << asMailText(*fromMed);
        units.setInput(20, mail);
        KeywordSet read;
        read.setValues("FORMAT", {std::string("ASTER")});
        auto fromMail = std::dynamic_pointer_cast<Mesh>(call("LIRE_MAILLAGE", read, "MAILLAG"));
        ASSERT_TRUE(fromMail);
        EXPECT_EQ(fromMail->dim, fromMed->dim) << file;
        EXPECT_EQ(fromMail->coords, fromMed->coords) << file;
        EXPECT_EQ(fromMail->nodeNames, fromMed->nodeNames) << file;
        EXPECT_EQ(fromMail->cellNames, fromMed->cellNames) << file;
        EXPECT_EQ(fromMail->connectivity, fromMed->connectivity) << file;
        EXPECT_EQ(fromMail->nodeGroups.names(), fromMed->nodeGroups.names()) << file;
        EXPECT_EQ(fromMail->cellGroups.names(), fromMed->cellGroups.names()) << file;
        KeywordSet kw;
        kw.setValues("UNITE", {81LL});
        kw.addOccurrence("RESU").setValues("MAILLAGE", {ConceptPtr(fromMail)});
        units.setOutput(81, mail + ".rmed");
        call("IMPR_RESU", kw);
        EXPECT_EQ(mdumpBody(mail + ".rmed", false), mdumpBody(original, false)) << file;
    }
}

TEST_F(MedCommands, DeplWrittenIsReadBackByMeshioAndMdump4) {
    auto m = lire(test::astest("ssnv511a.mmed"));
    auto res = makeResult(m, "UTOT1", 1);
    KeywordSet kw;
    auto& occ = kw.addOccurrence("RESU");
    occ.setValues("RESULTAT", {ConceptPtr(res)});
    occ.setValues("NOM_CHAM", {std::string("DEPL")});
    call("IMPR_RESU", kw);
    const std::string path = dir + "/fort.80";
    auto values = test::probeField(path, "UTOT1___DEPL");
    const auto& depl = *res->steps[0].nodal("DEPL");
    ASSERT_EQ(values.size(), size_t(m->nodeCount()));
    for (int i = 0; i < m->nodeCount(); ++i) {
        ASSERT_EQ(values[i].size(), 3u);
        EXPECT_EQ(values[i][0], depl.at(i, 0));
        EXPECT_EQ(values[i][1], depl.at(i, 1));
        EXPECT_EQ(values[i][2], i % 4 == 0 ? depl.at(i, 2) : 0.0);  // absent component written as 0
    }
    const auto dump = test::runCommand("mdump4 '" + path + "' NODALE FULL_INTERLACE 0");
    EXPECT_NE(dump.find("CHAMP |UTOT1___DEPL| A L'ÉTAPE DE CALCUL (n°dt,n°it)=( 01, 01)"), std::string::npos) << dump;
    EXPECT_NE(dump.find("Nom des composantes : |DX              DY              H1X             |"), std::string::npos);
    EXPECT_NE(dump.find("Valeur de la date du champ 0.500000"), std::string::npos);
    EXPECT_EQ(dump.find("ERR"), std::string::npos);
}

TEST_F(MedCommands, SecondImprResuOnTheSameUnitAddsToTheFile) {
    auto m = lire(test::astest("ssnv511a.mmed"));
    auto r1 = makeResult(m, "RES_XFEM", 2);
    auto r2 = makeResult(m, "UTOT1", 1);
    for (auto& r : {r1, r2}) {
        KeywordSet kw;
        kw.setValues("UNITE", {82LL});
        auto& occ = kw.addOccurrence("RESU");
        occ.setValues("RESULTAT", {ConceptPtr(r)});
        if (r == r1) occ.setValues("TOUT_ORDRE", {std::string("OUI")});
        call("IMPR_RESU", kw);
    }
    const auto dump = test::runCommand("mdump4 '" + dir + "/fort.82' NODALE FULL_INTERLACE 0");
    EXPECT_NE(dump.find("CHAMP |RES_XFEMDEPL| A L'ÉTAPE DE CALCUL (n°dt,n°it)=( 01, 01)"), std::string::npos);
    EXPECT_NE(dump.find("CHAMP |RES_XFEMDEPL| A L'ÉTAPE DE CALCUL (n°dt,n°it)=( 02, 02)"), std::string::npos);
    EXPECT_NE(dump.find("CHAMP |UTOT1___DEPL| A L'ÉTAPE DE CALCUL (n°dt,n°it)=( 01, 01)"), std::string::npos);
    // One mesh only.
    EXPECT_EQ(med::meshNames(dir + "/fort.82").size(), 1u);
}

TEST_F(MedCommands, PartialNodalFieldUsesAProfile) {
    auto m = lire(test::astest("ssnv511a.mmed"));
    auto f = std::make_shared<NodalField>();
    f->resize(m, {"DX", "DY"});
    for (int i = 0; i < 6; ++i) f->set(i, 0, 10.0 + i), f->set(i, 1, -1.0 * i);  // bottom row only
    f->name = "CH";
    KeywordSet kw;
    kw.addOccurrence("RESU").setValues("CHAM_GD", {ConceptPtr(f)});
    call("IMPR_RESU", kw);
    const auto dump = test::runCommand("mdump4 '" + dir + "/fort.80' NODALE FULL_INTERLACE 0");
    EXPECT_NE(dump.find("CHAMP |CH| A L'ÉTAPE DE CALCUL (n°dt,n°it)=(-01,-01)"), std::string::npos) << dump;
    EXPECT_NE(dump.find("Il y a 6 entités qui portent des valeurs"), std::string::npos) << dump;
    EXPECT_NE(dump.find("| 15.000000  -5.000000 |"), std::string::npos) << dump;
}

TEST_F(MedCommands, GaussFieldWithLocalisations) {
    auto m = lire(test::astest("ssnv511a.mmed"));
    // SIEF_ELGA-like field on the 25 QUAD4: 4 standard points, except one cell with 3 points
    // (as an X-FEM sub-cell rule would give), and no value on the SEG2 cells.
    auto g = std::make_shared<GaussField>();
    g->mesh = m;
    g->components = {"SIXX", "SIYY"};
    const double a = 1.0 / std::sqrt(3.0);
    const std::array<std::array<double, 3>, 4> std4{{{-a, -a, 0}, {a, -a, 0}, {a, a, 0}, {-a, a, 0}}};
    const std::array<std::array<double, 3>, 3> odd3{{{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0, 0.5, 0}}};
    for (int c = 20; c < 45; ++c) {
        g->cells.push_back(c);
        const bool odd = c == 32;
        const int n = odd ? 3 : 4;
        for (int p = 0; p < n; ++p) {
            g->pointRefCoords.push_back(odd ? odd3[p] : std4[p]);
            g->pointCoords.push_back({0, 0, 0});
            g->pointWeights.push_back(odd ? 4.0 / 3.0 : 1.0);  // 2x2 cells: |J| = 1
            g->pointSubcell.push_back(0);
            g->values.push_back(100.0 * c + p);
            g->values.push_back(-1.0 * p);
        }
        g->pointOffsets.push_back(int(g->pointWeights.size()));
    }
    auto res = std::make_shared<Result>("evol_elas");
    res->name = "RES";
    res->mesh = m;
    ResultStep step;
    step.order = 1;
    step.gaussFields.emplace_back("SIEF_ELGA", g);
    res->steps.push_back(step);
    KeywordSet kw;
    kw.addOccurrence("RESU").setValues("RESULTAT", {ConceptPtr(res)});
    call("IMPR_RESU", kw);
    const auto dump = test::runCommand("mdump4 '" + dir + "/fort.80' NODALE FULL_INTERLACE 0");
    EXPECT_EQ(dump.find("ERR"), std::string::npos) << dump;
    EXPECT_NE(dump.find("CHAMP |RES_____SIEF_ELGA|"), std::string::npos) << dump;
    EXPECT_NE(dump.find("Il y a 24 entités qui portent des valeurs"), std::string::npos) << dump;
    EXPECT_NE(dump.find("Il y a 1 entités qui portent des valeurs"), std::string::npos) << dump;
    EXPECT_NE(dump.find("LOC_QUAD4_4PG_1"), std::string::npos) << dump;
    EXPECT_NE(dump.find("LOC_QUAD4_3PG_2"), std::string::npos) << dump;
    // Values of cell M33 (the odd one): 3 points.
    EXPECT_NE(dump.find("3200.000000  -0.000000"), std::string::npos) << dump;
    EXPECT_NE(dump.find("3202.000000  -2.000000"), std::string::npos) << dump;

    // NOM_CMP selects the columns of a field at Gauss points too (it was ignored).
    KeywordSet only;
    only.setValues("UNITE", {81LL});
    auto& occ = only.addOccurrence("RESU");
    occ.setValues("RESULTAT", {ConceptPtr(res)});
    occ.setValues("NOM_CMP", {std::string("SIYY")});
    call("IMPR_RESU", only);
    const auto one = test::runCommand("mdump4 '" + dir + "/fort.81' NODALE FULL_INTERLACE 0");
    EXPECT_NE(one.find("Nom des composantes : |SIYY            |"), std::string::npos) << one;
    EXPECT_EQ(one.find("SIXX"), std::string::npos) << one;
    EXPECT_NE(one.find("-2.000000"), std::string::npos) << one;
    EXPECT_EQ(one.find("3202.000000"), std::string::npos) << one;
}

TEST_F(MedCommands, BadInputGivesClearErrors) {
    units.setInput(20, dir + "/nothing.med");
    KeywordSet kw;
    EXPECT_EQ(errorOf([&] { call("LIRE_MAILLAGE", kw, "M"); }), "MED file '" + dir + "/nothing.med' does not exist");
    KeywordSet other;
    other.setValues("UNITE", {21LL});
    EXPECT_NE(errorOf([&] { call("LIRE_MAILLAGE", other, "M"); }).find("logical unit 21"), std::string::npos);
    units.setInput(20, test::astest("ssnv511a.mmed"));
    KeywordSet named;
    named.setValues("NOM_MED", {std::string("MAIL2")});
    EXPECT_EQ(errorOf([&] { call("LIRE_MAILLAGE", named, "M"); }),
              "NOM_MED='MAIL2': MED file '" + test::astest("ssnv511a.mmed") +
                  "' has no mesh of that name; meshes in the file: 'MA'");
    KeywordSet gibi;
    gibi.setValues("FORMAT", {std::string("GIBI")});
    EXPECT_THROW(call("LIRE_MAILLAGE", gibi, "M"), NotImplemented);
}

TEST_F(MedCommands, FailedAppendLeavesTheFileAsItWas) {
    auto a = lire(test::astest("ssnv511a.mmed"));
    auto g = lire(test::astest("ssnv511g.mmed"));  // another mesh under the same name MAILLAG
    auto print = [&](const std::shared_ptr<Mesh>& m) {
        KeywordSet kw;
        kw.setValues("UNITE", {83LL});
        kw.addOccurrence("RESU").setValues("MAILLAGE", {ConceptPtr(m)});
        call("IMPR_RESU", kw);
    };
    print(a);
    const std::string path = dir + "/fort.83";
    const auto before = mdumpBody(path);
    EXPECT_EQ(errorOf([&] { print(g); }),
              "the MED file already holds a mesh named 'MAILLAG' with 36 nodes, not the 72 nodes of the mesh to print");
    EXPECT_EQ(mdumpBody(path), before);
    size_t files = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        files += e.path().filename().string().rfind("fort.83", 0) == 0;
    EXPECT_EQ(files, 1u);  // no temporary file left
}

TEST_F(MedCommands, InstAndNomCmpSelectWhatIsPrinted) {
    auto m = lire(test::astest("ssnv511c.mmed"));
    auto res = makeResult(m, "U", 3);  // INST 0.5, 1.0, 1.5
    KeywordSet kw;
    auto& occ = kw.addOccurrence("RESU");
    occ.setValues("RESULTAT", {ConceptPtr(res)});
    occ.setValues("NOM_CHAM", {std::string("DEPL")});
    occ.setValues("INST", {1.0});
    occ.setValues("NOM_CMP", {std::string("DY"), std::string("DX")});
    call("IMPR_RESU", kw);
    const auto dump = test::runCommand("mdump4 '" + dir + "/fort.80' NODALE FULL_INTERLACE 0");
    EXPECT_NE(dump.find("CHAMP |U_______DEPL| A L'ÉTAPE DE CALCUL (n°dt,n°it)=( 02, 02)"), std::string::npos) << dump;
    EXPECT_EQ(dump.find("(n°dt,n°it)=( 01, 01)"), std::string::npos);
    EXPECT_EQ(dump.find("(n°dt,n°it)=( 03, 03)"), std::string::npos);
    EXPECT_NE(dump.find("Nom des composantes : |DY              DX              |"), std::string::npos) << dump;
    auto values = test::probeField(dir + "/fort.80", "U_______DEPL");
    const auto& depl = *res->steps[1].nodal("DEPL");
    ASSERT_EQ(values.size(), size_t(m->nodeCount()));
    for (int i = 0; i < m->nodeCount(); ++i) {
        EXPECT_EQ(values[i][0], depl.at(i, 1));
        EXPECT_EQ(values[i][1], depl.at(i, 0));
    }
    KeywordSet missing;
    auto& bad = missing.addOccurrence("RESU");
    bad.setValues("RESULTAT", {ConceptPtr(res)});
    bad.setValues("NUME_ORDRE", {7LL});
    EXPECT_EQ(errorOf([&] { call("IMPR_RESU", missing); }), "result U has no NUME_ORDRE 7");
}
