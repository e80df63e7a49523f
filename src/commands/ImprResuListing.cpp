#include "commands/ImprResuListing.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "commands/ImprResuGmsh.hpp"
#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "fe/Result.hpp"
#include "post/NodalListing.hpp"
#include "post/PostMessages.hpp"

namespace ma {
namespace {

// NOEUD, GROUP_NO, then the nodes of GROUP_MA's cells, each once in that order (empty: every node).
std::vector<int> listedNodes(const Mesh& mesh, const KeywordSet& occ) {
    std::vector<int> nodes;
    std::vector<char> seen(size_t(mesh.nodeCount()), 0);
    auto add = [&](int n) {
        if (!seen[size_t(n)]) nodes.push_back(n), seen[size_t(n)] = 1;
    };
    if (occ.has("NOEUD"))
        for (const auto& name : occ.texts("NOEUD")) {
            const int n = mesh.findNode(name);
            if (n < 0)
                throw UserError(fmt::format("{}: the mesh {} has no node '{}'", occ.pathOf("NOEUD"), mesh.name, name));
            add(n);
        }
    if (occ.has("GROUP_NO"))
        for (const auto& g : occ.texts("GROUP_NO"))
            for (int n : namedGroup(mesh, GroupKind::Nodes, g, occ.pathOf("GROUP_NO"))) add(n);
    if (occ.has("GROUP_MA"))
        for (const auto& g : occ.texts("GROUP_MA"))
            for (int c : namedGroup(mesh, GroupKind::Cells, g, occ.pathOf("GROUP_MA")))
                for (int n : mesh.cellNodes(c)) add(n);
    return nodes;
}

post::ListingOptions listingOptions(const Mesh& mesh, const KeywordSet& occ) {
    post::ListingOptions o;
    if (occ.has("NOM_CMP")) o.components = occ.texts("NOM_CMP");
    o.nodes = listedNodes(mesh, occ);
    o.coordinates = occ.text("IMPR_COOR") == "OUI";
    o.maxima = occ.has("VALE_MAX");
    o.minima = occ.has("VALE_MIN");
    if (occ.has("BORNE_SUP")) o.upper = occ.real("BORNE_SUP");
    if (occ.has("BORNE_INF")) o.lower = occ.real("BORNE_INF");
    o.realFormat = occ.text("FORMAT_R");
    return o;
}

// The fields NOM_CHAM names, or every field of the step; a field at integration points is not
// listed (an error when named, an alarm when all are).
std::vector<std::string> listedFields(const ResultStep& step, const Result& result, const KeywordSet& occ) {
    std::vector<std::string> names, skipped;
    if (occ.has("NOM_CHAM")) {
        for (const auto& name : occ.texts("NOM_CHAM")) {
            if (!step.nodal(name) && step.gauss(name))
                throw NotImplemented(
                    fmt::format("{}: {} is a field at integration points; miniaster's FORMAT='RESULTAT' "
                                "lists nodal fields (print it with FORMAT='MED' or 'GMSH')",
                                occ.pathOf("NOM_CHAM"), name));
            names.push_back(name);
        }
        return names;
    }
    for (const auto& [name, field] : step.nodalFields) names.push_back(name);
    for (const auto& [name, field] : step.gaussFields) skipped.push_back(name);
    if (!skipped.empty())
        msg().alarm(PREPOST_LISTING, occ.path(), fmt::format("{}", fmt::join(skipped, ", ")), result.name, step.order);
    return names;
}

std::string resultListing(const Result& result, const KeywordSet& occ) {
    if (!result.mesh) throw UserError(occ.pathOf("RESULTAT") + ": result " + result.name + " has no mesh");
    const auto options = listingOptions(*result.mesh, occ);
    std::string out;
    for (const ResultStep* step : selectedResultSteps(result, occ)) {
        bool first = true;
        for (const auto& name : listedFields(*step, result, occ)) {
            const auto field = step->nodal(name);
            if (!field) {
                msg().alarm(RESULT1_6, occ.path(), name, step->order, result.name);
                continue;
            }
            if (first) out += "\n ======>\n";
            first = false;
            out += "\n ------>\n" + post::nodalFieldTitle(name, step) + post::nodalFieldListing(*field, options);
        }
    }
    return out;
}

}  // namespace

std::string resuListing(const KeywordSet& occ) {
    if (occ.has("RESULTAT")) return resultListing(*occ.object<Result>("RESULTAT"), occ);
    auto field = std::dynamic_pointer_cast<NodalField>(occ.rawObject("CHAM_GD"));
    if (!field)
        throw NotImplemented(occ.pathOf("CHAM_GD") +
                             ": miniaster's FORMAT='RESULTAT' lists nodal fields (cham_no); print this one with "
                             "FORMAT='MED' or 'GMSH'");
    if (!field->mesh) throw UserError(occ.pathOf("CHAM_GD") + ": the field has no mesh");
    return "\n ------>\n" + post::nodalFieldTitle(field->name, nullptr) +
           post::nodalFieldListing(*field, listingOptions(*field->mesh, occ));
}

}  // namespace ma
