// AFFE_CHAR_MECA: DDL_IMPO, FORCE_INTERNE here; FACE_IMPO, ARETE_IMPO, LIAISON_DDL, LIAISON_GROUP
// (RelationLoads.cpp); PRES_REP, FORCE_CONTOUR, FORCE_FACE, FORCE_ARETE (BoundaryLoads.cpp); real
// values (commands_spec §8.5).
// The same reader serves AFFE_CHAR_MECA_F (AffeCharMecaF.cpp), where values are functions of
// X, Y, Z, INST evaluated in batch when the analysis needs them.
#include <fmt/format.h>

#include "commands/BoundaryLoads.hpp"
#include "commands/LegacyContactLoad.hpp"
#include "commands/MechanicsKeywords.hpp"
#include "commands/RelationLoads.hpp"
#include "core/Messages.hpp"
#include "fe/DofNumbering.hpp"
#include "fe/MechanicalLoad.hpp"
#include "parser/CommandRegistry.hpp"

namespace ma {
namespace mechanics {

namespace {

const char* const kDofKeywords[] = {"DX",  "DY",  "DZ",  "H1X", "H1Y", "H1Z", "H2X", "H2Y", "H2Z",
                                    "H3X", "H3Y", "H3Z", "H4X", "H4Y", "H4Z", "K1",  "K2",  "K3"};

// Reads a load value: a real, or (AFFE_CHAR_MECA_F) a function.
void readValue(const KeywordSet& occ, const std::string& key, bool functions, double& value,
               std::shared_ptr<const Function>& function) {
    if (functions) function = occ.object<Function>(key);
    else value = occ.real(key);
}

}  // namespace

ConceptPtr buildMechanicalLoad(const KeywordSet& kw, bool functions) {
    auto model = kw.object<Model>("MODELE");
    const Mesh& mesh = *model->mesh;
    auto load = std::make_shared<MechanicalLoad>();
    load->model = model;
    readLegacyXfemContact(kw, *load);
    const DofNumbering numbering(*model);
    std::vector<char> modelNodes(mesh.nodeCount(), 0);
    for (int n = 0; n < mesh.nodeCount(); ++n) modelNodes[n] = numbering.hasNode(n);

    for (const auto& occ : kw.factor("DDL_IMPO")) {
        const auto nodes = selectedNodes(mesh, occ, modelNodes);
        int components = 0;
        for (const char* key : kDofKeywords) {
            if (!occ.has(key)) continue;
            ++components;
            int slot = 0, comp = 0;
            if (key[0] == 'K') slot = -1, comp = key[1] - '1';  // crack-tip unknowns: tip nodes only
            else parseDisplacementComponent(key, slot, comp);
            if (comp >= model->dim)
                throw UserError(fmt::format("{}: the model {} is {} and has no component {}", occ.pathOf(key),
                                            model->name, modelisationName(model->modelisation), key));
            if (slot == 0)  // a translation must exist on every node named (enriched ones are skipped silently)
                for (int n : nodes)
                    if (!modelNodes[n])
                        throw UserError(
                            fmt::format("{}: node {} carries no unknown of the model {} (it belongs to "
                                        "no cell of the model)",
                                        occ.pathOf(key), mesh.nodeNames[n], model->name));
            ImposedDof d;
            d.path = occ.pathOf(key);
            d.nodes = nodes;
            d.component = key;
            readValue(occ, key, functions, d.value, d.function);
            load->imposed.push_back(std::move(d));
        }
        msg().infof("    {}: {} component(s) on {} node(s)", occ.path(), components, nodes.size());
    }

    readRelationLoads(kw, functions, modelNodes, *load);
    readSurfaceLoads(kw, functions, *load);

    std::vector<char> isVolume(mesh.cellCount(), 0);
    for (const auto& e : model->elements) isVolume[e.cell] = 1;
    for (const auto& occ : kw.factor("FORCE_INTERNE")) {
        std::string what;
        VolumeForce f;
        f.path = occ.path();
        for (int c : selectedCells(mesh, occ, &what))
            if (isVolume[c]) f.cells.push_back(c);
        if (f.cells.empty())
            throw UserError(fmt::format("{} ({}): no element of the model {} there", occ.path(), what, model->name));
        const char* keys[] = {"FX", "FY", "FZ"};
        for (int c = 0; c < 3; ++c) {
            if (!occ.has(keys[c])) continue;
            if (c >= model->dim)
                throw UserError(fmt::format("{}: the model {} is plane", occ.pathOf(keys[c]), model->name));
            readValue(occ, keys[c], functions, f.value[c], f.function[c]);
        }
        msg().infof("    {}: volume force on {} element(s) ({})", occ.path(), f.cells.size(), what);
        load->volumeForces.push_back(std::move(f));
    }
    return load;
}

}  // namespace mechanics

namespace {
ConceptPtr affeCharMeca(const KeywordSet& kw, CommandContext&) { return mechanics::buildMechanicalLoad(kw, false); }
MA_REGISTER_COMMAND("AFFE_CHAR_MECA", affeCharMeca);
}  // namespace

}  // namespace ma
