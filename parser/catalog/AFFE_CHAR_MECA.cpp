// AFFE_CHAR_MECA: mechanical load with real values (imposed dofs, linear relations, pressures,
// forces), and the legacy X-FEM relations and contact given as a load.
#include "parser/catalog/common/Blocks.hpp"

namespace ma::catalog_entries {

void AFFE_CHAR_MECA(Catalog& c) {
    auto meca = loadKeywords(false);
    // Legacy X-FEM syntax (≤ 2013): interface relations and contact given as a load.
    meca.push_back(yesNo("LIAISON_XFEM"));
    meca.push_back(CO("CONTACT_XFEM", {kContact}));
    c.add(cmd("AFFE_CHAR_MECA", kMechanicalLoad)
              .keywords(std::move(meca))
              .rules({auMoinsUn({"DDL_IMPO", "FACE_IMPO", "ARETE_IMPO", "LIAISON_DDL", "LIAISON_GROUP", "PRES_REP",
                                   "FORCE_CONTOUR", "FORCE_FACE", "FORCE_ARETE", "FORCE_INTERNE", "LIAISON_XFEM",
                                   "CONTACT_XFEM"})}));
}

}  // namespace ma::catalog_entries
