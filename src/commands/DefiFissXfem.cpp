// DEFI_FISS_XFEM: the level sets at every mesh node (FONC_LN/FONC_LT, CHAM_NO_LSN/CHAM_NO_LST or
// FORM_FISS), snapped; for an interface (TYPE_DISCONTINUITE='INTERFACE') the cut cells, enriched
// nodes and junctions on master interfaces (xfem_spec §1, §2); for a crack ('FISSURE', the default)
// the node status, the cells containing the front and the front (docs/cracks.md).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <map>

#include "core/Error.hpp"
#include "core/Function.hpp"
#include "core/Messages.hpp"
#include "fe/Model.hpp"
#include "fields/Fields.hpp"
#include "parser/CommandRegistry.hpp"
#include "xfem/Crack.hpp"
#include "xfem/CrackShapes.hpp"
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

// Nodal values of a level-set function: parameters X, Y (2D mesh) or X, Y, Z, one batch.
std::vector<double> evaluateAtNodes(const Function& f, const Mesh& mesh) {
    const size_t nn = mesh.coords.size();
    std::map<std::string, std::vector<double>> columns;
    const char* names[] = {"X", "Y", "Z"};
    for (int j = 0; j < (mesh.dim == 3 ? 3 : 2); ++j) {
        auto& col = columns[names[j]];
        col.resize(nn);
        for (size_t n = 0; n < nn; ++n) col[n] = mesh.coords[n][size_t(j)];
    }
    return f.evaluateColumns(columns, nn);
}

// CHAM_NO_LSN / CHAM_NO_LST: one component at every node of the crack's mesh (code_aster asserts both).
std::vector<double> fieldValues(const KeywordSet& occ, const char* keyword, const Mesh& mesh) {
    auto field = occ.object<NodalField>(keyword);
    if (field->mesh.get() != &mesh)
        throw UserError(fmt::format("{}: field {} is defined on mesh {}, not on {}", occ.pathOf(keyword), field->name,
                                    field->mesh ? field->mesh->name : "?", mesh.name));
    if (field->componentCount() != 1)
        throw UserError(fmt::format("{}: field {} has {} components ({}); a level set has one", occ.pathOf(keyword),
                                    field->name, field->componentCount(), fmt::join(field->components, ", ")));
    std::vector<double> values(size_t(mesh.nodeCount()));
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        if (!field->has(n, 0))
            throw UserError(fmt::format("{}: field {} has no value at node {}", occ.pathOf(keyword), field->name,
                                        mesh.nodeNames[size_t(n)]));
        values[size_t(n)] = field->at(n, 0);
    }
    return values;
}

xfem::CrackShape shapeOf(const KeywordSet& occ) {
    xfem::CrackShape s;
    s.form = occ.text("FORM_FISS");
    auto real = [&](const char* k, double& v) {
        if (occ.has(k)) v = occ.real(k);
    };
    auto vec = [&](const char* k, Vec3& v) {
        if (!occ.has(k)) return;
        const auto r = occ.reals(k);
        for (size_t i = 0; i < 3 && i < r.size(); ++i) v[i] = r[i];
    };
    real(s.form == "ENTAILLE" ? "DEMI_LONGUEUR" : "DEMI_GRAND_AXE", s.semiMajor);
    real("DEMI_PETIT_AXE", s.semiMinor);
    real("RAYON_CONGE", s.filletRadius);
    vec("CENTRE", s.centre), vec("VECT_X", s.vectX), vec("VECT_Y", s.vectY), vec("NORMALE", s.normal);
    vec("DTAN", s.tangent), vec("PFON_EXTR", s.end);
    vec(s.form == "SEGMENT" ? "PFON_ORIG" : (s.form == "DROITE" ? "POINT" : "PFON"), s.point);
    s.outside = occ.has("COTE_FISS") && occ.text("COTE_FISS") == "OUT";
    return s;
}

