// --check-syntax on a command file that calls every catalogued command (current and legacy
// syntaxes), and on ssnv511 in the syntax of 2011-2012: the validation layer accepts them, nothing
// is executed. The catalog itself is tested in process: tests/unit/parser_catalog.cpp.
#include <gtest/gtest.h>

#include <string>
#include <tuple>

#include "parser/Catalog.hpp"
#include "parser_run.hpp"

using namespace ma;
using ma::test::runComm;

// A command file that calls every catalogued command with valid keywords (current and legacy
// syntaxes) is accepted by the validation layer (--check-syntax: nothing is executed).
namespace {
const char* kEveryCommand = R"(
DEBUT(CODE=_F(NIV_PUB_WEB='INTERNET'), DEBUG=_F(SDVERI='OUI'), IGNORE_ALARM=('TEST0_12',))
PRE_GIBI()
MA = LIRE_MAILLAGE(FORMAT='MED', UNITE=20, INFO=1, NOM_MED='mesh', INFO_MED=1, VERI_MAIL=_F(VERIF='OUI', APLAT=1e-3))
MA = DEFI_GROUP(reuse=MA, MAILLAGE=MA,
        CREA_GROUP_NO=(_F(NOM='SD', OPTION='PLAN', POINT=(5., 0., 0.), VECT_NORMALE=(1., 0., 0.), PRECISION=0.1),
                       _F(GROUP_MA='LD', CRIT_NOEUD='SOMMET'),
                       _F(NOM='SDG', UNION=('SD', 'SG')), _F(NOM='SI', INTERSEC=('SD', 'SG')),
                       _F(NOM='SM', DIFFE=('SD', 'SG'))),
        CREA_GROUP_MA=(_F(NOM='FACE', OPTION='FACE_NORMALE', VECT_NORMALE=(0, 0, 1), ANGL_PREC=0.5, VERI_SIGNE='OUI'),
                       _F(NOM='SD1', OPTION='BANDE', POINT=(5, 0, 0), VECT_NORMALE=(1, 0, 0), DIST=0.1,
                          CRIT_NOEUD='AU_MOINS_UN'),
                       _F(NOM='SD', INTERSEC=('SD1', 'FACE')), _F(NOM='U', UNION=('SD1', 'FACE')),
                       _F(NOM='D', DIFFE=('SD1', 'FACE'), TYPE_MAILLE='2D')))
MA = MODI_MAILLAGE(reuse=MA, MAILLAGE=MA, ORIE_PEAU_3D=_F(GROUP_MA=('ENV', 'SD'), GROUP_MA_VOLU='VOLU'))
MA = MODI_MAILLAGE(reuse=MA, MAILLAGE=MA, ORIE_PEAU_2D=_F(GROUP_MA='LD'))
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=(_F(GROUP_MA=('SURF', 'LH'), PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'),),
                 DISTRIBUTION=_F(METHODE='CENTRALISE'), VERI_JACOBIEN='OUI')
LN1 = FORMULE(VALE='Y', NOM_PARA=['X', 'Y'])
LN2 = FORMULE(VALE='X', NOM_PARA=('X', 'Y'))
F1 = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='INTERFACE', DEFI_FISS=_F(FONC_LN=LN1), INFO=1)
F2 = DEFI_FISS_XFEM(MODELE=MO, TYPE_DISCONTINUITE='INTERFACE', DEFI_FISS=_F(FONC_LN=LN2),
                    JONCTION=_F(FISSURE=F1, POINT=(0, 5)))
F3 = DEFI_FISS_XFEM(MAILLAGE=MA, DEFI_FISS=_F(FORM_FISS='DEMI_DROITE', PFON=(0.3, 0.45, 0.), DTAN=(1., 0., 0.)))
F4 = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='FISSURE', DEFI_FISS=_F(FONC_LN=LN1, FONC_LT=LN2), INFO=2)
LF3 = CREA_CHAMP(TYPE_CHAM='NOEU_NEUT_R', OPERATION='EXTR', FISSURE=F3, NOM_CHAM='LTNO')
TF3 = RECU_TABLE(CO=F3, NOM_TABLE='FOND_FISS')
MX = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=(F1, F2), CONTACT='STANDARD', INFO=1)
MA2 = COPIER(CONCEPT=MA)
MA2 = DEFI_GROUP(reuse=MA2, MAILLAGE=MA2,
        CREA_GROUP_NO=(_F(NOM='H', OPTION='ENV_SPHERE', POINT=(0., 0., 5.), RAYON=1e-3, PRECISION=2e-3),
                       _F(NOM='P', OPTION='PLAN', GROUP_NO_CENTRE='H', ANGL_NAUT=(0., -90.), PRECISION=1e-3),
                       _F(NOM='C', OPTION='ENV_CYLINDRE', NOEUD_CENTRE='N1', VECT_NORMALE=(0., 0., 1.), RAYON=2.,
                          PRECISION=0.1),
                       _F(NOM='S', OPTION='SEGM_DROI_ORDO', GROUP_NO='P', NOEUD_ORIG='N1', GROUP_NO_EXTR='H',
                          PRECISION=1e-6, CRITERE='RELATIF'),
                       _F(NOM='O', OPTION='NOEUD_ORDO', GROUP_MA='LD', GROUP_NO_ORIG='H', VECT_ORIE=(0., 1., 0.)),
                       _F(NOM='X', OPTION='FISS_XFEM', FISSURE=(F1, F2), TYPE_GROUP='HEAVISIDE')),
        CREA_GROUP_MA=(_F(NOM='SPH', OPTION='SPHERE', POINT=(0., 0.), RAYON=1., CRIT_NOEUD='MAJORITE'),
                       _F(NOM='CYL', OPTION='CYLINDRE', GROUP_NO_CENTRE='H', ANGL_NAUT=(0., 90.), RAYON=1.),
                       _F(NOM='XF', OPTION='FISS_XFEM', FISSURE=F1, TYPE_GROUP='FISSUREE')))
