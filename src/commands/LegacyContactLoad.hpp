#pragma once
// The X-FEM contact of code_aster <= 2013 (commands_spec §8.5): the load
// AFFE_CHAR_MECA(MODELE=..., LIAISON_XFEM='OUI', CONTACT_XFEM=<DEFI_CONTACT>) listed in EXCIT carried
// the contact relations of that DEFI_CONTACT. Its meaning is STAT_NON_LINE's CONTACT= (docs/contact.md,
// "The 2013 syntax"): these functions check such a load where it is made and resolve, for a solve,
// which contact definition its EXCIT and CONTACT= ask for together.
#include <memory>
#include <vector>

#include "contact/ContactDefinition.hpp"
#include "fe/MechanicalProblem.hpp"
#include "parser/KeywordTree.hpp"

namespace ma::mechanics {

// AFFE_CHAR_MECA's LIAISON_XFEM and CONTACT_XFEM into `load` (its model already set), checked and
// logged: LIAISON_XFEM='OUI' needs an X-FEM model (code_aster XFEM2_12); CONTACT_XFEM must be
// defined on the load's MODELE (XFEM2_11).
void readLegacyXfemContact(const KeywordSet& kw, MechanicalLoad& load);

// The contact of a STAT_NON_LINE: its CONTACT= or the one its EXCIT loads carry (CONTACT_XFEM), or
// null. The same definition given both ways is the same contact; two different ones are a conflict
// (UserError naming both). The mapping is logged.
std::shared_ptr<const contact::ContactDefinition> contactOfTheSolve(const KeywordSet& kw,
                                                                    const std::vector<LoadCase>& loads);

// MECA_STATIQUE solves no contact: a load that carries one is refused (UserError).
void refuseContactLoads(const std::vector<LoadCase>& loads, const char* command);

}  // namespace ma::mechanics
