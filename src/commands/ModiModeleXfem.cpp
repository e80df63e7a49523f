// MODI_MODELE_XFEM: a copy of MODELE_IN whose elements cut by the interfaces become X-FEM
// elements (xfem_spec §3). The model's enrichment also gives DDL_IMPO its X-FEM meaning (§4).
#include <fmt/format.h>

#include <cmath>
#include <map>
#include <optional>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "fe/Model.hpp"
#include "fe/Quadrature.hpp"
#include "parser/CommandRegistry.hpp"
#include "parser/RunOptions.hpp"
#include "xfem/SubcellQuadrature.hpp"
#include "xfem/XfemMessages.hpp"
#include "xfem/XfemModel.hpp"

namespace ma {
namespace {

// Expert run option `--subcell-quadrature RULE` (not a .comm keyword): 'catalogue' (0: the X-FEM
// sub-cell rules of code_aster's element catalogues) or a polynomial degree 1..kMaxSubcellDegree
// of the volume sub-cell rules. nullopt: not a rule.
std::optional<int> subcellDegreeOf(const std::string& rule) {
    if (rule == "catalogue") return 0;
    if (rule.size() == 1 && rule[0] >= '1' && rule[0] <= '0' + xfem::kMaxSubcellDegree) return rule[0] - '0';
    return std::nullopt;
}

const RunOptionRegistration subcellQuadratureOption(RunOption{
    "subcell-quadrature", "RULE",
    "--subcell-quadrature (expert option, not a code_aster keyword): RULE = catalogue (default: the X-FEM\n"
    "sub-cell rules of code_aster's element catalogues) or a degree 1..6 (every volume sub-cell uses the\n"
    "lowest rule exact for that polynomial degree).",
    [](const std::string& rule) {
        return subcellDegreeOf(rule) ? std::string()
                                     : fmt::format("'{}' is not a rule (catalogue, or a polynomial degree 1..{})", rule,
                                                   xfem::kMaxSubcellDegree);
    },
    [](const std::string& rule) {
        const int degree = *subcellDegreeOf(rule);
        return degree ? fmt::format(
                            "X-FEM       : --subcell-quadrature {} (volume sub-cells integrated to degree {}, "
                            "not code_aster's catalogue rules)",
                            degree, degree)
                      : std::string();
    }});

// Which rule each kind of sub-cell uses, and whether it is the catalogue's or the run option's, so
// that a .mess always tells how the X-FEM elements were integrated.
// The crack-tip enrichment in the .mess: nodes, unknowns, elements and their quadrature.
void logTipEnrichment(const xfem::XfemModel& xm) {
    if (xm.tipCrack() < 0) return;
    const xfem::Crack& crack = *xm.cracks()[size_t(xm.tipCrack())];
    int tipElements = 0, heaviside = 0, both = 0, twoTips = 0;
    for (int c : xm.xfemCells()) {
        bool tip = false;
        int first = -1, second = -1;
        for (int n : xm.mesh().cellNodes(c)) {
            tip = tip || xm.tipNode(n);
            const int f = xm.tipFrontOf(n);
            if (f >= 0 && first < 0) first = f;
            else if (f >= 0 && f != first) second = f;
        }
        tipElements += tip && !xm.cut(c)->skin;
        twoTips += second >= 0 && !xm.cut(c)->skin;
    }
    for (int n = 0; n < xm.mesh().nodeCount(); ++n) {
        heaviside += xm.activeSlots(n) > 0;
        both += xm.activeSlots(n) > 0 && xm.tipNode(n);
    }
    msg().infof(
        "    crack-tip enrichment of {}: {} nodes carry K1..K{} ({} unknowns; {} of them also Heaviside, status 3), "
        "{} Heaviside-enriched nodes in all, {} crack-tip elements",
        crack.name, xm.tipNodeCount(), xm.dim(), xm.tipNodeCount() * xm.dim(), both, heaviside, tipElements);
    if (xm.dim() == 2)
        msg().infof(
            "    crack-tip fields: each tip node carries those of its nearest front point, in every element of its "
            "support; {} element(s) hold tip nodes of two front points (both fields at their points)",
            twoTips);
    if (xm.subcellDegree() == 0 && xm.dim() == 2)
        msg().infof(
            "    crack-tip elements: each sub-triangle integrated by a collapsed {}x{} Gauss-Legendre rule, fanned "
            "from "
            "the front point (radial coordinate s^2) in the cell containing it (code_aster: FPG12 per sub-triangle)",
            xfem::XfemModel::kTipGaussPoints, xfem::XfemModel::kTipGaussPoints);
    else if (xm.subcellDegree() == 0)
        msg().infof(
            "    crack-tip elements: each sub-tetrahedron within {} of its diameter from the front line fanned from "
            "that line ({}x{}x{} points per face piece), the others a conical Gauss rule of {}^3 points "
            "(code_aster: FPG15 per sub-tetrahedron)",
            xfem::XfemModel::kTipFanReach, xfem::XfemModel::kTipRadialPoints, xfem::XfemModel::kTipRadialPoints,
            xfem::XfemModel::kTipAngularPoints, xfem::XfemModel::kTipFarPoints);
    msg().infof(
        "    conditioning: the linear solvers factorise the Jacobi-scaled matrix D^-1/2 K D^-1/2 (every unknown, "
        "K1..K{} included, scaled by its diagonal), in place of code_aster's preconditioning of the enriched unknowns",
        xm.dim());
}

void logSubcellQuadrature(const xfem::XfemModel& xm) {
    struct Usage {
        xfem::SubcellKind kind;
        int subcells = 0, points = 0;
    };
    // (skin, several interfaces) -> usage; the dimension is the model's for volume cells
    std::map<std::pair<bool, bool>, Usage> usage;
    int points = 0, volumePoints = 0, subcells = 0, volumeCells = 0;
    std::map<CellType, int> belowStrainDegree;  // parent type -> volume X-FEM cells
    for (int c : xm.xfemCells()) {
        const auto kind = xm.subcellKind(c);
        const CellType parent = xm.cut(c)->type;
        if (!kind.skin && xm.subcellDegree() > 0 && xm.subcellDegree() < xfem::strainDegree(parent))
            ++belowStrainDegree[parent];
        const int n = static_cast<int>(xm.cut(c)->subcells.size());
        const int p = n * quadratureRule(xfem::subcellType(kind), xm.subcellRule(c)).size();
        auto& u = usage[{kind.skin, kind.severalCracks}];
        u.kind = kind;
        u.subcells += n;
        u.points += p;
        subcells += n;
        points += p;
        if (!kind.skin) {
            volumePoints += p;
            ++volumeCells;
        }
    }
    const int degree = xm.subcellDegree();
    if (degree == 0)
        msg().info("    sub-cell quadrature: catalogue (the rules of code_aster's X-FEM element catalogues)");
    else
        msg().infof(
            "    sub-cell quadrature: degree {} (--subcell-quadrature {}, a miniaster run option, not a "
            "code_aster keyword): volume sub-cells use the lowest rule exact to degree {}; skin sub-cells "
            "keep the catalogue's rules",
            degree, degree, degree);
    for (const auto& [key, u] : usage) {
        const auto& kind = u.kind;
        const std::string used = xfem::subcellRule(kind, degree);
        const std::string catalogue = xfem::catalogueSubcellRule(kind);
        const CellType type = xfem::subcellType(kind);
        msg().infof("      {} sub-cells, {}: {} {} (degree {}, {}), {} sub-cells, {} points",
                    kind.skin ? "skin" : "volume", kind.severalCracks ? "several interfaces" : "one interface",
                    cellTypeName(type), used, quadratureRule(type, used).degree,
                    degree == 0         ? std::string("catalogue")
                    : kind.skin         ? std::string("catalogue, not overridden")
                    : used == catalogue ? "override, the same as the catalogue's " + catalogue
                                        : "override of the catalogue's " + catalogue,
                    u.subcells, u.points);
    }
    msg().infof("    sub-cell integration points: {} (volume {} in {} elements, skin {} in {}) on {} sub-cells", points,
                volumePoints, volumeCells, points - volumePoints, static_cast<int>(xm.xfemCells().size()) - volumeCells,
                subcells);
    for (const auto& [parent, cells] : belowStrainDegree)
        msg().alarm(XFEM_SUBCELL_RULE, degree, cellTypeName(parent), xfem::strainDegree(parent),
                    xfem::lowestRuleOfDegree(xfem::subcellType({xm.dim(), false, false}), degree), cells,
                    cellTypeName(parent), xfem::strainDegree(parent));
}

// Whether two interfaces are one: the same cut cells, the same junction masters on the same sides,
// and normal level sets proportional at their nodes (the same zero set in every cell: their
// Heaviside enrichments coincide).
bool sameInterface(const xfem::Crack& a, const xfem::Crack& b) {
    if (a.cutCells != b.cutCells || a.mesh != b.mesh || a.cutCells.empty()) return false;
    // Branches of a junction (JONCTION) with one level set live on different sides of their masters.
    if (a.masters.size() != b.masters.size()) return false;
    for (size_t k = 0; k < a.masters.size(); ++k)
        if (a.masters[k].crack != b.masters[k].crack || a.masters[k].coef != b.masters[k].coef) return false;
    int pivot = -1;
    double scale = 0.0;
    for (int c : a.cutCells)
        for (int n : a.mesh->cellNodes(c))
            if (std::abs(a.lsn[size_t(n)]) > scale) {
                scale = std::abs(a.lsn[size_t(n)]);
                pivot = n;
            }
    if (pivot < 0) return false;
    const double ratio = b.lsn[size_t(pivot)] / a.lsn[size_t(pivot)];
    for (int c : a.cutCells)
        for (int n : a.mesh->cellNodes(c))
            if (std::abs(b.lsn[size_t(n)] - ratio * a.lsn[size_t(n)]) > 1e-10 * std::abs(ratio) * scale) return false;
    return ratio != 0.0;
}

// Two interfaces that are one would enrich the same nodes with the same function: a singular
// system far from its cause (code_aster ends in the factorisation). One concept listed twice is
// XfemModel's refusal.
void refuseRepeatedInterfaces(const std::vector<std::shared_ptr<const xfem::Crack>>& cracks, const std::string& path) {
    for (size_t i = 0; i < cracks.size(); ++i)
        for (size_t j = 0; j < i; ++j)
            if (cracks[i] != cracks[j] && sameInterface(*cracks[j], *cracks[i]))
                throw UserError(fmt::format(
                    "{}: {} and {} are the same interface (the same cut elements, normal level sets proportional "
                    "at their nodes): their Heaviside enrichments coincide and the system would be singular; give "
                    "the interface once",
                    path, cracks[j]->name, cracks[i]->name));
}

ConceptPtr modiModeleXfem(const KeywordSet& kw, CommandContext& ctx) {
    auto in = kw.object<Model>("MODELE_IN");
    if (in->enrichment)
        throw UserError(kw.pathOf("MODELE_IN") + ": " + in->name +
                        " is already an X-FEM model; give the classical model made by AFFE_MODELE");
    std::vector<std::shared_ptr<const xfem::Crack>> cracks;
    for (const auto& c : kw.objects<xfem::Crack>("FISSURE")) { cracks.push_back(c); }
    refuseRepeatedInterfaces(cracks, kw.pathOf("FISSURE"));
    const std::string contact = kw.text("CONTACT");
    const xfem::XfemContact mode = contact == "SANS" ? xfem::XfemContact::None : xfem::XfemContact::Standard;
    if (contact != "SANS" && contact != "STANDARD" && contact != "P1P1" && contact != "OUI")
        throw NotImplemented(kw.pathOf("CONTACT") + "='" + contact + "' is not supported (SANS, STANDARD)");
    // Conditioning criterion of §3.10 (a slot is dropped when its support fraction < crit^dim).
    // code_aster: 1e-8 with PRETRAITEMENTS='AUTO'/'FORCE', 1e-4 with 'SANS'. miniaster's solvers
    // factorise the Jacobi-scaled matrix D^-1/2 K D^-1/2 (src/solver), which removes the
    // ill-conditioning of small-fraction slots; dropping a slot, on the other hand, removes a
    // region from the discrete space and breaks the exact rigid-block answer (5e-13 at a fraction
    // of 3e-17, interfaces 1e-4 h off a node row near a junction; docs/xfem.md). So 'AUTO'/'FORCE'
    // only drop domains whose linear size is round-off of the cell's (1e-15); 'SANS' keeps 1e-4.
    const double criterion = kw.text("PRETRAITEMENTS") == "SANS" ? 1e-4 : 1e-15;

    auto out = std::make_shared<Model>(*in);
    const auto rule = ctx.runOptions.find("subcell-quadrature");
    const int degree = rule == ctx.runOptions.end() ? 0 : *subcellDegreeOf(rule->second);
    auto xm = std::make_shared<xfem::XfemModel>(*out, cracks, mode, criterion, degree);
    if (xm->tipCrack() >= 0 && mode != xfem::XfemContact::None)
        throw NotImplemented(kw.pathOf("CONTACT") + "='" + contact +
                             "': contact on the lips of a crack with a front in the mesh (crack-tip enrichment) is "
                             "not implemented; CONTACT='SANS'");
    out->enrichment = xm;

    std::map<std::pair<int, int>, int> types;  // (cracks seen, slots) -> elements
    int subcells = 0;
    for (int c : xm->xfemCells()) {
        const auto* cut = xm->cut(c);
        ++types[{static_cast<int>(cut->cracks.size()), xm->cellHeavisideCount(c)}];
        subcells += static_cast<int>(cut->subcells.size());
    }
    int enriched = 0, multi = 0;
    for (int n = 0; n < out->mesh->nodeCount(); ++n) {
        const int a = xm->activeSlots(n);
        enriched += a > 0;
        multi += a > 1;
    }
    msg().infof(
        "    X-FEM model with {} interface(s), contact {}: {} X-FEM elements ({} sub-cells), {} enriched "
        "nodes ({} with several Heaviside enrichments), {} inactive Heaviside slots",
        cracks.size(), contact, xm->xfemCells().size(), subcells, enriched, multi, xm->inactiveSlots().size());
    for (const auto& [key, count] : types)
        msg().infof("      {} element(s) seeing {} interface(s), {} Heaviside slot(s) per node", count, key.first,
                    key.second);
    msg().infof(
        "    conditioning: smallest retained enrichment support fraction {:.6e} (criterion {:.1e}), {} "
        "enrichment(s) dropped",
        xm->smallestRetainedFraction(), std::pow(criterion, xm->dim()), xm->droppedSlots());
    logSubcellQuadrature(*xm);
    logTipEnrichment(*xm);
    return out;
}

MA_REGISTER_COMMAND("MODI_MODELE_XFEM", modiModeleXfem);

}  // namespace
}  // namespace ma
