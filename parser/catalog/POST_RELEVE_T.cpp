// POST_RELEVE_T: nodal values of a result or field extracted into a table.
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

void POST_RELEVE_T(Catalog& c) {
    c.add(cmd("POST_RELEVE_T", kTable).keywords({
        fact("ACTION").many().mandatory().keywords(join({
            {TXM("INTITULE").mandatory(),
             TXM("OPERATION").mandatory().max(2).into({"EXTRACTION", "MOYENNE", "MOYENNE_ARITH", "EXTREMA"}),
             CO("RESULTAT", kAnyResult), CO("CHAM_GD", kAnyField),
             bloc(whenPresent("RESULTAT"),
                  {TXM("NOM_CHAM").mandatory(), I("NUME_ORDRE").many(), TXM("TOUT_ORDRE").into({"OUI"}),
                   R("INST").many(), CO("LIST_INST", {kRealList}), critere(), R("PRECISION").def(1.0e-6)},
                  {exclus({"NUME_ORDRE", "TOUT_ORDRE", "INST", "LIST_INST"})}),
             TXM("GROUP_NO").many(), TXM("NOEUD").many(), TXM("TOUT_CMP").into({"OUI"}), TXM("NOM_CMP").many(),
             TXM("RESULTANTE").many().into({"DX", "DY", "DZ", "NXX", "NYY", "NXY"}).notSupported({"NXX", "NYY", "NXY"}),
             TXM("MOMENT").many().into({"DRX", "DRY", "DRZ", "MXX", "MYY", "MXY"}).notSupported({"MXX", "MYY", "MXY"}),
             R("POINT").many(),
             TXM("REPERE").into({"GLOBAL", "LOCAL", "POLAIRE", "UTILISATEUR", "CYLINDRIQUE"})
                 .notSupported({"LOCAL", "POLAIRE", "UTILISATEUR", "CYLINDRIQUE"}).def("GLOBAL"),
             yesNo("MOYE_NOEUD").def("OUI"), TXM("FORMAT_C").into({"MODULE", "REEL", "IMAG"}).def("MODULE")},
            unsupported({"CHEMIN", "GROUP_MA", "MAILLE", "INVARIANT", "ELEM_PRINCIPAUX", "LIST_ORDRE", "NUME_MODE", "FREQ", "LIST_FREQ", "NOM_CAS", "TRAC_NOR", "TRAC_DIR",
                         "NOEUD_CMP", "VECT_Y", "ORIGINE", "AXE_Z", "ANGL_NAUT", "LIST_MODE"},
                        "miniaster extracts nodal values on GROUP_NO / NOEUD"),
        }))
            .rules({unParmi({"RESULTAT", "CHAM_GD"}), auMoinsUn({"GROUP_NO", "NOEUD"}),
                    unParmi({"TOUT_CMP", "NOM_CMP", "RESULTANTE"}),
                    ensemble({"MOMENT", "POINT"}), presentPresent({"MOMENT", "RESULTANTE"})}),
        titre(), info()}));
}

}  // namespace ma::catalog_entries
