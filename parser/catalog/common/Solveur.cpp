// SOLVEUR: the linear solver (MUMPS by default, MULT_FRONT, LDLT, PETSC, GCPC; docs/solver.md).
// As code_aster's c_solveur.py: RESI_RELA of MUMPS defaults to 1e-6 in MECA_STATIQUE and to -1 (no
// check) in STAT_NON_LINE, whose Newton corrects an inaccurate solve; FILTRAGE_MATRICE and
// MIXER_PRECISION exist in STAT_NON_LINE only.
#include "parser/catalog/common/Blocks.hpp"

namespace ma::catalog_entries {

Keyword solveur(bool nonLinear) {
    std::vector<Keyword> mumps = {
        TXM("RENUM").into({"AUTO", "AMD", "AMF", "PORD", "METIS", "QAMD", "SCOTCH", "PARMETIS", "PTSCOTCH"}).def("AUTO"),
        I("NPREC").def(8), I("PCENT_PIVOT").def(20).range(0, {}), R("RESI_RELA").def(nonLinear ? -1.0 : 1.0e-6),
        TXM("ELIM_LAGR").into({"NON", "OUI", "LAGR2"}),
        TXM("TYPE_RESOL").into({"AUTO", "NONSYM", "SYMGEN", "SYMDEF"}).def("AUTO"),
        TXM("PRETRAITEMENTS").into({"SANS", "AUTO"}).def("AUTO"),
        TXM("POSTTRAITEMENTS").into({"SANS", "AUTO", "FORCE", "MINI"}).def("AUTO"),
        TXM("GESTION_MEMOIRE").into({"AUTO", "IN_CORE", "OUT_OF_CORE", "EVAL"}).def("AUTO"),
        TXM("ACCELERATION").into({"AUTO", "FR", "FR+", "FR++", "LR", "LR+", "LR++"}).def("AUTO"),
        R("LOW_RANK_SEUIL").def(0.0).range(0.0, {}),  // only with ACCELERATION='LR*', refused
        yesNo("MATR_DISTRIBUEE"), yesNo("STOP_SINGULIER").def("OUI")};
    if (nonLinear) {
        mumps.push_back(R("FILTRAGE_MATRICE").def(-1.0));
        mumps.push_back(yesNo("MIXER_PRECISION").def("NON"));
    }
    return fact("SOLVEUR").byDefault().keywords({
        TXM("METHODE").into({"MUMPS", "MULT_FRONT", "LDLT", "PETSC", "GCPC"}).def("MUMPS"),
        bloc(when("METHODE", {"MUMPS"}), mumps),
        bloc(when("METHODE", {"MULT_FRONT"}),
             {TXM("RENUM").into({"MD", "MDA", "METIS"}).def("METIS"), I("NPREC").def(8),
              yesNo("STOP_SINGULIER").def("OUI"), TXM("ELIM_LAGR").into({"NON", "OUI"})}),
        bloc(when("METHODE", {"LDLT"}),
             {TXM("RENUM").into({"RCMK", "SANS"}).def("RCMK"), I("NPREC").def(8), yesNo("STOP_SINGULIER").def("OUI"),
              TXM("ELIM_LAGR").into({"NON", "OUI"})}),
        // The keywords code_aster puts in sub-blocks by PRE_COND (RENUM, NIVE_REMPLISSAGE, REAC_PRECOND,
        // PCENT_PIVOT...) are flat here, with code_aster's defaults; each is read only where it applies.
        bloc(when("METHODE", {"PETSC"}),
             {TXM("ALGORITHME").into({"CG", "CR", "GMRES", "GCR", "FGMRES", "GMRES_LMP"}).def("FGMRES"),
              TXM("PRE_COND")
                  .into({"LDLT_INC", "LDLT_SP", "LDLT_DP", "JACOBI", "SOR", "ML", "BOOMER", "GAMG", "BLOC_LAGR",
                         "FIELDSPLIT", "SANS"})
                  .def("LDLT_SP"),
              TXM("OPTION_PETSC").def(""), R("RESI_RELA").def(1.0e-6), I("NMAX_ITER").def(0),
              TXM("RENUM").into({"RCMK", "SANS", "METIS", "PARMETIS"}), I("NIVE_REMPLISSAGE").def(0).range(0, {}),
              R("REMPLISSAGE").def(1.0), I("REAC_PRECOND").def(30), I("PCENT_PIVOT").def(20).range(1, {}),
              TXM("GESTION_MEMOIRE").into({"IN_CORE", "AUTO"}).def("AUTO"), R("LOW_RANK_SEUIL").def(1.0e-8),
              yesNo("MATR_DISTRIBUEE").def("NON"), TXM("ELIM_LAGR").into({"NON", "OUI"})}),
        bloc(when("METHODE", {"GCPC"}),
             {TXM("PRE_COND").into({"LDLT_INC", "LDLT_SP", "LDLT_DP"}).def("LDLT_INC"), R("RESI_RELA").def(1.0e-6),
              I("NMAX_ITER").def(0), TXM("RENUM").into({"RCMK", "SANS", "METIS", "PARMETIS"}),
              I("NIVE_REMPLISSAGE").def(0).range(0, {}), I("REAC_PRECOND").def(30),
              I("PCENT_PIVOT").def(20).range(1, {}), TXM("GESTION_MEMOIRE").into({"IN_CORE", "AUTO"}).def("AUTO"),
              R("LOW_RANK_SEUIL").def(1.0e-8), TXM("ELIM_LAGR").into({"NON", "OUI"})}),
    });
}

}  // namespace ma::catalog_entries
