#include "commands/LegacyContactLoad.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "fe/MechanicalLoad.hpp"
#include "xfem/XfemModel.hpp"

namespace ma::mechanics {

void readLegacyXfemContact(const KeywordSet& kw, MechanicalLoad& load) {
    const Model& model = *load.model;
    load.xfemLinks = kw.has("LIAISON_XFEM") && kw.text("LIAISON_XFEM") == "OUI";
    const auto* xm = dynamic_cast<const xfem::XfemModel*>(model.enrichment.get());
    if (load.xfemLinks && !xm)
        throw UserError(
            fmt::format("{}='OUI': the model {} is not an X-FEM model (the X-FEM relations need the "
                        "model made by MODI_MODELE_XFEM; code_aster XFEM2_12)",
                        kw.pathOf("LIAISON_XFEM"), model.name));
    if (kw.has("CONTACT_XFEM")) {
        auto contact = kw.object<contact::ContactDefinition>("CONTACT_XFEM");
        if (contact->model->enrichment != model.enrichment)
            throw UserError(
                fmt::format("{}: {} was defined on the model {}, this load on MODELE {} (code_aster "
                            "XFEM2_11: the contact and the load must be on the same X-FEM model)",
                            kw.pathOf("CONTACT_XFEM"), contact->name, contact->model->name, model.name));
        load.xfemContact = contact;
        msg().infof(
            "    {}={} (code_aster <= 2013: the X-FEM contact as a load): STAT_NON_LINE with this load in "
            "EXCIT solves the contact {} as with CONTACT={}",
            kw.pathOf("CONTACT_XFEM"), contact->name, contact->name, contact->name);
    }
    if (load.xfemLinks)
        msg().infof(
            "    {}='OUI' (code_aster <= 2013): the X-FEM relations it added were those between the contact "
            "multipliers of the interfaces; miniaster's contact (Nitsche) has no multipliers, so it adds no "
            "relation{}",
            kw.pathOf("LIAISON_XFEM"),
            load.xfemContact || !xm || xm->contact() != xfem::XfemContact::Standard
                ? std::string()
                : std::string(" (the model has contact: give the DEFI_CONTACT to STAT_NON_LINE/CONTACT or "
                              "here as CONTACT_XFEM)"));
}

std::shared_ptr<const contact::ContactDefinition> contactOfTheSolve(const KeywordSet& kw,
                                                                    const std::vector<LoadCase>& loads) {
    std::shared_ptr<const contact::ContactDefinition> chosen;
    std::string from;
    if (kw.has("CONTACT")) {
        chosen = kw.object<contact::ContactDefinition>("CONTACT");
        from = kw.pathOf("CONTACT");
    }
    for (size_t i = 0; i < loads.size(); ++i) {
        const auto& carried = loads[i].load->xfemContact;
        if (!carried) continue;
        auto contact = std::dynamic_pointer_cast<const contact::ContactDefinition>(carried);
        const std::string here =
            fmt::format("EXCIT[{}]/CHARGE={} (CONTACT_XFEM={})", i + 1, loads[i].load->name, contact->name);
        if (chosen && chosen != contact)
            throw UserError(
                fmt::format("two contact definitions for one solve: {} gives {}, {} gives {}. A "
                            "STAT_NON_LINE solves one contact, given as CONTACT= or (code_aster <= 2013) "
                            "as a load with AFFE_CHAR_MECA/CONTACT_XFEM: give the same one both ways, or "
                            "only one",
                            from, chosen->name, here, contact->name));
        if (chosen) {
            msg().infof("    {}: the same contact as {}", here, from);
            continue;
        }
        chosen = contact;
        from = here;
        msg().infof("    {}: the contact of this solve, as with CONTACT={} (code_aster <= 2013 syntax)", here,
                    contact->name);
    }
    return chosen;
}

void refuseContactLoads(const std::vector<LoadCase>& loads, const char* command) {
    for (size_t i = 0; i < loads.size(); ++i)
        if (loads[i].load->xfemContact)
            throw UserError(
                fmt::format("EXCIT[{}]/CHARGE={} carries the X-FEM contact {} "
                            "(AFFE_CHAR_MECA/CONTACT_XFEM); {} solves no contact: use STAT_NON_LINE",
                            i + 1, loads[i].load->name, loads[i].load->xfemContact->name, command));
}

}  // namespace ma::mechanics