MX2 = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=(F1, F2), CONTACT='P1P1')
MX3 = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=(F1,), CONTACT='OUI')
CT = DEFI_CONTACT(MODELE=MX, FORMULATION='XFEM', ITER_CONT_MAXI=10, ELIM_ARETE='ELIM', REAC_GEOM='SANS',
                  ZONE=(_F(FISS_MAIT=F1, INTEGRATION='NOEUD', CONTACT_INIT='OUI', GLISSIERE='NON',
                           ALGO_CONT='PENALISATION', COEF_PENA_CONT=1.e13),
                        _F(FISS_MAIT=F2, INTEGRATION='GAUSS', ORDRE_INT=3, ALGO_CONT='STANDARD', COEF_CONT=100.)))
CT2 = DEFI_CONTACT(MODELE=MX, FORMULATION='XFEM', NB_ITER_GEOM=1, REAC_GEOM='CONTROLE',
                   ZONE=_F(FISS_MAIT=F1, ALGO_LAGR='VERSION2', COEF_ECHELLE=1.0))
ACIER = DEFI_MATERIAU(ELAS=_F(E=100.0E6, NU=0.3, RHO=7800.0, ALPHA=1e-5))
CM = AFFE_MATERIAU(MAILLAGE=MA, MODELE=MX, AFFE=_F(TOUT=('OUI',), MATER=ACIER))
DEPX = FORMULE(VALE='X', NOM_PARA='X')
CH1 = AFFE_CHAR_MECA_F(MODELE=MX, DDL_IMPO=(_F(GROUP_MA=('LD', 'LG'), DX=DEPX, DY=DEPX),
                                           _F(GROUP_NO='SD', DZ=DEPX)),
                       PRES_REP=_F(GROUP_MA='LH', PRES=DEPX), FORCE_INTERNE=_F(TOUT='OUI', FY=DEPX), INFO=1)
CH2 = AFFE_CHAR_MECA(MODELE=MX, DDL_IMPO=(_F(GROUP_MA='LB', DX=0, DY=0, H1X=0, H1Y=0, H2X=0., H4Z=0.),
                                         _F(TOUT='OUI', DZ=0.), _F(NOEUD=('N1',), DX=1.), _F(MAILLE='M1', DY=0)),
                     PRES_REP=_F(TOUT='OUI', PRES=1.e6), FORCE_INTERNE=_F(GROUP_MA='SURF', FX=1., FZ=2))
