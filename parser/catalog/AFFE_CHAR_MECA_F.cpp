// AFFE_CHAR_MECA_F: mechanical load whose values are functions of X, Y, Z, INST.
#include "parser/catalog/common/Blocks.hpp"

namespace ma::catalog_entries {

void AFFE_CHAR_MECA_F(Catalog& c) {
    c.add(cmd("AFFE_CHAR_MECA_F", kMechanicalLoad)
              .keywords(loadKeywords(true))
              .rules({auMoinsUn({"DDL_IMPO", "FACE_IMPO", "ARETE_IMPO", "LIAISON_DDL", "LIAISON_GROUP", "PRES_REP",
                                   "FORCE_CONTOUR", "FORCE_FACE", "FORCE_ARETE", "FORCE_INTERNE"})}));
}

}  // namespace ma::catalog_entries
