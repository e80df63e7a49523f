// MECA_STATIQUE: linear static analysis.
#include "parser/catalog/common/Blocks.hpp"

namespace ma::catalog_entries {

void MECA_STATIQUE(Catalog& c) {
    c.add(cmd("MECA_STATIQUE", kStaticResult)
              .reuse(Reuse::Optional)
              .keywords(join({
                  {CO("MODELE", {kModel}).mandatory(), CO("CHAM_MATER", {kMaterialField}), excit(false),
                   R("INST"), CO("LIST_INST", {kRealList}), R("INST_FIN"),
                   TXM("OPTION").into({"SIEF_ELGA", "SANS"}).def("SIEF_ELGA"), solveur(false), info(), titre()},
                  unsupported({"CARA_ELEM", "SENSIBILITE", "SCHEMA_THM"}, "structural elements are not modelled"),
              }))
              .rules({exclus({"INST", "LIST_INST"}), presentPresent({"INST_FIN", "LIST_INST"})}));
}

}  // namespace ma::catalog_entries