CH3 = AFFE_CHAR_MECA(MODELE=MX, LIAISON_XFEM='OUI', INFO=1)
CH4 = AFFE_CHAR_MECA(MODELE=MX, CONTACT_XFEM=CT)
VAR1 = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0), INTERPOL='LIN', PROL_GAUCHE='CONSTANT',
                     PROL_DROITE='LINEAIRE', VERIF='CROISSANT', NOM_RESU='TOUTRESU')
ZERO = DEFI_CONSTANTE(VALE=0.0, NOM_RESU='TOUTRESU')
L_INST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=(_F(JUSQU_A=1, NOMBRE=1), _F(JUSQU_A=2., PAS=0.5)))
L2 = DEFI_LIST_REEL(VALE=(0., 1.))
U1 = MECA_STATIQUE(MODELE=MX, CHAM_MATER=CM, EXCIT=(_F(CHARGE=CH1), _F(CHARGE=CH2, FONC_MULT=VAR1)), INFO=1)
U1 = MECA_STATIQUE(reuse=U1, MODELE=MX, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH2), LIST_INST=L2, OPTION='SIEF_ELGA',
                   SOLVEUR=_F(METHODE='MULT_FRONT', RENUM='METIS', NPREC=8))
U2 = MECA_STATIQUE(MODELE=MX, EXCIT=_F(CHARGE=CH2), INST=1.0, SOLVEUR=_F(METHODE='LDLT'))
U3 = STAT_NON_LINE(MODELE=MX, CHAM_MATER=CM, CONTACT=CT,
                   EXCIT=(_F(CHARGE=CH1, FONC_MULT=VAR1), _F(CHARGE=CH2, TYPE_CHARGE='FIXE_CSTE')),
                   COMPORTEMENT=_F(RELATION='ELAS', GROUP_MA='SURF', DEFORMATION='PETIT'),
                   NEWTON=_F(REAC_INCR=1, REAC_ITER=1, MATRICE='TANGENTE', PREDICTION='ELASTIQUE'),
                   INCREMENT=_F(LIST_INST=L_INST, INST_INIT=0., INST_FIN=1.),
                   CONVERGENCE=_F(ITER_GLOB_MAXI=20, RESI_GLOB_MAXI=1e-6, RESI_GLOB_RELA=1e-6, ARRET='OUI'),
                   SOLVEUR=_F(METHODE='MUMPS', NPREC=-1, PCENT_PIVOT=250, RENUM='AUTO', ELIM_LAGR='NON', RESI_RELA=-1.0),
                   ARCHIVAGE=_F(CHAM_EXCLU='VARI_ELGA', PAS_ARCH=1), INFO=1)
U3 = STAT_NON_LINE(reuse=U3, MODELE=MX, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH3),
                   COMP_ELAS=_F(RELATION='ELAS', TOUT='OUI', RESI_INTE_RELA=1e-6, ITER_INTE_MAXI=100, ITER_INTE_PAS=-10),
                   INCREMENT=_F(LIST_INST=L_INST, NUME_INST_INIT=0, NUME_INST_FIN=1),
                   CONVERGENCE=_F(ARRET='NON'), SOLVEUR=_F(METHODE='PETSC', PRE_COND='LDLT_INC', RESI_RELA=1e-8),
                   ARCHIVAGE=_F(LIST_INST=L2))
MV = POST_MAIL_XFEM(MODELE=MX, PREF_NOEUD_P='NP', INFO=1)
MOV = AFFE_MODELE(MAILLAGE=MV, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='3D'))
RX = POST_CHAM_XFEM(MODELE_VISU=MOV, RESULTAT=U3)
RE = POST_CHAM_XFEM(MODELE_VISU=MOV, RESULTAT=U1, INFO=1)
DEP = POST_RELEVE_T(ACTION=(_F(INTITULE='DEPLE', GROUP_NO=('NFISSU',), RESULTAT=RX, NOM_CHAM='DEPL', NUME_ORDRE=1,
                              TOUT_CMP='OUI', OPERATION='EXTRACTION'),
                            _F(INTITULE='D2', NOEUD='N1', RESULTAT=RE, NOM_CHAM='DEPL', INST=1.0, NOM_CMP=('DX', 'DY'),
                              OPERATION='EXTRACTION')))
