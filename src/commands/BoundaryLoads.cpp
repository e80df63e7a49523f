#include "commands/BoundaryLoads.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "commands/MechanicsKeywords.hpp"
#include "core/Messages.hpp"
#include "fe/DofNumbering.hpp"
#include "xfem/XfemModel.hpp"

namespace ma::mechanics {

namespace {

LoadValue readValue(const KeywordSet& occ, const std::string& key, bool functions) {
    LoadValue v;
    if (!occ.has(key)) return v;
    if (functions) v.function = occ.object<Function>(key);
    else v.value = occ.real(key);
    return v;
}

// PRES_REP(FISSURE=...): one lip load per interface named.
void readLipPressure(const KeywordSet& occ, bool functions, MechanicalLoad& load) {
    const Model& model = *load.model;
    if (occ.has("GROUP_MA") || occ.has("MAILLE"))
        throw UserError(
            fmt::format("{}: FISSURE loads the lips of the interfaces, GROUP_MA/MAILLE the boundary "
                        "cells: give them in two occurrences",
                        occ.path()));
    if (model.dim == 3 && occ.has("CISA_2D"))
        throw UserError(fmt::format("{}: CISA_2D is a shear for plane models; the model {} is 3D",
                                    occ.pathOf("CISA_2D"), model.name));
    const auto* xm = dynamic_cast<const xfem::XfemModel*>(model.enrichment.get());
    for (const auto& crack : occ.objects<xfem::Crack>("FISSURE")) {
        const bool ofModel = xm && std::any_of(xm->cracks().begin(), xm->cracks().end(),
                                               [&](const auto& c) { return c.get() == crack.get(); });
        if (!ofModel)
            throw UserError(
                fmt::format("{}: the interface {} is not one of the model {} (MODI_MODELE_XFEM "
                            "FISSURE=...)",
                            occ.pathOf("FISSURE"), crack->name, model.name));
        LipPressure lp;
        lp.path = occ.path();
        lp.crack = crack;
        lp.pressure = readValue(occ, "PRES", functions);
        lp.shear = readValue(occ, "CISA_2D", functions);
        std::vector<LipIntegration> lips;
        xm->lipIntegration(*crack, lips);
        size_t points = 0;
        for (const auto& l : lips) points += l.xyz.size();
        msg().infof("    {}: pressure on both lips of {} ({} X-FEM cells, {} points)", occ.path(), crack->name,
                    lips.size(), points);
        load.lipPressures.push_back(std::move(lp));
    }
}

void readPressure(const KeywordSet& occ, bool functions, const std::vector<char>& isSkin, MechanicalLoad& load) {
    const Model& model = *load.model;
    if (occ.has("FISSURE")) return readLipPressure(occ, functions, load);
    if (model.dim == 3 && occ.has("CISA_2D"))
        throw UserError(fmt::format("{}: CISA_2D is a shear for plane models; the model {} is 3D",
                                    occ.pathOf("CISA_2D"), model.name));
    std::string what;
    PressureLoad p;
    p.path = occ.path();
    for (int c : selectedCells(*model.mesh, occ, &what))
        if (isSkin[size_t(c)]) p.cells.push_back(c);
    if (p.cells.empty())
        throw UserError(
            fmt::format("{} ({}): no boundary element of the model {} there; the boundary cells must "
                        "be listed in AFFE_MODELE",
                        occ.path(), what, model.name));
    const LoadValue pres = readValue(occ, "PRES", functions);
    p.value = pres.value;
    p.function = pres.function;
    p.shear = readValue(occ, "CISA_2D", functions);
    msg().infof("    {}: pressure on {} boundary element(s) ({})", occ.path(), p.cells.size(), what);
    load.pressures.push_back(std::move(p));
}

// FORCE_ARETE: the edges of a 3D model are not elements of it (AFFE_MODELE keeps faces); any SEG2
// cell whose nodes carry standard unknowns will do, unless an interface enriches them.
bool edgeOfModel(const Mesh& mesh, int c, const DofNumbering& numbering, const Model& model) {
    if (mesh.cellTypes[size_t(c)] != CellType::SEG2) return false;
    for (int n : mesh.cellNodes(c)) {
        if (!numbering.hasNode(n)) return false;
        if (model.enrichment && model.enrichment->nodeSlots(n) > 1)
            throw NotImplemented(
                fmt::format("FORCE_ARETE on cell {}: its node {} is enriched by an interface "
                            "(edge forces across X-FEM interfaces are not modelled)",
                            mesh.cellNames[size_t(c)], mesh.nodeNames[size_t(n)]));
    }
    return true;
}

void readSurfaceForce(const KeywordSet& occ, const char* keyword, bool functions, const std::vector<char>& isSkin,
                      MechanicalLoad& load) {
    const Model& model = *load.model;
    const Mesh& mesh = *model.mesh;
    const std::string name = keyword;
    const bool edges3d = name == "FORCE_ARETE";
    if ((name == "FORCE_CONTOUR") != (model.dim == 2))
        throw UserError(fmt::format("{}: {} is for {} models; the model {} is {}", occ.path(), name,
                                    model.dim == 2 ? "3D (FORCE_FACE, FORCE_ARETE)" : "plane (FORCE_CONTOUR)",
                                    model.name, modelisationName(model.modelisation)));
    std::string what;
    SurfaceForce f;
    f.path = occ.path();
    const DofNumbering numbering(model);
    for (int c : selectedCells(mesh, occ, &what))
        if (edges3d ? edgeOfModel(mesh, c, numbering, model) : bool(isSkin[size_t(c)])) f.cells.push_back(c);
    if (f.cells.empty())
        throw UserError(fmt::format("{} ({}): no {} of the model {} there{}", occ.path(), what,
                                    edges3d ? "SEG2 edge on nodes" : "boundary element", model.name,
                                    edges3d ? "" : "; the boundary cells must be listed in AFFE_MODELE"));
    const char* keys[] = {"FX", "FY", "FZ"};
    for (int c = 0; c < 3; ++c) {
        if (!occ.has(keys[c])) continue;
        if (c >= model.dim) throw UserError(fmt::format("{}: the model {} is plane", occ.pathOf(keys[c]), model.name));
        f.component[size_t(c)] = readValue(occ, keys[c], functions);
    }
    msg().infof("    {}: force on {} {}(s) ({})", occ.path(), f.cells.size(), edges3d ? "edge" : "boundary element",
                what);
    load.surfaceForces.push_back(std::move(f));
}

}  // namespace

void readSurfaceLoads(const KeywordSet& kw, bool functions, MechanicalLoad& load) {
    const Mesh& mesh = *load.model->mesh;
    std::vector<char> isSkin(size_t(mesh.cellCount()), 0);
    for (const auto& e : load.model->skinElements) isSkin[size_t(e.cell)] = 1;
    for (const auto& occ : kw.factor("PRES_REP")) readPressure(occ, functions, isSkin, load);
    for (const char* keyword : {"FORCE_CONTOUR", "FORCE_FACE", "FORCE_ARETE"})
        for (const auto& occ : kw.factor(keyword)) readSurfaceForce(occ, keyword, functions, isSkin, load);
}

}  // namespace ma::mechanics
