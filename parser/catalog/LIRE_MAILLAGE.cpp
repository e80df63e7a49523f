// LIRE_MAILLAGE: mesh read from a MED, code_aster text or gmsh (MSH 2 text) file.
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void LIRE_MAILLAGE(Catalog& c) {
    c.add(cmd("LIRE_MAILLAGE", kMesh).keywords(join({
        {I("UNITE").def(20),
         TXM("FORMAT").into({"ASTER", "GIBI", "GMSH", "IDEAS", "MED"}).notSupported({"GIBI", "IDEAS"}).def("MED"),
         bloc(when("FORMAT", {"MED"}), {TXM("NOM_MED"), I("INFO_MED").intoInt({1, 2, 3}).def(1)}),
         fact("VERI_MAIL").byDefault().keywords({yesNo("VERIF").def("OUI"), R("APLAT").def(1.0e-3)}),
         info()},
        unsupported({"PARTITIONNEUR", "LECTURE_PARALLELE"}, "parallel reading"),
    })));
}

}  // namespace ma::catalog_entries
