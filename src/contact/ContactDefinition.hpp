#pragma once
// The contact concept (char_contact) made by DEFI_CONTACT with FORMULATION='XFEM': one zone per
// interface (FISS_MAIT) with its algorithm, and the parameters of the contact loop of
// STAT_NON_LINE (docs/contact.md).
#include <memory>
#include <string>
#include <vector>

#include "contact/ContactIntegration.hpp"
#include "core/Concept.hpp"
#include "fe/Model.hpp"

namespace ma::xfem {
class Crack;
class XfemModel;
}  // namespace ma::xfem

namespace ma::contact {

enum class ContactAlgorithm {
    Nitsche,  // ALGO_CONT='STANDARD': consistent (exact when the exact solution is discrete)
    Penalty   // ALGO_CONT='PENALISATION': sigma_n = COEF_PENA_CONT * min(gap, 0)
};

struct ContactZone {
    std::shared_ptr<const xfem::Crack> crack;  // FISS_MAIT
    int crackIndex = -1;                       // index in the X-FEM model's crack list
    ContactAlgorithm algorithm = ContactAlgorithm::Nitsche;
    double penalty = 0.0;            // COEF_PENA_CONT
    bool initiallyActive = false;    // CONTACT_INIT='OUI'
    bool bilateral = false;          // GLISSIERE='OUI': a point that has been in contact stays active
    ContactIntegration integration;  // INTEGRATION, ORDRE_INT: the rule of the zone's facets
};

// Nitsche parameters (docs/contact.md, "Parameters"): at each facet pair gamma = gammaZero * M *
// |shared interface| / (|block -| + |block +|), M the larger P-wave modulus lambda + 2 mu of the two
// sides; theta = 1 (symmetric).
struct NitscheParameters {
    double gammaZero = 100.0;
    double theta = 1.0;
};

class ContactDefinition : public Concept {
public:
    std::string typeName() const override { return "char_contact"; }

    std::shared_ptr<const Model> model;  // the X-FEM model (MODI_MODELE_XFEM, CONTACT='STANDARD')
    std::vector<ContactZone> zones;
    int maxContactIterations = 0;  // ITER_CONT_MAXI (DEFI_CONTACT)
    NitscheParameters nitsche;

    const xfem::XfemModel& xfemModel() const;
    // Zone of a crack of the X-FEM model, or -1.
    int zoneOfCrack(int crackIndex) const;
};

}  // namespace ma::contact
