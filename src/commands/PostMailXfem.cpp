// POST_MAIL_XFEM: the visualisation mesh of an X-FEM model (xfem_spec §6): sub-cells as cells,
// nodes duplicated on each side of the interfaces, group NFISSU of the interface nodes.
#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "fe/Model.hpp"
#include "parser/CommandRegistry.hpp"
#include "xfem/Visualisation.hpp"
#include "xfem/XfemModel.hpp"

namespace ma {
namespace {

ConceptPtr postMailXfem(const KeywordSet& kw, CommandContext&) {
    auto model = kw.object<Model>("MODELE");
    const auto* xm = dynamic_cast<const xfem::XfemModel*>(model->enrichment.get());
    if (!xm) throw UserError(kw.pathOf("MODELE") + ": " + model->name + " is not an X-FEM model (MODI_MODELE_XFEM)");
    xfem::VisualisationNames names;
    names.nodeX = kw.text("PREF_NOEUD_X");
    names.nodeMinus = kw.text("PREF_NOEUD_M");
    names.nodePlus = kw.text("PREF_NOEUD_P");
    names.cellX = kw.text("PREF_MAILLE_X");
    names.crackGroup = kw.text("PREF_GROUP_CO");
    auto visu = xfem::buildVisualisation(*model, *xm, names);
    const Mesh& m = *visu.mesh;
    int copiedCells = 0, copiedNodes = 0;
    for (const auto& c : visu.cells) copiedCells += c.original >= 0;
    for (const auto& n : visu.nodes) copiedNodes += n.original >= 0;
    const size_t crack = m.nodeGroups.has(names.crackGroup) ? m.nodeGroups.get(names.crackGroup).size() : 0;
    msg().infof(
        "    visualisation mesh: {} nodes ({} copied, {} new of which {} on the interfaces in group {}), "
        "{} cells ({} copied, {} sub-cells {}...)",
        m.nodeCount(), copiedNodes, m.nodeCount() - copiedNodes, crack, names.crackGroup, m.cellCount(), copiedCells,
        m.cellCount() - copiedCells, names.cellX);
    return visu.mesh;
}

MA_REGISTER_COMMAND("POST_MAIL_XFEM", postMailXfem);

}  // namespace
}  // namespace ma
