// CALC_G THETA=_F(FISSURE=..., NUME_FOND, R_INF, R_SUP), OPTION='CALC_G' / 'CALC_K_G': the energy
// release rate (and K1, K2) at a 2D crack tip (3D fronts: CalcG3D.cpp) of an X-FEM result by the theta method, code_aster's
// table (cgcrtb, cakg2d): NUME_FOND NUME_ORDRE INST COOR_X COOR_Y G [K1 K2 G_IRWIN], a row per order.
// The engine is src/fracture (docs/cracks.md).
#include <fmt/format.h>

#include "commands/FractureKeywords.hpp"
#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "fe/Discretisation.hpp"
#include "fe/Result.hpp"
#include "fracture/DomainSampling.hpp"
#include "fracture/LipTerm.hpp"
#include "fracture/ThetaField.hpp"
#include "mesh/PointLocation.hpp"
#include "parser/CommandRegistry.hpp"
#include "post/Table.hpp"

namespace ma {
namespace {

std::shared_ptr<Table> emptyTable(bool withK) {
    auto t = std::make_shared<Table>();
    t->addColumn("NUME_FOND", ColumnType::integer());
    t->addColumn("NUME_ORDRE", ColumnType::integer());
    for (const char* c : {"INST", "COOR_X", "COOR_Y", "G"}) t->addColumn(c, ColumnType::real());
    if (withK)
        for (const char* c : {"K1", "K2", "G_IRWIN"}) t->addColumn(c, ColumnType::real());
    return t;
}

// +1 when LSN > 0 lies on the e2 side of the frame at the tip.
double positiveLsnSide(const Mesh& mesh, const xfem::Crack& crack, const fracture::TipPoint& tip) {
    const auto grad = xfem::nodalLevelSetGradient(mesh, crack.lsn);
    const PointInCell at = locatePoint(mesh, tip.point);
    std::vector<double> component(grad.size());
    double projection = 0.0;
    for (int c = 0; c < 2; ++c) {
        for (size_t n = 0; n < grad.size(); ++n) component[n] = grad[n][size_t(c)];
        projection += interpolateAt(mesh, at, component) * tip.frame.e2[size_t(c)];
    }
    return projection >= 0 ? 1.0 : -1.0;
}

ConceptPtr calcG(const KeywordSet& kw, CommandContext&) {
    auto result = kw.object<Result>("RESULTAT");
    const KeywordSet& theta = kw.factor("THETA").front();
    auto crack = theta.object<xfem::Crack>("FISSURE");
    checkCrackResult(*result, *crack, theta.pathOf("FISSURE"), "CALC_G", true);
    if (result->model->dim == 3) return calcG3D(kw, *result, *crack);
    const Mesh& mesh = *result->model->mesh;
    const int numeFond = int(theta.integer("NUME_FOND"));
    const auto grlt = xfem::nodalLevelSetGradient(mesh, crack->lst);
    const fracture::TipPoint tip = fracture::tipPoint2D(mesh, *crack, grlt, numeFond);
    double rInf = 2 * tip.cellSize, rSup = 4 * tip.cellSize;
    if (theta.has("R_INF")) {
        rInf = theta.real("R_INF"), rSup = theta.real("R_SUP");
        if (!(rSup > rInf) || rInf < 0)
            throw UserError(fmt::format("{}: R_SUP must exceed R_INF >= 0 (code_aster's RUPTURE1_6), here {} and {}",
                                        theta.pathOf("R_SUP"), rInf, rSup));
    } else {
        msg().infof("    R_INF and R_SUP not given: 2 and 4 times the tip cell size {:.6e}: {:.6e}, {:.6e}",
                    tip.cellSize, rInf, rSup);
    }
    msg().infof("    front {} of {} at ({:.6e}, {:.6e}), propagation direction ({:.6f}, {:.6f})", numeFond, crack->name,
                tip.point[0], tip.point[1], tip.frame.e1[0], tip.frame.e1[1]);
    const auto thetaField = fracture::thetaField2D(mesh, tip.point, grlt, rInf, rSup);
    const double side = positiveLsnSide(mesh, *crack, tip);
    const bool withK = kw.text("OPTION") == "CALC_K_G";
    // Only the cells where theta varies are read (fracture::domainPoints).
    Discretisation space(result->model, result->material, {},
                         [&](int cell) { return fracture::thetaVaries(mesh, cell, thetaField); });
    auto table = emptyTable(withK);
    for (const ResultStep* step : fractureSteps(*result, kw)) {
        const auto depl = step->nodal("DEPL");
        if (!depl) throw UserError(fmt::format("result {} has no DEPL at NUME_ORDRE {}", result->name, step->order));
        const auto u = space.numbering().fromNodalField(*depl);
        const auto points = fracture::domainPoints(space, u, thetaField, crack->lsn, side);
        auto v = fracture::domainIntegrals(points, tip.frame, result->model->modelisation, 2, withK);
        const auto lips = fracture::lipPoints(space, u, result->loads, *crack, step->inst,
                                              [&](int cell) { return fracture::thetaReaches(mesh, cell, thetaField); });
        if (!lips.empty()) {
            const auto lip = fracture::lipIntegrals(mesh, lips, thetaField, std::span(&tip.frame, 1),
                                                    result->model->modelisation, 2, withK);
            msg().infof("    NUME_ORDRE {}: lip-pressure term on {} lip points: G {:.6e}{}", step->order, lips.size(),
                        lip.G, withK ? fmt::format(", K1 {:.6e}, K2 {:.6e}", lip.K1, lip.K2) : std::string());
            fracture::addLipTerm(v, lip, lips, result->model->modelisation);
        }
        const size_t row = table->addRow();
        table->set(row, "NUME_FOND", static_cast<long long>(numeFond));
        table->set(row, "NUME_ORDRE", static_cast<long long>(step->order));
        table->set(row, "INST", step->inst);
        table->set(row, "COOR_X", tip.point[0]);
        table->set(row, "COOR_Y", tip.point[1]);
        table->set(row, "G", v.G);
        if (withK) table->set(row, "K1", v.K1), table->set(row, "K2", v.K2), table->set(row, "G_IRWIN", v.gIrwin);
        msg().infof("    NUME_ORDRE {}: {} integration points in the crown R_INF {:.6e} R_SUP {:.6e}: G = {:.6e}{}",
                    step->order, points.size(), rInf, rSup, v.G,
                    withK ? fmt::format(", K1 = {:.6e}, K2 = {:.6e}", v.K1, v.K2) : std::string());
    }
    if (kw.has("TITRE")) table->title = kw.texts("TITRE");
    return table;
}

MA_REGISTER_COMMAND("CALC_G", calcG);

}  // namespace
}  // namespace ma
