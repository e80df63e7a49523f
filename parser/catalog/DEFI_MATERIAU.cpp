// DEFI_MATERIAU: a material (ELAS: linear isotropic elasticity).
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void DEFI_MATERIAU(Catalog& c) {
    c.add(cmd("DEFI_MATERIAU", kMaterial)
              .keywords(join({
                  {fact("ELAS").keywords({R("E").mandatory().range(0, {}), R("NU").mandatory().range(-1.0, 0.5),
                                          R("RHO"), R("ALPHA"), R("AMOR_ALPHA"), R("AMOR_BETA"), R("AMOR_HYST")}),
                   info()},
                  unsupported({"ELAS_FO", "ELAS_ORTH", "ELAS_ISTR", "ECRO_LINE", "ECRO_PUIS", "TRACTION", "THER",
                               "THER_NL", "BETON_DOUBLE_DP", "ENDO_ORTH_BETON", "MAZARS", "RUPT_FRAG", "VISCOCHAB",
                               "CIN1_CHAB", "ROUSSELIER", "DIS_CONTACT", "ELAS_HYPER"},
                              "miniaster models linear isotropic elasticity (ELAS) only"),
              }))
              .rules({auMoinsUn({"ELAS"})}));
}

}  // namespace ma::catalog_entries
