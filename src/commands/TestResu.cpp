// TEST_RESU: a value of a result's field (RESU), of a nodal field (CHAM_NO) or of a field at
// integration points (CHAM_ELEM) checked against VALE_CALC (non-regression) and VALE_REFE
// (reference), with code_aster's report text (trresu, trchno, trchel) and the lines recorded for
// the run summary, as TEST_TABLE.
#include <fmt/format.h>

#include <optional>

#include "commands/TestKeywords.hpp"
#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "fe/Result.hpp"
#include "parser/CommandRegistry.hpp"
#include "post/FieldProbe.hpp"
#include "post/PostMessages.hpp"
#include "post/TestHeader.hpp"

namespace ma {
namespace {

std::optional<std::string> component(const KeywordSet& occ) {
    if (!occ.has("NOM_CMP")) return std::nullopt;
    return occ.text("NOM_CMP");
}

// The place keywords TYPE_TEST ignores (CALCULEL6_96).
void warnIgnoredPlaces(const KeywordSet& occ, std::initializer_list<const char*> places) {
    std::string given;
    for (const char* k : places)
        if (occ.has(k)) given += (given.empty() ? "" : ", ") + std::string(k);
    if (!given.empty()) msg().alarm(CALCULEL6_96, occ.path(), given);
}

// The node named by NOEUD, or the one node of GROUP_NO (code_aster CALCULEL5_20 for a larger group).
int selectedNode(const KeywordSet& occ, const Mesh& mesh) {
    if (occ.has("NOEUD")) {
        const auto names = occ.texts("NOEUD");
        if (names.size() != 1) throw UserError(occ.pathOf("NOEUD") + ": one node is tested, give one name");
        const int node = mesh.findNode(names.front());
        if (node < 0)
            throw UserError(fmt::format("{}: mesh {} has no node {}", occ.pathOf("NOEUD"), mesh.name, names[0]));
        return node;
    }
    if (occ.has("GROUP_NO")) {
        const auto groups = occ.texts("GROUP_NO");
        if (groups.size() != 1) throw UserError(occ.pathOf("GROUP_NO") + ": one node is tested, give one group");
        if (!mesh.nodeGroups.has(groups[0]))
            throw UserError(
                fmt::format("{}: mesh {} has no node group {}", occ.pathOf("GROUP_NO"), mesh.name, groups[0]));
        const auto& members = mesh.nodeGroups.get(groups[0]);
        if (members.size() != 1)
            throw UserError(fmt::format("{}: group {} holds {} nodes, TEST_RESU tests one (code_aster CALCULEL5_20)",
                                        occ.pathOf("GROUP_NO"), groups[0], members.size()));
        return members.front();
    }
    throw UserError(occ.path() + ": give NOEUD or GROUP_NO (or TYPE_TEST to test the whole field)");
}

// The cell named by MAILLE, or the one cell of GROUP_MA (code_aster TEST0_20 for a larger group).
int selectedCell(const KeywordSet& occ, const Mesh& mesh) {
    if (occ.has("MAILLE")) {
        const int cell = mesh.findCell(occ.text("MAILLE"));
        if (cell < 0)
            throw UserError(
                fmt::format("{}: mesh {} has no cell {}", occ.pathOf("MAILLE"), mesh.name, occ.text("MAILLE")));
        return cell;
    }
    if (occ.has("GROUP_MA")) {
        const std::string group = occ.text("GROUP_MA");
        if (!mesh.cellGroups.has(group))
            throw UserError(fmt::format("{}: mesh {} has no cell group {}", occ.pathOf("GROUP_MA"), mesh.name, group));
        const auto& members = mesh.cellGroups.get(group);
        if (members.size() != 1)
            throw UserError(fmt::format("{}: group {} holds {} cells, TEST_RESU tests one (code_aster TEST0_20)",
                                        occ.pathOf("GROUP_MA"), group, members.size()));
        return members.front();
    }
    throw UserError(occ.path() + ": give MAILLE or GROUP_MA (or TYPE_TEST to test the whole field)");
}

// TYPE_TEST over `field` (a NodalField or a GaussField): TYPE_TEST and NOM_CMP in the header, the
// reduction; the place keywords among `places` are ignored (CALCULEL6_96).
template <class Field>
double reduced(const KeywordSet& occ, const Field& field, TestHeader& header,
               std::initializer_list<const char*> places) {
    warnIgnoredPlaces(occ, places);
    header.add("TYPE_TEST", occ.text("TYPE_TEST"));
    const auto cmp = component(occ);
    if (cmp) header.add("NOM_CMP", *cmp);
    return reduceField(field, reductionOf(occ.text("TYPE_TEST")), cmp, occ.path());
}

// The tested node, added to the header as NOEUD or GROUP_NO.
int nodePlace(const KeywordSet& occ, const Mesh& mesh, TestHeader& header) {
    const int node = selectedNode(occ, mesh);
    const char* keyword = occ.has("NOEUD") ? "NOEUD" : "GROUP_NO";
    header.add(keyword, occ.texts(keyword).front());
    return node;
}

// POINT and SOUS_POINT of a field at integration points; miniaster's points have one sub-point.
int selectedPoint(const KeywordSet& occ) {
    if (!occ.has("POINT")) throw UserError(occ.path() + ": give POINT, the integration point tested in the cell");
    if (occ.has("SOUS_POINT") && occ.integer("SOUS_POINT") != 1)
        throw UserError(fmt::format("{}={}: the points of miniaster's fields have one sub-point",
                                    occ.pathOf("SOUS_POINT"), occ.integer("SOUS_POINT")));
    return static_cast<int>(occ.integer("POINT"));
}

// The tested cell and point, added to the header (MAILLE or GROUP_MA, POINT, SOUS_POINT).
std::pair<int, int> pointPlace(const KeywordSet& occ, const Mesh& mesh, TestHeader& header) {
    const int cell = selectedCell(occ, mesh);
    const char* keyword = occ.has("MAILLE") ? "MAILLE" : "GROUP_MA";
    header.add(keyword, occ.text(keyword));
    const int point = selectedPoint(occ);
    header.add("POINT", std::to_string(point));
    if (occ.has("SOUS_POINT")) header.add("SOUS_POINT", "1");
    return {cell, point};
}

// One tested value with its header, computed before anything is printed: an error in any
// occurrence leaves no partial block behind.
struct Tested {
    TestChecks checks;
    CheckScale scale;
    TestHeader header;
    double value = 0.0;
    bool labelBlank = true;  // trchel writes its label line with format (A): no leading blank
    bool blankAfter = true;  // the "  " line after the occurrence (not after trchel's TYPE_TEST)
};

// RESU: the field NOM_CHAM of RESULTAT at NUME_ORDRE / INST (trresu).
Tested testResult(const KeywordSet& occ, const CommandContext& ctx) {
    const TestChecks checks = test_keywords::checks(occ, "TEST_RESU", ctx);
    const CheckScale scale = checkScale(checks);
    auto result = occ.object<Result>("RESULTAT");
    const ResultStep* step = nullptr;
    if (occ.has("NUME_ORDRE")) {
        step = &result->step(static_cast<int>(occ.integer("NUME_ORDRE")));
    } else {
        // As trprec: INST is matched with the second CRITERE / TOLE_MACHINE (default: the first).
        const auto crit = occ.has("CRITERE") ? occ.texts("CRITERE") : std::vector<std::string>{"RELATIF"};
        const auto tole = occ.has("TOLE_MACHINE") ? occ.reals("TOLE_MACHINE") : std::vector<double>{1.0e-6};
        step = &result->stepAtInst(occ.real("INST"), tole.back(), crit.back() == "RELATIF");
    }
    const std::string name = occ.text("NOM_CHAM");
    const auto nodal = step->nodal(name);
    const auto gauss = step->gauss(name);
    if (!nodal && !gauss)
        throw UserError(fmt::format("{}: result {} has no field {} at NUME_ORDRE {}", occ.pathOf("NOM_CHAM"),
                                    result->name, name, step->order));
    TestHeader header("RESULTAT", result->name);
    header.add("NUME_ORDRE", std::to_string(step->order));
    header.add("NOM_CHAM", name);
    const std::string where = occ.path();
    if (occ.has("TYPE_TEST")) {
        const std::initializer_list<const char*> places{"NOEUD", "GROUP_NO", "POINT"};
        const double value = nodal ? reduced(occ, *nodal, header, places) : reduced(occ, *gauss, header, places);
        return {checks, scale, header, value};
    }
    if (!occ.has("NOM_CMP")) throw UserError(where + ": give NOM_CMP (or TYPE_TEST to test the whole field)");
    const std::string cmp = occ.text("NOM_CMP");
    header.add("NOM_CMP", cmp);
    if (nodal) {
        if (occ.has("POINT"))
            throw UserError(
                fmt::format("{}: field {} of result {} is a nodal field, POINT is meaningless (code_aster "
                            "CALCULEL6_97)",
                            occ.pathOf("POINT"), name, result->name));
        const int node = nodePlace(occ, *nodal->mesh, header);
        return {checks, scale, header, nodalValue(*nodal, node, cmp, where)};
    }
    for (const char* k : {"NOEUD", "GROUP_NO"})
        if (occ.has(k))
            throw UserError(
                fmt::format("{}: field {} is at integration points (no value at nodes): give MAILLE and POINT",
                            occ.pathOf(k), name));
    const auto [cell, point] = pointPlace(occ, *gauss->mesh, header);
    return {checks, scale, header, gaussValue(*gauss, cell, point, cmp, where)};
}

// The start shared by CHAM_NO and CHAM_ELEM (trchno, trchel): NOM_CMP and VALE_ABS in the header.
TestHeader fieldHeader(const KeywordSet& occ, const std::string& kind, const Concept& field) {
    TestHeader header(kind, field.name);
    if (occ.has("NOM_CMP")) header.add("NOM_CMP", occ.text("NOM_CMP"));
    if (occ.text("VALE_ABS") == "OUI") header.add("VALE_ABS", "OUI");
    return header;
}

// CHAM_NO: a nodal field, at a node or reduced (trchno).
Tested testNodalField(const KeywordSet& occ, const CommandContext& ctx) {
    const TestChecks checks = test_keywords::checks(occ, "TEST_RESU", ctx);
    const CheckScale scale = checkScale(checks);
    const auto field = occ.object<NodalField>("CHAM_GD");
    TestHeader header = fieldHeader(occ, "CHAM_NO", *field);
    const auto cmp = component(occ);
    if (occ.has("TYPE_TEST")) {
        const double value = reduced(occ, *field, header, {"NOEUD", "GROUP_NO"});  // completes the header
        return {checks, scale, header, value};
    }
    const int node = nodePlace(occ, *field->mesh, header);
    if (!cmp) throw UserError(occ.path() + ": give NOM_CMP");
    return {checks, scale, header, nodalValue(*field, node, *cmp, occ.path())};
}

// CHAM_ELEM: a field at integration points, at a point of a cell or reduced (trchel).
Tested testGaussField(const KeywordSet& occ, const CommandContext& ctx) {
    const TestChecks checks = test_keywords::checks(occ, "TEST_RESU", ctx);
    const CheckScale scale = checkScale(checks);
    const auto field = occ.object<GaussField>("CHAM_GD");
    TestHeader header = fieldHeader(occ, "CHAM_ELEM", *field);
    const auto cmp = component(occ);
    // As trchel, no blank line after a TYPE_TEST occurrence.
    if (occ.has("TYPE_TEST")) {
        const double value = reduced(occ, *field, header, {"MAILLE", "GROUP_MA"});  // completes the header
        return {checks, scale, header, value, true, false};
    }
    const auto [cell, point] = pointPlace(occ, *field->mesh, header);
    if (!cmp) throw UserError(occ.path() + ": give NOM_CMP");
    return {checks, scale, header, gaussValue(*field, cell, point, *cmp, occ.path()), false};
}

ConceptPtr testResu(const KeywordSet& kw, CommandContext& ctx) {
    // op0023's order: CHAM_NO, CHAM_ELEM, then RESU.
    std::vector<Tested> tested;
    for (const auto& occ : kw.factor("CHAM_NO")) tested.push_back(testNodalField(occ, ctx));
    for (const auto& occ : kw.factor("CHAM_ELEM")) tested.push_back(testGaussField(occ, ctx));
    for (const auto& occ : kw.factor("RESU")) tested.push_back(testResult(occ, ctx));
    msg().result("\n" + std::string(80, '-') + "\n");
    for (const auto& t : tested) {
        msg().result(t.header.text(t.labelBlank));
        runChecks(t.checks, t.scale, Cell(t.value), true, t.checks.where + " " + t.header.describe());
        if (t.blankAfter) msg().result("  \n");
    }
    return nullptr;
}

MA_REGISTER_COMMAND("TEST_RESU", testResu);

}  // namespace
}  // namespace ma