UC = CREA_CHAMP(OPERATION='EXTR', TYPE_CHAM='NOEU_DEPL_R', RESULTAT=U1, NOM_CHAM='DEPL', NUME_ORDRE=1)
SC = CREA_CHAMP(OPERATION='EXTR', TYPE_CHAM='ELGA_SIEF_R', RESULTAT=U3, NOM_CHAM='SIEF_ELGA', INST=1.0,
                CRITERE='ABSOLU', PRECISION=1e-8)
U3 = CALC_CHAMP(reuse=U3, RESULTAT=U3, CONTRAINTE=('SIGM_ELGA', 'SIGM_ELNO', 'SIGM_NOEU'), INST=1.0, GROUP_MA='SURF')
DEP2 = POST_RELEVE_T(ACTION=_F(INTITULE='C', GROUP_NO='SD', CHAM_GD=UC, TOUT_CMP='OUI', OPERATION='EXTRACTION'))
SXX = FORMULE(VALE='-1e6', NOM_PARA=('X', 'Y'))
T1 = POST_ERREUR(OPTION='ENER_RELA', CHAM_GD=SC, MODELE=MX, DEFORMATION='PETIT', CHAM_MATER=CM, GROUP_MA='SURF',
                 SIXX=SXX, SIYY=(SXX,), SIZZ=SXX, SIXY=SXX)
T2 = POST_ERREUR(OPTION='DEPL_RELA', CHAM_GD=UC, MODELE=MX, GROUP_MA=('SURF', 'VOLU'), DX=(DEPX, DEPX), DY=(DEPX, DEPX),
                 CHAM_MATER=CM)
DEP = CALC_TABLE(TABLE=DEP, reuse=DEP, ACTION=_F(OPERATION='EXTR', NOM_PARA=('NOEUD', 'COOR_X', 'COOR_Y', 'DX', 'DY')))
DF = FORMULE(VALE='DX-COOR_X', NOM_PARA=['DX', 'COOR_X'])
Z = [None] * 3
Z[1] = CALC_TABLE(TABLE=DEP, ACTION=(_F(OPERATION='FILTRE', NOM_PARA='NOEUD', CRIT_COMP='REGEXP', VALE_K='NP'),
                                     _F(OPERATION='FILTRE', NOM_PARA='COOR_X', CRIT_COMP='GT', VALE=0.02),
                                     _F(OPERATION='FILTRE', NOM_PARA='COOR_Y', VALE=(0.0, 1.0), CRITERE='ABSOLU',
                                        PRECISION=1e-6),
                                     _F(OPERATION='FILTRE', NOM_PARA='NUME_ORDRE', CRIT_COMP='NE', VALE_I=0),
                                     _F(OPERATION='FILTRE', NOM_PARA='DX', CRIT_COMP='MAXI_ABS'),
                                     _F(OPERATION='COMB', TABLE=DEP2),
                                     _F(OPERATION='COMB', TABLE=DEP2, NOM_PARA='NOEUD', RESTREINT='OUI'),
                                     _F(OPERATION='OPER', FORMULE=DF, NOM_PARA='DX-DX'),
                                     _F(OPERATION='OPER', FORMULE=DF, NOM_PARA='D2', NOM_COLONNE=('DX', 'COOR_Y')),
                                     _F(OPERATION='RENOMME', NOM_PARA=('D2', 'D3')),
                                     _F(OPERATION='TRI', NOM_PARA='DX', ORDRE='DECROISSANT'),
                                     _F(OPERATION='SUPPRIME', NOM_PARA='D3')),
                 TITRE='zone 1')
IMPR_TABLE(TABLE=Z[1])
IMPR_TABLE(TABLE=T1, UNITE=8, FORMAT='TABLEAU', NOM_PARA=('GROUP_MA', 'REFERENCE'), FORMAT_R='E12.5')
IMPR_TABLE(TABLE=DEP, FORMAT='AGRAF', FORMAT_R='1PE12.5', IMPR_FONCTION='NON')
IMPR_CO(CONCEPT=(_F(NOM=F1), _F(NOM=(MA, DEP, ZERO))), UNITE=8, NIVEAU=2)
DEFI_FICHIER(ACTION='ASSOCIER', UNITE=82, TYPE='ASCII', ACCES='NEW')
DEFI_FICHIER(ACTION='LIBERER', UNITE=82)
DETRUIRE(CONCEPT=_F(NOM=(ZERO,)), INFO=1)
TEST_TABLE(TABLE=Z[1], NOM_PARA='DX', TYPE_TEST='MIN', VALE_CALC=-0.25, VALE_REFE=-0.25, CRITERE='RELATIF',
           PRECISION=1e-13, REFERENCE='ANALYTIQUE')
