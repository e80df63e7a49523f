// POST_K1_K2_K3 FISSURE=..., NUME_FOND, NB_NOEUD_COUPE, ABSC_CURV_MAXI[, NB_POINT_FOND]: stress
// intensity factors at an X-FEM crack front by extrapolating the lips' displacement jump (code_aster's
// post_k1_k2_k3_ops). 2D, one tip: INST NUME_ORDRE K1 ERR_K1 K2 ERR_K2 G, a row per order; 3D, every
// point of the front: FISSURE NUME_FOND INST NUME_ORDRE NUM_PT ABSC_CURV K1 ERR_K1 K2 ERR_K2 K3 ERR_K3 G,
// a row per order and point (get_erreur's columns). Engine: src/fracture.
#include <fmt/format.h>

#include <algorithm>

#include "commands/FractureKeywords.hpp"
#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "fe/ElasticityKernels.hpp"
#include "fe/Material.hpp"
#include "fracture/FractureMessages.hpp"
#include "fracture/FrontPoints.hpp"
#include "fracture/JumpExtrapolation.hpp"
#include "fracture/LipJumps.hpp"
#include "fracture/ThetaField.hpp"
#include "mesh/PointLocation.hpp"
#include "parser/CommandRegistry.hpp"
#include "post/Table.hpp"
#include "xfem/XfemModel.hpp"

