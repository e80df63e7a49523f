// MODI_MAILLAGE: mesh modified in place: skin orientation.
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void MODI_MAILLAGE(Catalog& c) {
    c.add(cmd("MODI_MAILLAGE", kMesh)
              .reuse(Reuse::Mandatory)
              .keywords(join({
                  {CO("MAILLAGE", {kMesh}).mandatory(),
                   fact("ORIE_PEAU_2D").many().keywords({TXM("GROUP_MA").many().mandatory(), TXM("GROUP_MA_SURF").many()}),
                   fact("ORIE_PEAU_3D").many().keywords({TXM("GROUP_MA").many().mandatory(), TXM("GROUP_MA_VOLU").many()}),
                   info()},
                  unsupported({"ORIE_FISSURE", "ORIE_NORM_COQUE", "ORIE_LIGNE", "DEFORME", "TRANSLATION", "ROTATION",
                               "MODI_MAILLE", "ECHELLE", "PLAQ_TUBE", "TUBE_COUDE", "SYMETRIE", "ORIE_SHB",
                               "ABSC_CURV", "MODI_BASE"},
                              "miniaster only orients skins (ORIE_PEAU_2D / ORIE_PEAU_3D)"),
              }))
              .rules({auMoinsUn({"ORIE_PEAU_2D", "ORIE_PEAU_3D"})}));
}

}  // namespace ma::catalog_entries