TEST_TABLE(TABLE=T1, NOM_PARA='REFERENCE', VALE_CALC=0., VALE_REFE=0., REFERENCE='ANALYTIQUE',
           FILTRE=_F(NOM_PARA='GROUP_MA', VALE_K='TOTAL'))
TEST_TABLE(TABLE=T2, NOM_PARA='ERREUR RELATIVE', CRITERE='ABSOLU', VALE_CALC=9.6e-16, ORDRE_GRANDEUR=1.0,
           FILTRE=(_F(NOM_PARA='GROUP_MA', VALE_K='TOTAL'), _F(NOM_PARA='X', VALE=0., CRITERE='ABSOLU'),
                   _F(NOM_PARA='Y', CRIT_COMP='GT', VALE=0.)), LEGENDE='L2', VALE_ABS='NON')
TEST_TABLE(TABLE=T2, NOM_PARA='REFERENCE', VALE=6.8, PRECISION=1e-3, REFERENCE='ANALYTIQUE', VERSION='10.3')
TEST_TABLE(TABLE=T2, NOM_PARA='REFERENCE', VALE=6.8, CRITERE='RELATIF', PRECISION=1e-3)
TEST_TABLE(TABLE=T2, NOM_PARA='REFERENCE', VALE_CALC=6.8, VALE_REFE=6.8, TOLE_MACHINE=2e-4, PRECISION=2e-4,
           REFERENCE='ANALYTIQUE')
TEST_TABLE(TABLE=T2, NOM_PARA='N', VALE_CALC_I=3, TYPE_TEST='SOMM')
TEST_TABLE(TABLE=T2, NOM_PARA='GROUP_MA', VALE_CALC_K='TOTAL', FILTRE=_F(NOM_PARA='N', VALE_I=1))
TEST_RESU(RESU=(_F(RESULTAT=U1, NUME_ORDRE=1, NOM_CHAM='DEPL', NOEUD='N1', NOM_CMP='DX', VALE_CALC=0.,
                   ORDRE_GRANDEUR=1.0, CRITERE='ABSOLU', LEGENDE='L'),
                _F(RESULTAT=RX, INST=1.0, NOM_CHAM='DEPL', TYPE_TEST='SOMM_ABS', NOM_CMP='DY', VALE_CALC=1.0,
                   REFERENCE='ANALYTIQUE', VALE_REFE=1.0, PRECISION=1e-3, CRITERE=('RELATIF', 'ABSOLU'),
                   TOLE_MACHINE=(1e-6, 1e-8)),
                _F(RESULTAT=U3, NUME_ORDRE=1, NOM_CHAM='SIEF_ELGA', MAILLE='M1', POINT=1, SOUS_POINT=1,
                   NOM_CMP='SIXX', VALE_CALC=1.0, VALE_ABS='OUI')),
          CHAM_NO=(_F(CHAM_GD=UC, GROUP_NO='G1', NOM_CMP='DX', VALE_CALC=1.0), _F(CHAM_GD=UC, TYPE_TEST='MAX',
                   VALE_CALC=1.0)),
          CHAM_ELEM=(_F(CHAM_GD=SC, GROUP_MA='G', POINT=2, NOM_CMP='SIYY', VALE_CALC=1.0),
                     _F(CHAM_GD=SC, TYPE_TEST='MIN', NOM_CMP='SIXY', VALE_CALC=1.0)))
IMPR_RESU(FORMAT='MED', UNITE=80, RESU=(_F(MAILLAGE=MA), _F(RESULTAT=U1, NOM_CHAM=('DEPL', 'SIEF_ELGA'), NUME_ORDRE=1),
                                       _F(RESULTAT=U3, TOUT_ORDRE='OUI'), _F(RESULTAT=RX, INST=1.0),
                                       _F(CHAM_GD=UC), _F(CHAM_GD=SC)))