namespace ma {
namespace {

// The normal to the crack at the tip: the interpolated GRLNNO, towards increasing LSN.
Vec3 crackNormal(const Mesh& mesh, const xfem::Crack& crack, const Vec3& tip) {
    const auto grad = xfem::nodalLevelSetGradient(mesh, crack.lsn);
    const PointInCell at = locatePoint(mesh, tip);
    std::vector<double> component(grad.size());
    Vec3 n{};
    for (int c = 0; c < 2; ++c) {
        for (size_t i = 0; i < grad.size(); ++i) component[i] = grad[i][size_t(c)];
        n[size_t(c)] = interpolateAt(mesh, at, component);
    }
    const double length = norm(n);
    if (!(length > 0))
        throw UserError(fmt::format("the gradient of LSN of crack {} vanishes at its front", crack.name));
    return {n[0] / length, n[1] / length, 0.0};
}

// ABSC_CURV_MAXI, or code_aster's 5 times the largest tip cell size of the crack's fronts.
double segmentLength(const KeywordSet& kw, const Mesh& mesh, const xfem::Crack& crack, const std::vector<Vec3>& grlt) {
    if (kw.has("ABSC_CURV_MAXI")) return kw.real("ABSC_CURV_MAXI");
    double largest = 0.0, smallest = 1e300;
    for (size_t f = 0; f < crack.fronts.size(); ++f) {
        const double size = fracture::tipPoint2D(mesh, crack, grlt, int(f + 1)).cellSize;
        largest = std::max(largest, size), smallest = std::min(smallest, size);
    }
    if (largest > 2 * smallest) msg().alarm(RUPTURE0_17, int(crack.fronts.size()), smallest, largest);
    msg().infof("    ABSC_CURV_MAXI not given: 5 times the largest tip cell size, {:.6e}", 5 * largest);
    return 5 * largest;
}

// The jump of the crack-tip terms at a lip point, as code_aster's pjxfem adds it to H1:
// sum_a N_a (Phi_a(+) - Phi_a(-)) K_a over the tip nodes a of the point's cell, each node's Phi (its
// own tip's, 2D) on either side.
fracture::TipJump tipJumpOf(const Result& result, const xfem::Crack& crack, const NodalField& depl) {
    const auto* xm = dynamic_cast<const xfem::XfemModel*>(result.model->enrichment.get());
    const int kColumn[3] = {depl.componentIndex("K1"), depl.componentIndex("K2"), depl.componentIndex("K3")};
    if (!xm || xm->tipCrack() < 0 || xm->cracks()[size_t(xm->tipCrack())].get() != &crack || kColumn[0] < 0) return {};
    const Mesh& mesh = *result.model->mesh;
    const Modelisation modelisation = result.model->modelisation;
    const MaterialField* material = result.material.get();
    return [xm, &mesh, &depl, kColumn, modelisation, material](const PointInCell& at, std::span<const double> N) {
        Vec3 jump{};
        if (!material) throw UserError("the result has no material: the crack-tip terms of its jump need it");
        const Material& mat = material->at(at.cell);
        const IsotropicLaw law = IsotropicLaw::from(mat, modelisation, mat.name);
        xfem::XfemModel::TipPoint upper, lower;
        if (!xm->tipMatrixOnSide(at.cell, at.xi, 1, law.lambdaEff, law.mu, upper) ||
            !xm->tipMatrixOnSide(at.cell, at.xi, -1, law.lambdaEff, law.mu, lower))
            return jump;
        const auto nodes = mesh.cellNodes(at.cell);
        for (size_t a = 0; a < nodes.size(); ++a)
            for (int m = 0; m < 3; ++m) {
                if (kColumn[m] < 0 || !depl.has(nodes[a], kColumn[m])) continue;
                const double K = depl.at(nodes[a], kColumn[m]);
                for (int c = 0; c < 3; ++c)
                    jump[size_t(c)] += N[a] * (upper.Phi[a][c * 3 + m] - lower.Phi[a][c * 3 + m]) * K;
            }
        return jump;
    };
}

const Material& materialAt(const KeywordSet& kw, const Result& result, const Mesh& mesh, const Vec3& tip) {
    if (kw.has("MATER")) return *kw.object<Material>("MATER");
    return result.material->at(locatePoint(mesh, tip).cell);
}

std::shared_ptr<Table> emptyTable() {
    auto t = std::make_shared<Table>();
    t->addColumn("INST", ColumnType::real());
    t->addColumn("NUME_ORDRE", ColumnType::integer());
    for (const char* c : {"K1", "ERR_K1", "K2", "ERR_K2", "G"}) t->addColumn(c, ColumnType::real());
    return t;
}

// The jump in code_aster's basis (v1 the normal, v2, v3; v3 = 0 in 2D) extrapolated to the front.
fracture::JumpSifs sifsOf(const fracture::LipSamples& samples, const std::array<Vec3, 3>& basis,
                          const fracture::JumpCoefficients& coef, const ResultStep& step,
                          const std::string& resultName) {
    if (samples.abscissa.size() < 3)
        throw UserError(
            fmt::format("NUME_ORDRE {} of {}: only {} points of the lips lie in the mesh, 3 are needed "
                        "(code_aster's RUPTURE0_46): shorten ABSC_CURV_MAXI",
                        step.order, resultName, samples.abscissa.size()));
    std::array<std::vector<double>, 3> local;
    for (const Vec3& j : samples.jump)
        for (size_t c = 0; c < 3; ++c) local[c].push_back(dot(j, basis[c]));
    return fracture::extrapolateJumps(samples.abscissa, local, coef);
}

std::shared_ptr<Table> postK1K2K3InPlane(const KeywordSet& kw, const std::shared_ptr<Result>& result,
                                         const std::shared_ptr<xfem::Crack>& crack) {
    const Mesh& mesh = *result->model->mesh;
    const int numeFond = int(kw.integer("NUME_FOND"));
    const auto grlt = xfem::nodalLevelSetGradient(mesh, crack->lst);
    const fracture::TipPoint tip = fracture::tipPoint2D(mesh, *crack, grlt, numeFond);
    const double length = segmentLength(kw, mesh, *crack, grlt);
    // code_aster's basis: v1 the normal (increasing LSN), v2 = v1 turned by -90 degrees.
    const Vec3 normal = crackNormal(mesh, *crack, tip.point);
    const Vec3 tangent{normal[1], -normal[0], 0.0};
    const Material& material = materialAt(kw, *result, mesh, tip.point);
    const auto coef = fracture::JumpCoefficients::of(material.E, material.nu, result->model->modelisation);
    const int points = int(kw.integer("NB_NOEUD_COUPE"));
    auto table = emptyTable();
    for (const ResultStep* step : fractureSteps(*result, kw)) {
        const auto depl = step->nodal("DEPL");
        if (!depl) throw UserError(fmt::format("result {} has no DEPL at NUME_ORDRE {}", result->name, step->order));
        const auto samples =
            fracture::heavisideJumps(mesh, *depl, tip.point, tip.frame.e1, length, points,
                                     kw.real("PREC_VIS_A_VIS") * length, tipJumpOf(*result, *crack, *depl));
        for (size_t i = 0; i < samples.abscissa.size(); ++i)
            msg().infof("    lips' jump at abscissa {:.6e}: opening {:.6e}, sliding {:.6e}", samples.abscissa[i],
                        dot(samples.jump[i], normal), dot(samples.jump[i], tangent));
        const auto k = sifsOf(samples, {normal, tangent, Vec3{}}, coef, *step, result->name);
        const size_t row = table->addRow();
        table->set(row, "INST", step->inst);
        table->set(row, "NUME_ORDRE", static_cast<long long>(step->order));
        table->set(row, "K1", k.K[0]);
        table->set(row, "ERR_K1", k.err[0]);
        table->set(row, "K2", k.K[1]);
        table->set(row, "ERR_K2", k.err[1]);
        table->set(row, "G", k.G);
        msg().infof("    front {} of {}, NUME_ORDRE {}: {} points over {:.6e}: K1 = {:.6e}, K2 = {:.6e}, G = {:.6e}",
                    numeFond, crack->name, step->order, samples.abscissa.size(), length, k.K[0], k.K[1], k.G);
    }
    return table;
}

// ABSC_CURV_MAXI in 3D, or 5 times the largest tip cell size of all the crack's front points.
double segmentLength3D(const KeywordSet& kw, const Mesh& mesh, const xfem::Crack& crack) {
    if (kw.has("ABSC_CURV_MAXI")) return kw.real("ABSC_CURV_MAXI");
    double largest = 0.0, smallest = 1e300;
    int count = 0;
    for (size_t f = 0; f < crack.fronts.size(); ++f)
        for (const auto& p : fracture::frontPoints3D(mesh, crack, int(f + 1))) {
            largest = std::max(largest, p.cellSize), smallest = std::min(smallest, p.cellSize);
            ++count;
        }
    if (!(largest > 0)) throw InternalError("crack " + crack.name + ": no tip cell contains its front points");
    if (largest > 2 * smallest) msg().alarm(RUPTURE0_17, count, smallest, largest);
    msg().infof("    ABSC_CURV_MAXI not given: 5 times the largest tip cell size, {:.6e}", 5 * largest);
    return 5 * largest;
}

std::shared_ptr<Table> emptyTable3D() {
    auto t = std::make_shared<Table>();
    t->addColumn("FISSURE", ColumnType::text(8));
    t->addColumn("NUME_FOND", ColumnType::integer());
    t->addColumn("INST", ColumnType::real());
    t->addColumn("NUME_ORDRE", ColumnType::integer());
    t->addColumn("NUM_PT", ColumnType::integer());
    t->addColumn("ABSC_CURV", ColumnType::real());
    for (const char* c : {"K1", "ERR_K1", "K2", "ERR_K2", "K3", "ERR_K3", "G"}) t->addColumn(c, ColumnType::real());
    return t;
}

// Every point of front NUME_FOND (or NB_POINT_FOND points along it): the jump sampled back along
// VDIR from the point, in code_aster's basis v1 = VNOR, v2 = VDIR, v3 = v1 x v2 (get_pgl).
std::shared_ptr<Table> postK1K2K3AlongFront(const KeywordSet& kw, const std::shared_ptr<Result>& result,
                                            const std::shared_ptr<xfem::Crack>& crack) {
    const Mesh& mesh = *result->model->mesh;
    const int numeFond = int(kw.integer("NUME_FOND"));
    auto front = fracture::frontPoints3D(mesh, *crack, numeFond);
    if (kw.has("NB_POINT_FOND")) front = fracture::resampleFront(front, int(kw.integer("NB_POINT_FOND")));
    const double length = segmentLength3D(kw, mesh, *crack);
    const int points = int(kw.integer("NB_NOEUD_COUPE"));
    auto table = emptyTable3D();
    for (const ResultStep* step : fractureSteps(*result, kw)) {
        const auto depl = step->nodal("DEPL");
        if (!depl) throw UserError(fmt::format("result {} has no DEPL at NUME_ORDRE {}", result->name, step->order));
        const auto tipJump = tipJumpOf(*result, *crack, *depl);
        for (size_t i = 0; i < front.size(); ++i) {
            const auto& fp = front[i];
            const Vec3 v1 = unit(fp.normal), v2 = unit(fp.direction);
            const std::array<Vec3, 3> basis{v1, v2, unit(cross(v1, v2))};
            const Material& material = materialAt(kw, *result, mesh, fp.point);
            const auto coef = fracture::JumpCoefficients::of(material.E, material.nu, Modelisation::TRI_D);
            const auto samples = fracture::heavisideJumps(mesh, *depl, fp.point, v2, length, points,
                                                          kw.real("PREC_VIS_A_VIS") * length, tipJump);
            const auto k = sifsOf(samples, basis, coef, *step, result->name);
            const size_t row = table->addRow();
            table->set(row, "FISSURE", crack->name);
            table->set(row, "NUME_FOND", static_cast<long long>(numeFond));
            table->set(row, "INST", step->inst);
            table->set(row, "NUME_ORDRE", static_cast<long long>(step->order));
            table->set(row, "NUM_PT", static_cast<long long>(i + 1));
            table->set(row, "ABSC_CURV", fp.abscissa);
            for (size_t c = 0; c < 3; ++c) {
                table->set(row, fmt::format("K{}", c + 1), k.K[c]);
                table->set(row, fmt::format("ERR_K{}", c + 1), k.err[c]);
            }
            table->set(row, "G", k.G);
            msg().infof(
                "    front {} of {}, point {} (s = {:.6e}), NUME_ORDRE {}: {} points over {:.6e}: K1 = {:.6e}, "
                "K2 = {:.6e}, K3 = {:.6e}, G = {:.6e}",
                numeFond, crack->name, i + 1, fp.abscissa, step->order, samples.abscissa.size(), length, k.K[0], k.K[1],
                k.K[2], k.G);
        }
    }
    return table;
}

ConceptPtr postK1K2K3(const KeywordSet& kw, CommandContext&) {
    auto result = kw.object<Result>("RESULTAT");
    auto crack = kw.object<xfem::Crack>("FISSURE");
    checkCrackResult(*result, *crack, kw.pathOf("FISSURE"), "POST_K1_K2_K3", false);
    auto table =
        result->model->dim == 3 ? postK1K2K3AlongFront(kw, result, crack) : postK1K2K3InPlane(kw, result, crack);
    table->title =
        kw.has("TITRE")
            ? kw.texts("TITRE")
            : std::vector<std::string>{"CALCUL DES FACTEURS D'INTENSITE DES CONTRAINTES PAR LA METHODE POST_K1_K2_K3"};
    return table;
}

MA_REGISTER_COMMAND("POST_K1_K2_K3", postK1K2K3);

}  // namespace
}  // namespace ma
