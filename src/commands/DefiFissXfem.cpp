// DEFI_FISS_XFEM with TYPE_DISCONTINUITE='INTERFACE': the normal level set of FONC_LN at every
// mesh node, snapped, cut cells, enriched nodes, junction on master interfaces (xfem_spec §1, §2).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <map>

#include "core/Error.hpp"
#include "core/Function.hpp"
#include "core/Messages.hpp"
#include "fe/Model.hpp"
#include "parser/CommandRegistry.hpp"
#include "xfem/Crack.hpp"
#include "xfem/XfemMessages.hpp"

namespace ma {
namespace {

// JONCTION/POINT: as many coordinates as the mesh has. code_aster zeroes the point and reads up to
// 3 values (xinlsj), so it takes (5,) in 2D for (5, 0); that silent 0 is refused. A 3D mesh
// accepts 2 (z = 0, said in the log) because code_aster's own ssnv510f gives POINT=(0,4) on one,
// and a 2D mesh (x, y, 0), its own plane.
std::vector<double> jonctionPoint(const KeywordSet& j, int dim) {
    auto point = j.reals("POINT");
    if (dim == 2 && point.size() == 3 && point[2] == 0.0) point.pop_back();
    const size_t least = dim == 3 ? 2 : size_t(dim);
    if (point.size() < least || point.size() > size_t(dim))
        throw UserError(fmt::format("{}=({}): {} coordinate(s) on a mesh of dimension {}; give {}", j.pathOf("POINT"),
                                    fmt::join(point, ", "), point.size(), dim, dim == 3 ? "3 (X, Y, Z)" : "2 (X, Y)"));
    if (point.size() < size_t(dim))
        msg().infof("    {}: {} coordinate(s) given on a mesh of dimension {}; the missing ones are 0",
                    j.pathOf("POINT"), point.size(), dim);
    return point;
}

ConceptPtr defiFissXfem(const KeywordSet& kw, CommandContext& ctx) {
    std::shared_ptr<const Mesh> mesh;
    if (kw.has("MAILLAGE")) {
        mesh = kw.object<Mesh>("MAILLAGE");
    } else {
        auto model = kw.object<Model>("MODELE");  // legacy syntax: only the mesh is used
        mesh = model->mesh;
    }
    const std::string type = kw.text("TYPE_DISCONTINUITE");
    if (type != "INTERFACE")
        throw NotImplemented(kw.pathOf("TYPE_DISCONTINUITE") + "='" + type +
                             "': miniaster models interfaces only (TYPE_DISCONTINUITE='INTERFACE')");
    const auto& defi = kw.factor("DEFI_FISS");
    if (defi.empty()) throw UserError("DEFI_FISS is mandatory");
    const auto& occ = defi[0];
    auto fln = occ.object<Function>("FONC_LN");
    if (occ.has("FONC_LT")) msg().alarm(XFEM_25, occ.pathOf("FONC_LT"));

    // One batch evaluation at every node: parameters X, Y (2D mesh) or X, Y, Z.
    const size_t nn = mesh->coords.size();
    std::map<std::string, std::vector<double>> columns;
    const char* names[] = {"X", "Y", "Z"};
    for (int j = 0; j < (mesh->dim == 3 ? 3 : 2); ++j) {
        auto& col = columns[names[j]];
        col.resize(nn);
        for (size_t n = 0; n < nn; ++n) col[n] = mesh->coords[n][j];
    }
    std::vector<double> lsn = fln->evaluateColumns(columns, nn);

    xfem::JunctionInput junction;
    const auto& jonction = kw.factor("JONCTION");
    if (!jonction.empty()) {
        const auto& j = jonction[0];
        for (const auto& c : j.objects<xfem::Crack>("FISSURE")) junction.masters.push_back(c);
        const auto point = jonctionPoint(j, mesh->dim);
        for (size_t i = 0; i < point.size(); ++i) junction.point[i] = point[i];
        junction.keywordPath = j.path().empty() ? "JONCTION" : j.path();
    }
    // GROUP_MA_ENRI: the cells where the interface may enrich (code_aster's xlenri; all cells without it).
    std::vector<char> zone;
    if (kw.has("GROUP_MA_ENRI")) {
        zone.assign(size_t(mesh->cellCount()), 0);
        const auto& cells = namedGroup(*mesh, GroupKind::Cells, kw.text("GROUP_MA_ENRI"), kw.pathOf("GROUP_MA_ENRI"));
        for (int c : cells) zone[size_t(c)] = 1;
        msg().infof("    GROUP_MA_ENRI: the interface enriches only in the {} cell(s) of {}", cells.size(),
                    kw.text("GROUP_MA_ENRI"));
    }
    auto crack =
        xfem::buildCrack(mesh, std::move(lsn), jonction.empty() ? nullptr : &junction, zone.empty() ? nullptr : &zone);

    if (crack->adjustedLevelSets > 0) msg().alarm(XFEM_63, crack->adjustedLevelSets);
    msg().infof(
        "    interface ({}): {} cut cells, {} Heaviside-enriched nodes, {} cells with an enriched node, "
        "{} level-set values adjusted",
        ctx.resultName.empty() ? "DEFI_FISS_XFEM" : ctx.resultName, crack->cutCells.size(), crack->enrichedNodeCount(),
        crack->heavisideCells.size(), crack->adjustedLevelSets);
    for (const auto& m : crack->masters)
        msg().infof("    junction on {}: the interface exists where {} * LSN({}) < 0{}", m.crack->name,
                    m.coef > 0 ? "+1" : "-1", m.crack->name, m.declared ? "" : " (inherited)");
    if (crack->enrichedNodeCount() == 0) msg().alarm(XFEM_ENRI);
    if (ctx.info >= 3)
        for (int n = 0; n < mesh->nodeCount(); ++n)
            msg().infof("      {:8s} LSN = {:.12e}  status {}", mesh->nodeNames[n], crack->lsn[n],
                        int(crack->nodeStatus[n]));
    return crack;
}

MA_REGISTER_COMMAND("DEFI_FISS_XFEM", defiFissXfem);

}  // namespace
}  // namespace ma
