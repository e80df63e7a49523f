#include "contact/ContactDefinition.hpp"

#include "xfem/XfemModel.hpp"

namespace ma::contact {

const xfem::XfemModel& ContactDefinition::xfemModel() const {
    return dynamic_cast<const xfem::XfemModel&>(*model->enrichment);
}

int ContactDefinition::zoneOfCrack(int crackIndex) const {
    for (size_t z = 0; z < zones.size(); ++z)
        if (zones[z].crackIndex == crackIndex) return static_cast<int>(z);
    return -1;
}

}  // namespace ma::contact
