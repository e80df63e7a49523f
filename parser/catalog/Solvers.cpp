// Analyses: MECA_STATIQUE, STAT_NON_LINE (commands_spec §8.6, §8.7), with the shared SOLVEUR.
#include "parser/catalog/Types.hpp"

namespace ma::catalog_entries {
using namespace cata;
using namespace cata::types;

namespace {
Keyword solveur() {
    return fact("SOLVEUR").byDefault().keywords({
        TXM("METHODE").into({"MUMPS", "MULT_FRONT", "LDLT", "PETSC", "GCPC"}).def("MUMPS"),
        bloc(when("METHODE", {"MUMPS"}),
             {TXM("RENUM").into({"AUTO", "AMD", "AMF", "PORD", "METIS", "QAMD", "SCOTCH", "PARMETIS", "PTSCOTCH"})
                  .def("AUTO"),
              I("NPREC").def(8), I("PCENT_PIVOT").def(20).range(0, {}), R("RESI_RELA"),
              TXM("ELIM_LAGR").into({"NON", "OUI", "LAGR2"}),
              TXM("TYPE_RESOL").into({"AUTO", "NONSYM", "SYMGEN", "SYMDEF"}).def("AUTO"),
              TXM("PRETRAITEMENTS").into({"SANS", "AUTO"}).def("AUTO"),
              TXM("POSTTRAITEMENTS").into({"SANS", "AUTO", "FORCE", "MINI"}).def("AUTO"),
              TXM("GESTION_MEMOIRE").into({"AUTO", "IN_CORE", "OUT_OF_CORE", "EVAL"}).def("AUTO"),
              TXM("ACCELERATION").into({"AUTO", "FR", "FR+", "FR++", "LR", "LR+", "LR++"}).def("AUTO"),
              R("LOW_RANK_SEUIL").def(0.0).range(0.0, {}),  // only with ACCELERATION='LR*', refused
              yesNo("MATR_DISTRIBUEE"), yesNo("STOP_SINGULIER").def("OUI")}),
        bloc(when("METHODE", {"MULT_FRONT"}),
             {TXM("RENUM").into({"MD", "MDA", "METIS"}).def("METIS"), I("NPREC").def(8),
              yesNo("STOP_SINGULIER").def("OUI"), TXM("ELIM_LAGR").into({"NON", "OUI"})}),
        bloc(when("METHODE", {"LDLT"}),
             {TXM("RENUM").into({"RCMK", "SANS"}).def("RCMK"), I("NPREC").def(8), yesNo("STOP_SINGULIER").def("OUI"),
              TXM("ELIM_LAGR").into({"NON", "OUI"})}),
        bloc(when("METHODE", {"PETSC", "GCPC"}),
             {TXM("PRE_COND"), TXM("ALGORITHME"), TXM("RENUM"), R("RESI_RELA").def(1.0e-6), I("NMAX_ITER").def(0),
              I("REAC_PRECOND"), R("PCENT_PIVOT"), TXM("ELIM_LAGR").into({"NON", "OUI"})}),
    });
}

Keyword excit(bool nonlinear) {
    std::vector<Keyword> k{CO("CHARGE", {kMechanicalLoad}).mandatory(), CO("FONC_MULT", kAnyFunction)};
    if (nonlinear)
        k.push_back(TXM("TYPE_CHARGE").into({"FIXE_CSTE", "FIXE_PILO", "SUIV", "DIDI"})
                        .notSupported({"FIXE_PILO", "SUIV", "DIDI"}).def("FIXE_CSTE"));
    return fact("EXCIT").many().keywords(std::move(k));
}

// COMPORTEMENT, and its legacy name COMP_ELAS (≤ 2013), stored as COMPORTEMENT.
Keyword behaviour(const std::string& name) {
    auto k = fact(name).many().keywords({
        TXM("RELATION")
            .into({"ELAS", "VMIS_ISOT_LINE", "VMIS_ISOT_TRAC", "VMIS_CINE_LINE", "ELAS_VMIS_LINE", "ENDO_ISOT_BETON",
                   "MAZARS", "ELAS_HYPER"})
            .notSupported({"VMIS_ISOT_LINE", "VMIS_ISOT_TRAC", "VMIS_CINE_LINE", "ELAS_VMIS_LINE", "ENDO_ISOT_BETON",
                           "MAZARS", "ELAS_HYPER"})
            .def("ELAS"),
        TXM("DEFORMATION").into({"PETIT", "PETIT_REAC", "GROT_GDEP", "SIMO_MIEHE", "GDEF_LOG"})
            .notSupported({"PETIT_REAC", "GROT_GDEP", "SIMO_MIEHE", "GDEF_LOG"}).def("PETIT"),
        TXM("TOUT").into({"OUI"}), TXM("GROUP_MA").many(), TXM("MAILLE").many(),
    }).rules({exclus({"TOUT", "GROUP_MA", "MAILLE"})});
    if (name != "COMPORTEMENT") k.storeAs("COMPORTEMENT");
    return k;
}
}  // namespace

void addSolverCommands(Catalog& c) {
    c.add(cmd("MECA_STATIQUE", kStaticResult)
              .reuse(Reuse::Optional)
              .keywords(join({
                  {CO("MODELE", {kModel}).mandatory(), CO("CHAM_MATER", {kMaterialField}), excit(false),
                   R("INST"), CO("LIST_INST", {kRealList}), R("INST_FIN"),
                   TXM("OPTION").into({"SIEF_ELGA", "SANS"}).def("SIEF_ELGA"), solveur(), info(), titre()},
                  unsupported({"CARA_ELEM", "SENSIBILITE", "SCHEMA_THM"}, "structural elements are not modelled"),
              }))
              .rules({exclus({"INST", "LIST_INST"}), presentPresent({"INST_FIN", "LIST_INST"})}));

    c.add(cmd("STAT_NON_LINE", kNonlinearResult)
              .reuse(Reuse::Optional)
              .keywords(join({
                  {CO("MODELE", {kModel}).mandatory(), CO("CHAM_MATER", {kMaterialField}).mandatory(), excit(true),
                   CO("CONTACT", {kContact}), behaviour("COMPORTEMENT"), behaviour("COMP_ELAS"),
                   fact("INCREMENT").mandatory().keywords({
                       CO("LIST_INST", {kRealList}).mandatory(), R("INST_INIT"), R("INST_FIN"), I("NUME_INST_INIT"),
                       I("NUME_INST_FIN"), R("PRECISION").def(1.0e-6)})
                       .rules({exclus({"INST_INIT", "NUME_INST_INIT"}), exclus({"INST_FIN", "NUME_INST_FIN"})}),
                   TXM("METHODE").into({"NEWTON", "IMPLEX", "NEWTON_KRYLOV", "MODELE_REDUIT"})
                       .notSupported({"IMPLEX", "NEWTON_KRYLOV", "MODELE_REDUIT"}).def("NEWTON"),
                   fact("NEWTON").byDefault().keywords({
                       I("REAC_INCR").def(1).range(0, {}), I("REAC_ITER").def(1).range(0, {}),
                       TXM("MATRICE").into({"TANGENTE", "ELASTIQUE"}).def("TANGENTE"),
                       TXM("PREDICTION").into({"DEPL_CALCULE", "TANGENTE", "ELASTIQUE", "EXTRAPOLE"}),
                       I("REAC_ITER_ELAS").def(0), R("PAS_MINI_ELAS")}),
                   fact("CONVERGENCE").byDefault().keywords(join({
                       {R("RESI_GLOB_MAXI").range(0, {}), R("RESI_GLOB_RELA").range(0, {}),
                        I("ITER_GLOB_MAXI").def(10).range(0, {}), I("ITER_GLOB_ELAS").def(25),
                        yesNo("ARRET").def("OUI")},
                       unsupported({"RESI_REFE_RELA", "RESI_COMP_RELA", "SIGM_REFE", "EPSI_REFE"},
                                   "miniaster checks RESI_GLOB_MAXI / RESI_GLOB_RELA"),
                   })),
                   solveur(),
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