// LSN and LST at the nodes from FONC_LN/FONC_LT, CHAM_NO_LSN/CHAM_NO_LST or FORM_FISS; LST = -1 for
// an interface. A crack needs both (code_aster's XFEM_24); an interface ignores LST (XFEM_25).
xfem::ShapeLevelSets levelSets(const KeywordSet& occ, const Mesh& mesh, bool isCrack) {
    if (occ.has("FORM_FISS")) return xfem::shapeLevelSets(mesh, shapeOf(occ), isCrack);
    const bool byFunction = occ.has("FONC_LN");
    const char* tangential = byFunction ? "FONC_LT" : "CHAM_NO_LST";
    xfem::ShapeLevelSets out;
    out.lsn =
        byFunction ? evaluateAtNodes(*occ.object<Function>("FONC_LN"), mesh) : fieldValues(occ, "CHAM_NO_LSN", mesh);
    if (!isCrack) {
        if (occ.has(tangential)) msg().alarm(XFEM_25, occ.pathOf(tangential));
        out.lst.assign(out.lsn.size(), -1.0);
    } else if (!occ.has(tangential)) {
        throw UserError(
            fmt::format("{}: a crack (TYPE_DISCONTINUITE='FISSURE', the default) needs its tangential "
                        "level set {} too, which locates its front (code_aster's XFEM_24); for a "
                        "discontinuity without front give TYPE_DISCONTINUITE='INTERFACE'",
                        occ.path().empty() ? "DEFI_FISS" : occ.path(), tangential));
    } else {
        out.lst = byFunction ? evaluateAtNodes(*occ.object<Function>("FONC_LT"), mesh)
                             : fieldValues(occ, "CHAM_NO_LST", mesh);
    }
    return out;
}

// The front as code_aster's xenrch prints it (X, Y[, Z, S] per point, fronts numbered from 1).
void logFronts(const xfem::Crack& crack, int dim) {
    size_t points = 0;
    for (const auto& f : crack.fronts) points += f.points.size();
    msg().infof("    number of crack front points: {}; crack fronts: {}", points, crack.fronts.size());
    for (size_t k = 0; k < crack.fronts.size(); ++k) {
        const auto& f = crack.fronts[k];
        msg().infof("    crack front {}{}", k + 1, f.closed ? " (closed: its first point repeated at the end)" : "");
        msg().info(dim == 3 ? "           X             Y             Z             S" : "           X             Y");
        for (size_t i = 0; i < f.points.size(); ++i) {
            const auto& p = f.points[i];
            msg().info(
                dim == 3 ? fmt::format("      {:12.5E}  {:12.5E}  {:12.5E}  {:12.5E}", p[0], p[1], p[2], f.abscissa[i])
                         : fmt::format("      {:12.5E}  {:12.5E}", p[0], p[1]));
        }
    }
}

void logCrack(const xfem::Crack& crack, const std::string& name) {
    msg().infof(
        "    crack ({}): {} cut cells, {} cells containing the front; nodes: {} Heaviside (status 1), {} crack tip "
        "(2), {} both (3); {} level-set values adjusted",
        name, crack.cutCells.size(), crack.tipCells.size(), crack.nodeCountWithStatus(1), crack.nodeCountWithStatus(2),
        crack.nodeCountWithStatus(3), crack.adjustedLevelSets);
    if (crack.fronts.empty()) msg().alarm(XFEM_58, name);
    logFronts(crack, crack.mesh->dim);
}

void logInterface(const xfem::Crack& crack, const std::string& name) {
    msg().infof(
        "    interface ({}): {} cut cells, {} Heaviside-enriched nodes, {} cells with an enriched node, "
        "{} level-set values adjusted",
        name, crack.cutCells.size(), crack.enrichedNodeCount(), crack.heavisideCells.size(), crack.adjustedLevelSets);
    for (const auto& m : crack.masters)
        msg().infof("    junction on {}: the interface exists where {} * LSN({}) < 0{}", m.crack->name,
                    m.coef > 0 ? "+1" : "-1", m.crack->name, m.declared ? "" : " (inherited)");
    if (crack.enrichedNodeCount() == 0) msg().alarm(XFEM_ENRI);
}

