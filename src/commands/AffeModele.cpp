// AFFE_MODELE: finite elements on the cells of a mesh (commands_spec §8.3). Cells of the model's
// dimension become elements (TRIA3/QUAD4 in D_PLAN/C_PLAN, TETRA4/HEXA8 in 3D); cells one
// dimension lower become boundary ("skin") elements able to carry PRES_REP; points and lower
// cells get no element.
#include <fmt/format.h>

#include <map>

#include "commands/MechanicsKeywords.hpp"
#include "core/Messages.hpp"
#include "fe/Model.hpp"
#include "mesh/ShapeFunctions.hpp"
#include "parser/CommandRegistry.hpp"

namespace ma {
namespace {

Modelisation parseModelisation(const KeywordSet& occ) {
    const auto names = occ.texts("MODELISATION");
    if (names.size() != 1)
        throw NotImplemented(occ.pathOf("MODELISATION") + ": several modelisations in one AFFE occurrence");
    if (names[0] == "D_PLAN") return Modelisation::D_PLAN;
    if (names[0] == "C_PLAN") return Modelisation::C_PLAN;
    if (names[0] == "3D") return Modelisation::TRI_D;
    throw NotImplemented(occ.pathOf("MODELISATION") + "='" + names[0] + "' is not supported (D_PLAN, C_PLAN, 3D)");
}

int modelDimension(Modelisation m) { return m == Modelisation::TRI_D ? 3 : 2; }

bool isVolumeType(CellType t, int dim) {
    return dim == 2 ? (t == CellType::TRIA3 || t == CellType::QUAD4) : (t == CellType::TETRA4 || t == CellType::HEXA8);
}
bool isSkinType(CellType t, int dim) {
    return dim == 2 ? t == CellType::SEG2 : (t == CellType::TRIA3 || t == CellType::QUAD4);
}

ConceptPtr affeModele(const KeywordSet& kw, CommandContext&) {
    auto mesh = kw.object<Mesh>("MAILLAGE");
    auto model = std::make_shared<Model>();
    model->mesh = mesh;
    const int ncell = mesh->cellCount();
    std::vector<int> assigned(ncell, -1);  // modelisation per cell (last occurrence wins)
    int dim = 0;
    bool first = true;
    for (const auto& occ : kw.factor("AFFE")) {
        if (occ.text("PHENOMENE") != "MECANIQUE")
            throw NotImplemented(occ.pathOf("PHENOMENE") + "='" + occ.text("PHENOMENE") + "': only MECANIQUE");
        const Modelisation m = parseModelisation(occ);
        if (first) model->modelisation = m, first = false;
        if (dim != 0 && dim != modelDimension(m))
            throw UserError(fmt::format("{}: {} cannot be mixed with modelisations of another dimension in one model",
                                        occ.pathOf("MODELISATION"), modelisationName(m)));
        dim = modelDimension(m);
        std::string what;
        const auto cells = mechanics::selectedCells(*mesh, occ, &what);
        std::map<std::string, int> ignored;
        int used = 0;
        for (int c : cells) {
            const CellType t = mesh->cellTypes[c];
            const int cd = cellDimension(t);
            if (isVolumeType(t, dim) && cd == dim) {
                assigned[c] = static_cast<int>(m);
                ++used;
            } else if (isSkinType(t, dim) && cd == dim - 1) {
                assigned[c] = static_cast<int>(m);
                ++used;
            } else if (cd >= dim - 1) {
                throw NotImplemented(
                    fmt::format("{} ({}): cell {} is a {}, for which miniaster has no {} element (supported: {})",
                                occ.path(), what, mesh->cellNames[c], cellTypeName(t), modelisationName(m),
                                dim == 2 ? "TRIA3, QUAD4 and SEG2 boundaries"
                                         : "TETRA4, HEXA8 and TRIA3/QUAD4 boundaries"));
            } else {
                ++ignored[cellTypeName(t)];
            }
        }
        if (used == 0)
            throw UserError(fmt::format("{} ({}): none of the {} cells can carry a {} element", occ.path(), what,
                                        cells.size(), modelisationName(m)));
        for (const auto& [type, count] : ignored)
            msg().infof("    {} ({}): {} {} cell(s) carry no element", occ.path(), what, count, type);
    }
    model->dim = dim;
    std::map<std::string, int> counts;
    for (int c = 0; c < ncell; ++c) {
        if (assigned[c] < 0) continue;
        ModelElement e{c, static_cast<Modelisation>(assigned[c])};
        const CellType t = mesh->cellTypes[c];
        if (cellDimension(t) == dim) model->elements.push_back(e);
        else model->skinElements.push_back(e);
        ++counts[cellTypeName(t)];
    }
    if (model->elements.empty())
        throw UserError("AFFE_MODELE: the model has no element of dimension " + std::to_string(dim));
    // A plane model lives in the x-y plane.
    if (dim == 2)
        for (const auto& e : model->elements)
            for (int n : mesh->cellNodes(e.cell))
                if (mesh->coords[n][2] != 0.0)
                    throw UserError(
                        fmt::format("AFFE_MODELE: node {} of cell {} has z = {}: a {} model must lie in "
                                    "the plane z = 0",
                                    mesh->nodeNames[n], mesh->cellNames[e.cell], mesh->coords[n][2],
                                    modelisationName(model->modelisation)));
    for (const auto& [type, count] : counts)
        msg().infof("    {} elements on {} cells ({})", modelisationName(model->modelisation), count, type);
    return model;
}

MA_REGISTER_COMMAND("AFFE_MODELE", affeModele);

}  // namespace
}  // namespace ma
