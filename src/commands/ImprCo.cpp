// IMPR_CO: a listing of each concept named under CONCEPT/NOM on UNITE (8: the .resu). code_aster
// prints the JEVEUX objects the concept is made of (a developers' tool); miniaster has no JEVEUX
// and prints the data it holds instead: for a crack its nodal level set (LNNO), cut cells, enriched
// nodes and junction masters; for a mesh its sizes and groups; for a table its content; for a
// function its points. NIVEAU 0 prints the headers only, CONTENU='NON' too.
#include <fmt/format.h>

#include <string>

#include "commands/TextUnit.hpp"
#include "core/Function.hpp"
#include "core/Messages.hpp"
#include "core/Units.hpp"
#include "mesh/Mesh.hpp"
#include "parser/CommandRegistry.hpp"
#include "post/Table.hpp"
#include "post/TablePrinter.hpp"
#include "xfem/Crack.hpp"

namespace ma {
namespace {

// Items as lines of up to 8 names.
std::string nameLines(const std::vector<std::string>& names) {
    std::string out;
    for (size_t i = 0; i < names.size(); ++i) out += fmt::format("{}{:<8}", i % 8 == 0 ? "\n      " : " ", names[i]);
    return out + "\n";
}

std::string crackListing(const xfem::Crack& c) {
    const Mesh& mesh = *c.mesh;
    std::string out =
        fmt::format("    level set LNNO at the {} nodes of mesh {} (node, value):\n", mesh.nodeCount(), mesh.name);
    for (int n = 0; n < mesh.nodeCount(); ++n)
        out += fmt::format("      {:<8} {:13.6E}\n", mesh.nodeNames[size_t(n)], c.lsn[size_t(n)]);
    std::vector<std::string> cells, nodes;
    for (int cell : c.cutCells) cells.push_back(mesh.cellNames[size_t(cell)]);
    for (int n = 0; n < mesh.nodeCount(); ++n)
        if (c.nodeStatus[size_t(n)]) nodes.push_back(mesh.nodeNames[size_t(n)]);
    out += fmt::format("    cut cells (MAILFISS): {}", cells.size()) + nameLines(cells);
    out += fmt::format("    Heaviside-enriched nodes (STNO = 1): {}", nodes.size()) + nameLines(nodes);
    for (const auto& m : c.masters)
        out += fmt::format("    junction on {} (JONFISS), side coefficient {:+g} (JONCOEF){}\n", m.crack->name, m.coef,
                           m.declared ? "" : ", through a chain");
    return out;
}

std::string meshListing(const Mesh& m) {
    std::string out = fmt::format("    space dimension {}, {} nodes, {} cells\n", m.dim, m.nodeCount(), m.cellCount());
    for (const auto& g : m.nodeGroups.names())
        out += fmt::format("    GROUP_NO {:<24} {} nodes\n", g, m.nodeGroups.get(g).size());
    for (const auto& g : m.cellGroups.names())
        out += fmt::format("    GROUP_MA {:<24} {} cells\n", g, m.cellGroups.get(g).size());
    return out;
}

std::string functionListing(const Concept& f) {
    if (const auto* c = dynamic_cast<const ConstantFunction*>(&f))
        return fmt::format("    constant {:13.6E}\n", c->value);
    const auto* t = dynamic_cast<const TabulatedFunction*>(&f);
    if (!t) return "";
    std::string out = fmt::format("    {} points ({}, value):\n", t->x.size(), t->parameter_[0]);
    for (size_t i = 0; i < t->x.size(); ++i) out += fmt::format("      {:13.6E} {:13.6E}\n", t->x[i], t->y[i]);
    return out;
}

std::string listing(const Concept& c, bool content) {
    std::string out = fmt::format("\n IMPR_CO: concept {} of type {}\n", c.name, c.typeName());
    if (!content) return out;
    if (const auto* crack = dynamic_cast<const xfem::Crack*>(&c)) return out + crackListing(*crack);
    if (const auto* mesh = dynamic_cast<const Mesh*>(&c)) return out + meshListing(*mesh);
    if (const auto* table = dynamic_cast<const Table*>(&c)) return out + formatTable(*table);
    if (const std::string f = functionListing(c); !f.empty()) return out + f;
    return out + "    (no listing of this type's content in miniaster)\n";
}

ConceptPtr imprCo(const KeywordSet& kw, CommandContext& ctx) {
    const bool content = kw.text("CONTENU") == "OUI" && kw.integer("NIVEAU") > 0;
    std::string text;
    for (const auto& occ : kw.factor("CONCEPT"))
        for (const auto& c : occ.objects<Concept>("NOM")) text += listing(*c, content);
    printOnUnit("IMPR_CO", kw.integer("UNITE"), ctx.units, text);
    return nullptr;
}

MA_REGISTER_COMMAND("IMPR_CO", imprCo);

}  // namespace
}  // namespace ma
