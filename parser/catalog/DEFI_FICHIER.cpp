// DEFI_FICHIER: associates or frees a logical unit (code_aster/Cata/Commands/defi_fichier.py).
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void DEFI_FICHIER(Catalog& c) {
    c.add(cmd("DEFI_FICHIER")
              .keywords(join({
                  {TXM("ACTION").into({"ASSOCIER", "LIBERER", "RESERVER"}).def("ASSOCIER").notSupported({"RESERVER"}),
                   I("UNITE").mandatory(),
                   bloc(when("ACTION", {"ASSOCIER"}),
                        {TXM("TYPE").into({"ASCII", "BINARY", "LIBRE"}).def("ASCII").notSupported({"BINARY", "LIBRE"}),
                         TXM("ACCES").into({"NEW", "APPEND", "OLD"}).def("NEW").notSupported({"APPEND", "OLD"})}),
                   info()},
                  unsupported({"FICHIER"},
                              "miniaster writes unit N to the file of the .export's line for that unit, or to fort.N "
                              "of the output folder"),
              })));
}

}  // namespace ma::catalog_entries
