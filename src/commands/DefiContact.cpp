// DEFI_CONTACT with FORMULATION='XFEM' (xfem_spec §5.1): frictionless contact on the interfaces of
// an X-FEM model, one zone per interface (FISS_MAIT). What miniaster computes is described in
// docs/contact.md; ZONE/INTEGRATION and ORDRE_INT choose the rule of the facets as in code_aster;
// keywords that only tune code_aster's own algorithm (augmented Lagrangian coefficient, multiplier
// space, geometric loop) are accepted and logged as ignored.
#include <fmt/format.h>

#include <set>

#include "contact/ContactDefinition.hpp"
#include "contact/ContactIntegration.hpp"
#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "fe/Model.hpp"
#include "parser/CommandRegistry.hpp"
#include "xfem/Crack.hpp"
#include "xfem/XfemModel.hpp"

namespace ma {
namespace {

using contact::ContactAlgorithm;

// What miniaster computes: FORMULATION='XFEM', frictionless.
void refuseUnsupportedFormulation(const KeywordSet& kw) {
    const std::string formulation = kw.text("FORMULATION");
    if (formulation != "XFEM")
        throw NotImplemented(kw.pathOf("FORMULATION") + "='" + formulation +
                             "' is not supported by miniaster (only FORMULATION='XFEM')");
    if (kw.text("FROTTEMENT") != "SANS")
        throw NotImplemented(kw.pathOf("FROTTEMENT") + "='" + kw.text("FROTTEMENT") +
                             "': friction is not supported by miniaster (frictionless contact only)");
}

// The X-FEM model with contact that FORMULATION='XFEM' needs.
std::shared_ptr<const xfem::XfemModel> contactModel(const KeywordSet& kw, const Model& model) {
    auto xm = std::dynamic_pointer_cast<const xfem::XfemModel>(model.enrichment);
    if (!xm)
        throw UserError(
            fmt::format("{}: {} is not an X-FEM model; FORMULATION='XFEM' needs the model made by "
                        "MODI_MODELE_XFEM(..., CONTACT='STANDARD')",
                        kw.pathOf("MODELE"), model.name));
    if (xm->contact() != xfem::XfemContact::Standard)
        throw UserError(
            fmt::format("{}: the X-FEM model {} was made without contact; use "
                        "MODI_MODELE_XFEM(..., CONTACT='STANDARD') (code_aster XFEM2_9)",
                        kw.pathOf("MODELE"), model.name));
    return xm;
}

// Keywords of code_aster's own contact algorithm: accepted, listed in the log as ignored.
struct IgnoredKeywords {
    std::vector<std::string> list;
    void note(const KeywordSet& set, const std::string& key, const std::string& why) {
        if (set.has(key)) list.push_back(fmt::format("{} ({})", set.pathOf(key), why));
    }
};

void noteIgnoredGlobalKeywords(const KeywordSet& kw, IgnoredKeywords& ignored) {
    ignored.note(kw, "ITER_CONT_TYPE", "the contact loop stops when no status changes");
    ignored.note(kw, "ELIM_ARETE", "Nitsche/penalty contact has no multiplier space to restrict");
    if (kw.has("REAC_GEOM") && kw.text("REAC_GEOM") != "SANS")
        ignored.list.push_back(kw.pathOf("REAC_GEOM") + "='" + kw.text("REAC_GEOM") +
                               "' (small displacements: the facets are never updated, as with 'SANS')");
    ignored.note(kw, "NB_ITER_GEOM", "no geometric loop");
    ignored.note(kw, "ITER_GEOM_MAXI", "no geometric loop");
    ignored.note(kw, "RESI_GEOM", "no geometric loop");
    ignored.note(kw, "STOP_INTERP", "no interpenetration control loop");
}

// ZONE/ALGO_CONT: Nitsche (STANDARD) or penalty.
void readAlgorithm(const KeywordSet& z, contact::ContactZone& zone) {
    const std::string algo = z.text("ALGO_CONT");
    if (algo == "PENALISATION") {
        zone.algorithm = ContactAlgorithm::Penalty;
        zone.penalty = z.real("COEF_PENA_CONT");
        if (!(zone.penalty > 0.0))
            throw UserError(fmt::format("{} = {}: the penalty coefficient must be positive", z.pathOf("COEF_PENA_CONT"),
                                        zone.penalty));
    } else if (algo != "STANDARD") {
        throw NotImplemented(z.pathOf("ALGO_CONT") + "='" + algo + "' is not supported by miniaster");
    }
}

// One ZONE occurrence, on an interface of the model that has no zone yet (`seen`).
contact::ContactZone readZone(const KeywordSet& z, const Model& model, const xfem::XfemModel& xm, std::set<int>& seen,
                              IgnoredKeywords& ignored) {
    const auto& cracks = xm.cracks();
    contact::ContactZone zone;
    zone.crack = z.object<xfem::Crack>("FISS_MAIT");
    for (size_t i = 0; i < cracks.size(); ++i)
        if (cracks[i] == zone.crack) zone.crackIndex = static_cast<int>(i);
    if (zone.crackIndex < 0)
        throw UserError(fmt::format("{}: interface {} is not one of the interfaces of model {}", z.pathOf("FISS_MAIT"),
                                    zone.crack->name, model.name));
    if (!seen.insert(zone.crackIndex).second)
        throw UserError(
            fmt::format("{}: interface {} already has a contact zone", z.pathOf("FISS_MAIT"), zone.crack->name));
    readAlgorithm(z, zone);
    zone.initiallyActive = z.text("CONTACT_INIT") == "OUI";
    zone.bilateral = z.text("GLISSIERE") == "OUI";
    zone.integration.scheme = z.text("INTEGRATION");
    zone.integration.order = zone.integration.scheme == "NOEUD" ? 0 : static_cast<int>(z.integer("ORDRE_INT"));
    if (const std::string why = contact::missingRuleReason(xm.dim(), zone.integration); !why.empty())
        throw NotImplemented(fmt::format(
            "{}='{}' with {}={} on the triangular facets of a 3D model: {}, so miniaster has no rule to take "
            "and does not substitute another one; in 3D use INTEGRATION='NOEUD', 'GAUSS' (ORDRE_INT 1 to 6) "
            "or 'SIMPSON' with ORDRE_INT=1",
            z.pathOf("INTEGRATION"), zone.integration.scheme, z.pathOf("ORDRE_INT"), zone.integration.order, why));
    ignored.note(z, "COEF_CONT", "augmented Lagrangian coefficient; miniaster uses Nitsche");
    ignored.note(z, "ALGO_LAGR", "multiplier space of code_aster; Nitsche has none");
    ignored.note(z, "COEF_ECHELLE", "scaling of code_aster's contact equations");
    ignored.note(z, "TOLE_PROJ_EXT", "no projection: facets come from the sub-cells");
    return zone;
}

void logDefinition(const contact::ContactDefinition& def, const xfem::XfemModel& xm, const std::set<int>& seen,
                   const IgnoredKeywords& ignored) {
    const auto& cracks = xm.cracks();
    for (size_t i = 0; i < cracks.size(); ++i)
        if (!seen.count(static_cast<int>(i)))
            msg().infof("    interface {} has no contact zone: its lips are free (no contact condition)",
                        cracks[i]->name);
    for (const auto& z : def.zones)
        msg().infof("    contact zone on {}: {}, {}, CONTACT_INIT={}, GLISSIERE={}", z.crack->name,
                    z.algorithm == ContactAlgorithm::Nitsche
                        ? fmt::format("ALGO_CONT='STANDARD' (Nitsche, gamma = {} (lambda + 2 mu) / h, theta = {})",
                                      def.nitsche.gammaZero, def.nitsche.theta)
                        : fmt::format("ALGO_CONT='PENALISATION' (penalty, COEF_PENA_CONT = {:.6e})", z.penalty),
                    contact::describe(xm.dim(), z.integration), z.initiallyActive ? "OUI" : "NON",
                    z.bilateral ? "OUI" : "NON");
    msg().infof("    ITER_CONT_MAXI = {}", def.maxContactIterations);
    if (!ignored.list.empty())
        msg().infof(
            "    DEFI_CONTACT keywords accepted but ignored by miniaster (code_aster algorithm settings):\n      {}",
            fmt::join(ignored.list, "\n      "));
}

ConceptPtr defiContact(const KeywordSet& kw, CommandContext& ctx) {
    (void)ctx;
    refuseUnsupportedFormulation(kw);
    auto model = kw.object<Model>("MODELE");
    const auto xm = contactModel(kw, *model);
    auto def = std::make_shared<contact::ContactDefinition>();
    def->model = model;
    def->maxContactIterations = static_cast<int>(kw.integer("ITER_CONT_MAXI"));
    IgnoredKeywords ignored;
    noteIgnoredGlobalKeywords(kw, ignored);
    std::set<int> seen;
    for (const auto& z : kw.factor("ZONE")) def->zones.push_back(readZone(z, *model, *xm, seen, ignored));
    logDefinition(*def, *xm, seen, ignored);
    return def;
}

MA_REGISTER_COMMAND("DEFI_CONTACT", defiContact);

}  // namespace
}  // namespace ma
