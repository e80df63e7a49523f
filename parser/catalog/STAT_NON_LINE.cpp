// STAT_NON_LINE: nonlinear static analysis (Newton, contact active set).
#include "parser/catalog/common/Blocks.hpp"

namespace ma::catalog_entries {

void STAT_NON_LINE(Catalog& c) {
    c.add(cmd("STAT_NON_LINE", kNonlinearResult)
              .reuse(Reuse::Optional)
              .keywords(join({
                  {CO("MODELE", {kModel}).mandatory(), CO("CHAM_MATER", {kMaterialField}).mandatory(), excit(true),
                   CO("CONTACT", {kContact}), comportement("COMPORTEMENT"), comportement("COMP_ELAS"),
                   fact("INCREMENT").mandatory().keywords({
                       CO("LIST_INST", {kRealList}).mandatory(), R("INST_INIT"), R("INST_FIN"), I("NUME_INST_INIT"),
                       I("NUME_INST_FIN"), R("PRECISION").def(1.0e-6)})
                       .rules({exclus({"INST_INIT", "NUME_INST_INIT"}), exclus({"INST_FIN", "NUME_INST_FIN"})}),
                   TXM("METHODE").into({"NEWTON", "IMPLEX", "NEWTON_KRYLOV", "MODELE_REDUIT"})
                       .notSupported({"IMPLEX", "NEWTON_KRYLOV", "MODELE_REDUIT"}).def("NEWTON"),
                   newton(), convergence(), solveur(true),
                   fact("ARCHIVAGE").keywords({CO("LIST_INST", {kRealList}), R("INST").many(), I("PAS_ARCH"),
                                               TXM("CHAM_EXCLU").many(), R("PRECISION").def(1.0e-6), critere()})
                       .rules({exclus({"LIST_INST", "INST", "PAS_ARCH"})}),
                   info(), titre()},
                  unsupported({"CARA_ELEM", "ETAT_INIT", "PILOTAGE", "RECH_LINEAIRE", "ENERGIE", "OBSERVATION",
                               "SUIVI_DDL", "CRIT_QUALITE", "AFFICHAGE", "COMP_INCR", "AMOR_RAYL_RIGI", "ERRE_THM",
                               "SCHEMA_THM", "EXCIT_RESU", "SENSIBILITE", "LIST_INST_AUTO"},
                              "not modelled by miniaster (linear elastic, small strains, fixed loads)"),
              }))
              .rules({exclus({"COMPORTEMENT", "COMP_ELAS"})}));
}

}  // namespace ma::catalog_entries