IMPR_RESU(RESU=_F(RESULTAT=RE))
IMPR_RESU(FORMAT='RESULTAT', RESU=_F(MAILLAGE=MA))
G1 = CALC_G(RESULTAT=U1, OPTION='CALC_K_G', THETA=_F(FISSURE=F4, NUME_FOND=1, R_INF=0.5, R_SUP=1.5),
            LISSAGE=_F(LISSAGE_THETA='LEGENDRE', DEGRE=3), NUME_ORDRE=1, TITRE='G', INFO=1)
K1 = POST_K1_K2_K3(FISSURE=F4, RESULTAT=U1, NUME_FOND=1, NB_NOEUD_COUPE=6, ABSC_CURV_MAXI=1.,
                   PREC_VIS_A_VIS=0.1, INST=1., CRITERE='RELATIF', PRECISION=1e-6, MATER=ACIER, TITRE='K')
FIN()
)";
}  // namespace

TEST(ParserCatalog, EveryCommandIsAcceptedBySyntaxCheck) {
    for (const auto& [name, c] : Catalog::instance().commands())
        EXPECT_NE(std::string(kEveryCommand).find(name + "("), std::string::npos) << name << " is not exercised";
    auto r = runComm(kEveryCommand, "--check-syntax");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("--- DIAGNOSTIC JOB : SYNTAX_OK (no command executed)"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("<F>"), std::string::npos) << r.output;
    EXPECT_FALSE(r.exists("out/t.resu"));  // nothing was run
    EXPECT_NE(r.output.find("Z_1 = CALC_TABLE("), std::string::npos);
    // The run never pretends: the commands were validated, not executed.
    EXPECT_NE(r.output.find("syntax checked; not executed (--check-syntax)"), std::string::npos);
}

// Keyword values the catalog cannot take are found by the static check, before any command runs:
// a FORMAT_R that is not a Fortran real format after a solve.
TEST(ParserCatalog, AFormatRThatIsNotFortranIsRefusedBeforeAnyCommandRuns) {
    auto r = runComm(std::string(kEveryCommand)
                         .replace(std::string(kEveryCommand).find("FORMAT_R='1PE12.5'"), 18, "FORMAT_R='1PQ12.5'"));
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("<F> <ERROR> IMPR_TABLE (t.comm, line 120): keyword FORMAT_R: value '1PQ12.5' is not a "
                            "Fortran real format such as 'E12.5', '1PE12.5', 'D15.8', 'F10.3' or 'G14.7'"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("# Command #0001"), std::string::npos) << r.output;  // nothing ran
    EXPECT_FALSE(r.exists("out/t.resu"));
}

// DEFI_GROUP selections miniaster does not model (crack propagation zones, tunnels) are refused by
// the static check too, with the keyword's path.
TEST(ParserCatalog, UnmodelledDefiGroupOptionsAreRefusedBeforeAnyCommandRuns) {
    const std::string every = kEveryCommand;
    for (const auto& [from, to, cause] :
         {std::tuple<std::string, std::string, std::string>{
              "TYPE_GROUP='HEAVISIDE')", "TYPE_GROUP='ZONE_MAJ')",
              "keyword CREA_GROUP_NO[6]/TYPE_GROUP: value 'ZONE_MAJ' is not supported by miniaster"},
          {"OPTION='NOEUD_ORDO', GROUP_MA='LD',", "OPTION='TUNNEL', GROUP_MA='LD',",
           "keyword CREA_GROUP_NO[5]/OPTION: value 'TUNNEL' is not supported by miniaster"}}) {
        auto r = runComm(std::string(every).replace(every.find(from), from.size(), to));
        EXPECT_EQ(r.status, 1) << r.output;
        EXPECT_NE(r.output.find("<F> <ERROR> DEFI_GROUP (t.comm, line 30): " + cause), std::string::npos) << r.output;
        EXPECT_EQ(r.output.find("# Command #0001"), std::string::npos) << r.output;  // nothing ran
    }
}

