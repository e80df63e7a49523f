// AFFE_MATERIAU: material field: materials assigned to cells.
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void AFFE_MATERIAU(Catalog& c) {
    c.add(cmd("AFFE_MATERIAU", kMaterialField)
              .keywords(join({
                  {CO("MAILLAGE", {kMesh}), CO("MODELE", {kModel}),
                   fact("AFFE").many().mandatory().keywords({
                       TXM("TOUT").into({"OUI"}), TXM("GROUP_MA").many(), TXM("MAILLE").many(),
                       CO("MATER", {kMaterial}).mandatory().max(30)})
                       .rules({unParmi({"TOUT", "GROUP_MA", "MAILLE"})}),
                   info()},
                  unsupported({"AFFE_VARC", "AFFE_COMPOR", "AFFE_NOM_VARC"}, "command variables (temperature...)"),
              }))
              .rules({auMoinsUn({"MAILLAGE", "MODELE"})}));
}

}  // namespace ma::catalog_entries
