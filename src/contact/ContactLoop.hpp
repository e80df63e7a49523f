#pragma once
// STAT_NON_LINE with contact (xfem_spec §5.7, docs/contact.md): the contact statuses are frozen
// during each Newton solve of MechanicalProblem::solveIncrement; after convergence they are
// updated from the new state (active set / semi-smooth Newton step); the increment is done when
// no status changes. ITER_CONT_MAXI reached -> NumericalError (never an unconverged result).
#include <memory>

#include "contact/ContactDefinition.hpp"
#include "contact/ContactTerms.hpp"
#include "fe/MechanicalProblem.hpp"

namespace ma::contact {

// Builds the facets and the contact terms of `definition` for `problem` and installs them
// (setAdditionalTerms), with the initial statuses (CONTACT_INIT). Logs the facets.
std::shared_ptr<ContactTerms> attachContact(MechanicalProblem& problem, const MaterialField& material,
                                            std::shared_ptr<const ContactDefinition> definition);

struct ContactIncrementReport {
    int contactIterations = 0;
    int newtonIterations = 0;
    StatusReport last;
    IncrementReport lastNewton;  // the last Newton solve (residuals)
};

// One increment at `inst` with the contact loop.
ContactIncrementReport solveIncrementWithContact(MechanicalProblem& problem, ContactTerms& terms, double inst,
                                                 const ConvergenceOptions& options);

}  // namespace ma::contact