std::shared_ptr<xfem::Crack> interfaceOf(const KeywordSet& kw, std::shared_ptr<const Mesh> mesh,
                                         std::vector<double> lsn) {
    xfem::JunctionInput junction;
    const auto& jonction = kw.factor("JONCTION");
    if (!jonction.empty()) {
        const auto& j = jonction[0];
        for (const auto& c : j.objects<xfem::Crack>("FISSURE")) {
            if (c->isCrack)
                throw NotImplemented(
                    fmt::format("{}: {} is a crack (TYPE_DISCONTINUITE='FISSURE'); junctions on "
                                "cracks with a front are not implemented, only on interfaces",
                                j.pathOf("FISSURE"), c->name));
            junction.masters.push_back(c);
        }
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
    return xfem::buildCrack(mesh, std::move(lsn), jonction.empty() ? nullptr : &junction,
                            zone.empty() ? nullptr : &zone);
}

ConceptPtr defiFissXfem(const KeywordSet& kw, CommandContext& ctx) {
    std::shared_ptr<const Mesh> mesh;
    if (kw.has("MAILLAGE")) {
        mesh = kw.object<Mesh>("MAILLAGE");
    } else {
        auto model = kw.object<Model>("MODELE");  // legacy syntax: only the mesh is used
        mesh = model->mesh;
    }
    const bool isCrack = kw.text("TYPE_DISCONTINUITE") == "FISSURE";
    const auto& defi = kw.factor("DEFI_FISS");
    if (defi.empty()) throw UserError("DEFI_FISS is mandatory");
    auto ls = levelSets(defi[0], *mesh, isCrack);
    const std::string name = ctx.resultName.empty() ? "DEFI_FISS_XFEM" : ctx.resultName;
    std::shared_ptr<xfem::Crack> crack;
    if (isCrack) {
        if (!kw.factor("JONCTION").empty())
            throw NotImplemented(kw.pathOf("JONCTION") +
                                 ": junctions of a crack with a front (TYPE_DISCONTINUITE='FISSURE') are not "
                                 "implemented; junctions join interfaces (TYPE_DISCONTINUITE='INTERFACE')");
        if (kw.has("GROUP_MA_ENRI"))
            throw NotImplemented(kw.pathOf("GROUP_MA_ENRI") +
                                 ": an enrichment zone for a crack with a front (TYPE_DISCONTINUITE='FISSURE') is "
                                 "not implemented; it restricts interfaces (TYPE_DISCONTINUITE='INTERFACE')");
        crack = xfem::buildCrackWithFront(mesh, std::move(ls.lsn), std::move(ls.lst));
        if (kw.text("TYPE_ENRI_FOND") == "GEOMETRIQUE") {
            const bool given = kw.has("RAYON_ENRI");
            const double radius = xfem::enrichCrackTipZone(*crack, given ? kw.real("RAYON_ENRI") : 0.0,
                                                           given ? 0 : static_cast<int>(kw.integer("NB_COUCHES")));
            if (radius > 0.0)
                msg().infof("    TYPE_ENRI_FOND='GEOMETRIQUE': crack-tip enrichment radius {:.6e} ({})", radius,
                            given ? "RAYON_ENRI"
                                  : fmt::format("NB_COUCHES={} times the smallest tip cell's size",
                                                kw.integer("NB_COUCHES")));
        }
    } else {
        crack = interfaceOf(kw, mesh, std::move(ls.lsn));
    }
    if (crack->adjustedLevelSets > 0) msg().alarm(XFEM_63, crack->adjustedLevelSets);
    isCrack ? logCrack(*crack, name) : logInterface(*crack, name);
    if (ctx.info >= 3)
        for (int n = 0; n < mesh->nodeCount(); ++n)
            msg().infof("      {:8s} LSN = {:.12e}  LST = {:.12e}  status {}", mesh->nodeNames[size_t(n)],
                        crack->lsn[size_t(n)], crack->lst[size_t(n)], int(crack->nodeStatus[size_t(n)]));
    return crack;
}

MA_REGISTER_COMMAND("DEFI_FISS_XFEM", defiFissXfem);

}  // namespace
}  // namespace ma
