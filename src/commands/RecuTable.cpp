// RECU_TABLE CO=<crack>: the tables DEFI_FISS_XFEM builds for a crack's fronts (code_aster's xtabff):
// FOND_FISS (3D: NUME_FOND, NUM_PT, ABSC_CURV, COOR_X, COOR_Y, COOR_Z; 2D: NUME_FOND, COOR_X,
// COOR_Y) and NB_FOND_FISS (NOMBRE). A crack without front has neither (code_aster builds none).
#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "parser/CommandRegistry.hpp"
#include "post/Table.hpp"
#include "xfem/Crack.hpp"

namespace ma {
namespace {

void frontTable(const xfem::Crack& crack, Table& t) {
    const bool threeD = crack.mesh->dim == 3;
    t.addColumn("NUME_FOND", ColumnType::integer());
    if (threeD) t.addColumn("NUM_PT", ColumnType::integer()), t.addColumn("ABSC_CURV", ColumnType::real());
    t.addColumn("COOR_X", ColumnType::real());
    t.addColumn("COOR_Y", ColumnType::real());
    if (threeD) t.addColumn("COOR_Z", ColumnType::real());
    for (size_t f = 0; f < crack.fronts.size(); ++f) {
        const auto& front = crack.fronts[f];
        for (size_t i = 0; i < front.points.size(); ++i) {
            const size_t row = t.addRow();
            t.set(row, "NUME_FOND", static_cast<long long>(f + 1));
            if (threeD) {
                t.set(row, "NUM_PT", static_cast<long long>(i + 1));
                t.set(row, "ABSC_CURV", front.abscissa[i]);
                t.set(row, "COOR_Z", front.points[i][2]);
            }
            t.set(row, "COOR_X", front.points[i][0]);
            t.set(row, "COOR_Y", front.points[i][1]);
        }
    }
}

ConceptPtr recuTable(const KeywordSet& kw, CommandContext&) {
    auto crack = kw.object<xfem::Crack>("CO");
    const std::string name = kw.text("NOM_TABLE");
    if (crack->fronts.empty())
        throw UserError(
            fmt::format("{}='{}': {} {} has no front in the mesh, so no {} table (code_aster builds "
                        "none either)",
                        kw.pathOf("NOM_TABLE"), name, crack->isCrack ? "crack" : "interface", crack->name, name));
    auto t = std::make_shared<Table>();
    if (name == "NB_FOND_FISS") {
        t->addColumn("NOMBRE", ColumnType::integer());
        t->set(t->addRow(), "NOMBRE", static_cast<long long>(crack->fronts.size()));
    } else {
        frontTable(*crack, *t);
    }
    if (kw.has("TITRE")) t->title = kw.texts("TITRE");
    msg().infof("    table {} of {}: {} rows", name, crack->name, t->rowCount());
    return t;
}

MA_REGISTER_COMMAND("RECU_TABLE", recuTable);

}  // namespace
}  // namespace ma
