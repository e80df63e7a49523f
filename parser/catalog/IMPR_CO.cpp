// IMPR_CO: a listing of concepts (code_aster prints their JEVEUX objects; miniaster its own data).
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void IMPR_CO(Catalog& c) {
    c.add(cmd("IMPR_CO").keywords(join({
        {I("UNITE").def(8), I("NIVEAU").intoInt({-1, 0, 1, 2}).def(2), yesNo("ATTRIBUT").def("NON"),
         yesNo("CONTENU").def("OUI"), TXM("BASE").into({" ", "G", "V", "L"}).def("G"),
         fact("CONCEPT").many().keywords({CO("NOM", kAnyConcept).many().mandatory()}), I("POSITION").def(1),
         TXM("PERMUTATION").into({"OUI", "NON"})},
        unsupported({"CHAINE", "TOUT"}, "name the concepts under CONCEPT/NOM"),
    })).rules({unParmi({"CONCEPT", "CHAINE", "TOUT"})}));
}

}  // namespace ma::catalog_entries