// A command file in the syntax of the 2011-2012 versions of ssnv511 (commands_spec §9, old-only
// keywords) passes the syntax check.
TEST(ParserCatalog, LegacySsnv511SyntaxIsAccepted) {
    auto r = runComm(R"(
DEBUT(CODE=_F(NOM='SSNV511E', NIV_PUB_WEB='INTERNET'), PAR_LOT='NON')
PRE_GIBI()
MAILLAG = LIRE_MAILLAGE(INFO=1)
MODELEIN = AFFE_MODELE(MAILLAGE=MAILLAG, AFFE=_F(GROUP_MA=('SURF', 'LH', 'LD'), PHENOMENE='MECANIQUE',
                                                 MODELISATION='D_PLAN'))
LN1 = FORMULE(VALE='Y', NOM_PARA=('X', 'Y'))
FISS1 = DEFI_FISS_XFEM(MODELE=MODELEIN, TYPE_DISCONTINUITE='INTERFACE', DEFI_FISS=_F(FONC_LN=LN1), INFO=1)
MODELEK = MODI_MODELE_XFEM(MODELE_IN=MODELEIN, FISSURE=FISS1, CONTACT='P1P1', INFO=1)
CTXFEM = DEFI_CONTACT(MODELE=MODELEK, FORMULATION='XFEM', ITER_CONT_MAXI=10, NB_ITER_GEOM=1,
                      ZONE=_F(FISS_MAIT=FISS1, INTEGRATION='GAUSS', CONTACT_INIT='OUI', ALGO_LAGR='VERSION2',
                              COEF_ECHELLE=1.0, GLISSIERE='NON'))
ACIER = DEFI_MATERIAU(ELAS=_F(E=100.0E6, NU=0.3, RHO=7800.0))
CHAMPMAT = AFFE_MATERIAU(MAILLAGE=MAILLAG, MODELE=MODELEK, AFFE=_F(TOUT='OUI', MATER=ACIER))
CH1 = AFFE_CHAR_MECA(MODELE=MODELEK, LIAISON_XFEM='OUI', DDL_IMPO=_F(GROUP_MA='LB', DY=0, H1Y=0), INFO=1)
CH2 = AFFE_CHAR_MECA(MODELE=MODELEK, CONTACT_XFEM=CTXFEM)
VAR1 = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))
L_INST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=1))
UTOT1 = STAT_NON_LINE(MODELE=MODELEK, CHAM_MATER=CHAMPMAT, CONTACT=CTXFEM,
                      EXCIT=(_F(CHARGE=CH1, FONC_MULT=VAR1), _F(CHARGE=CH2)),
                      COMP_ELAS=_F(RELATION='ELAS', GROUP_MA='SURF'),
                      INCREMENT=_F(LIST_INST=L_INST),
                      CONVERGENCE=_F(ITER_GLOB_MAXI=20, RESI_GLOB_MAXI=1e-6, ARRET='NON'),
                      SOLVEUR=_F(METHODE='MUMPS', PCENT_PIVOT=250, NPREC=-1), INFO=1)
MA_XFEM = POST_MAIL_XFEM(MODELE=MODELEK)
MOD_VISU = AFFE_MODELE(MAILLAGE=MA_XFEM, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
RES_XFEM = POST_CHAM_XFEM(MODELE_VISU=MOD_VISU, RESULTAT=UTOT1)
DEP = POST_RELEVE_T(ACTION=_F(INTITULE='DEPLE', GROUP_NO=('NFISSU',), RESULTAT=RES_XFEM, NOM_CHAM='DEPL',
                              TOUT_CMP='OUI', OPERATION='EXTRACTION'))
vale = [0, -0.25, -0.5, 0.75, 1]
preci = 1e-13
for i in [1, 2]:
    TEST_TABLE(TABLE=DEP, NOM_PARA='DX', TYPE_TEST='MIN', VALE=vale[i], CRITERE='RELATIF', PRECISION=preci,
               REFERENCE='ANALYTIQUE')
    TEST_TABLE(TABLE=DEP, NOM_PARA='DY', TYPE_TEST='MAX', VALE_CALC=0., VALE_REFE=vale[0], TOLE_MACHINE=2e-4,
               PRECISION=preci, CRITERE='ABSOLU', REFERENCE='ANALYTIQUE')
TEST_TABLE(TABLE=DEP, NOM_PARA='DX', TYPE_TEST='MAX', VALE=1.0, REFERENCE='NON_REGRESSION', VERSION='10.3')
FIN()
)",
                     "--check-syntax");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output.find("<F>"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("CONTACT='STANDARD'"), std::string::npos);  // 'P1P1' read as the current value
    EXPECT_NE(r.output.find("PRE_GIBI is a no-op in miniaster"), std::string::npos);
}
