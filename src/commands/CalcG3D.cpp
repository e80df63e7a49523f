// CALC_G on a 3D crack front (THETA=_F(FISSURE, NUME_FOND, R_INF, R_SUP), LISSAGE=_F(LISSAGE_THETA,
// LISSAGE_G, DEGRE): LEGENDRE / LEGENDRE, LAGRANGE / LAGRANGE or LAGRANGE_NO_NO): code_aster's table (cgcrtb, cakg3d), a row
// per order and front point: NUME_FOND NUME_ORDRE INST COOR_X COOR_Y COOR_Z NUM_PT ABSC_CURV G
// [K1 K2 G_IRWIN K3]. The engine is src/fracture/FrontG (docs/cracks.md).
#include <fmt/format.h>

#include <algorithm>

#include "commands/FractureKeywords.hpp"
#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "fracture/FractureMessages.hpp"
#include "fracture/FrontG.hpp"
#include "post/Table.hpp"

namespace ma {
namespace {

std::shared_ptr<Table> frontTable(bool withK) {
    auto t = std::make_shared<Table>();
    t->addColumn("NUME_FOND", ColumnType::integer());
    t->addColumn("NUME_ORDRE", ColumnType::integer());
    for (const char* c : {"INST", "COOR_X", "COOR_Y", "COOR_Z"}) t->addColumn(c, ColumnType::real());
    t->addColumn("NUM_PT", ColumnType::integer());
    for (const char* c : {"ABSC_CURV", "G"}) t->addColumn(c, ColumnType::real());
    if (withK)
        for (const char* c : {"K1", "K2", "G_IRWIN", "K3"}) t->addColumn(c, ColumnType::real());
    return t;
}

// code_aster's cgveli: LEGENDRE / LEGENDRE, LAGRANGE / LAGRANGE or LAGRANGE_NO_NO; the mixed rule
// (LAGRANGE theta, LEGENDRE G) is refused for a fiss_xfem (RUPTURE0_76), LEGENDRE theta with a
// LAGRANGE G always (RUPTURE0_86).
fracture::GSmoothing smoothingOf(const KeywordSet& lissage) {
    const std::string thetaRule = lissage.text("LISSAGE_THETA"), gRule = lissage.text("LISSAGE_G");
    if (thetaRule == "LEGENDRE" && gRule == "LEGENDRE") return fracture::GSmoothing::Legendre;
    if (thetaRule == "LAGRANGE" && gRule == "LAGRANGE") return fracture::GSmoothing::Lagrange;
    if (thetaRule == "LAGRANGE" && gRule == "LAGRANGE_NO_NO") return fracture::GSmoothing::LagrangeNoNo;
    throw UserError(fmt::format(
        "{}: LISSAGE_THETA='{}' with LISSAGE_G='{}' is not a smoothing of CALC_G on an X-FEM crack (code_aster's {}): "
        "give LEGENDRE for both, or LISSAGE_THETA='LAGRANGE' with LISSAGE_G='LAGRANGE' or 'LAGRANGE_NO_NO'",
        lissage.pathOf("LISSAGE_G"), thetaRule, gRule, thetaRule == "LAGRANGE" ? "RUPTURE0_76" : "RUPTURE0_86"));
}

void addRows(Table& table, int numeFond, const ResultStep& step, const fracture::Front3D& front,
             const std::vector<fracture::FrontValues>& values, bool withK) {
    for (size_t i = 0; i < values.size(); ++i) {
        const size_t row = table.addRow();
        table.set(row, "NUME_FOND", static_cast<long long>(numeFond));
        table.set(row, "NUME_ORDRE", static_cast<long long>(step.order));
        table.set(row, "INST", step.inst);
        table.set(row, "COOR_X", front.points[i][0]);
        table.set(row, "COOR_Y", front.points[i][1]);
        table.set(row, "COOR_Z", front.points[i][2]);
        table.set(row, "NUM_PT", static_cast<long long>(i + 1));
        table.set(row, "ABSC_CURV", front.abscissa[i]);
        table.set(row, "G", values[i].G);
        if (!withK) continue;
        table.set(row, "K1", values[i].K1);
        table.set(row, "K2", values[i].K2);
        table.set(row, "G_IRWIN", values[i].gIrwin);
        table.set(row, "K3", values[i].K3);
    }
}

}  // namespace

ConceptPtr calcG3D(const KeywordSet& kw, const Result& result, const xfem::Crack& crack) {
    const KeywordSet& theta = kw.factor("THETA").front();
    const KeywordSet& lissage = kw.factor("LISSAGE").front();
    const auto smoothing = smoothingOf(lissage);
    const int degree = lissage.has("DEGRE") ? int(lissage.integer("DEGRE")) : 5;
    const Mesh& mesh = *result.model->mesh;
    const int numeFond = int(theta.integer("NUME_FOND"));
    std::optional<std::pair<double, double>> radii;
    if (theta.has("R_INF")) {
        radii = {theta.real("R_INF"), theta.real("R_SUP")};
        if (!(radii->second > radii->first) || radii->first < 0)
            throw UserError(fmt::format("{}: R_SUP must exceed R_INF >= 0 (code_aster's RUPTURE1_6), here {} and {}",
                                        theta.pathOf("R_SUP"), radii->first, radii->second));
    }
    if (smoothing == fracture::GSmoothing::Legendre && numeFond >= 1 && size_t(numeFond) <= crack.fronts.size() &&
        crack.fronts[size_t(numeFond - 1)].closed)
        throw UserError(
            fmt::format("{}: front {} of crack {} is closed: LEGENDRE smoothing needs an open front, give "
                        "LISSAGE_THETA='LAGRANGE' (code_aster's RUPTURE0_90)",
                        lissage.pathOf("LISSAGE_THETA"), numeFond, crack.name));
    size_t points = 0;
    if (theta.has("NB_POINT_FOND")) {
        const auto n = theta.integer("NB_POINT_FOND");
        if (n < 2)
            throw UserError(
                fmt::format("{}: NB_POINT_FOND must be at least 2, here {}", theta.pathOf("NB_POINT_FOND"), n));
        points = size_t(n);
    }
    const auto setup = fracture::frontGSetup(mesh, crack, numeFond, radii, smoothing, degree, points);
    if (!radii) {
        const auto [smallest, largest] = std::minmax_element(setup.front.cellSize.begin(), setup.front.cellSize.end());
        if (*largest > 2 * *smallest) msg().alarm(RUPTURE1_16, *smallest, *largest);
        msg().infof(
            "    R_INF and R_SUP not given: 2 and 4 times the largest tip cell size along the front: {:.6e}, {:.6e}",
            setup.rInf, setup.rSup);
    }
    msg().infof("    front {} of {}: {} points, length {:.6e}, {} theta fields ({}), crown R_INF {:.6e} R_SUP {:.6e}",
                numeFond, crack.name, setup.front.points.size(), setup.front.abscissa.back(), setup.thetas.size(),
                lissage.text("LISSAGE_THETA"), setup.rInf, setup.rSup);
    const bool withK = kw.text("OPTION") == "CALC_K_G";
    // The numbering only: frontValues describes each element of the crown when it samples it.
    Discretisation space(result.model, result.material, {}, [](int) { return false; });
    auto table = frontTable(withK);
    for (const ResultStep* step : fractureSteps(result, kw)) {
        const auto depl = step->nodal("DEPL");
        if (!depl) throw UserError(fmt::format("result {} has no DEPL at NUME_ORDRE {}", result.name, step->order));
        const auto u = space.numbering().fromNodalField(*depl);
        const auto lips = fracture::lipPoints(space, u, result.loads, crack, step->inst,
                                              [&](int cell) { return fracture::anyThetaReaches(mesh, cell, setup); });
        if (!lips.empty())
            msg().infof("    NUME_ORDRE {}: lip-pressure term on {} lip points", step->order, lips.size());
        const auto values = fracture::frontValues(space, u, crack, setup, withK, lips);
        addRows(*table, numeFond, *step, setup.front, values, withK);
        for (size_t i = 0; i < values.size(); ++i)
            msg().infof("    NUME_ORDRE {} point {} (s = {:.6e}): G = {:.6e}{}", step->order, i + 1,
                        setup.front.abscissa[i], values[i].G,
                        withK ? fmt::format(", K1 = {:.6e}, K2 = {:.6e}, K3 = {:.6e}", values[i].K1, values[i].K2,
                                            values[i].K3)
                              : std::string());
    }
    if (kw.has("TITRE")) table->title = kw.texts("TITRE");
    return table;
}

}  // namespace ma
