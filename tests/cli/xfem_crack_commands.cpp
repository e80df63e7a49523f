// Cracks through the supervisor (issue 26, step 1) on ssnv511a's mesh, the square [-5, 5]^2 in
// QUAD4: DEFI_FISS_XFEM with FORM_FISS, FONC_LN + FONC_LT and CHAM_NO_LSN + CHAM_NO_LST, the front in
// the .mess and RECU_TABLE's FOND_FISS / NB_FOND_FISS, CREA_CHAMP OPERATION='EXTR' of LNNO, LTNO,
// GRLNNO checked by TEST_RESU, and
// MODI_MODELE_XFEM with a front inside a 3D mesh and with a crack cutting it through.
#include <gtest/gtest.h>

#include <string>

#include "parser_run.hpp"

using namespace ma::test;

namespace {

const std::string kMesh = std::string("--mesh '") + MINIASTER_SHARED_DIR + "/astest/ssnv511a.mmed'";

const std::string kHead =
    "DEBUT()\n"
    "MA = LIRE_MAILLAGE(FORMAT='MED')\n"
    "MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA='SURF', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))\n";

// A crack with a front in a 3D model (sslv318a's mesh and crack): MODI_MODELE_XFEM gives its tip
// nodes K1, K2, K3 (TOPOLOGIQUE: the nodes of the cells the front crosses).
TEST(XfemCrackCommands, ThreeDimensionalTipEnrichment) {
    const auto r = runComm(
        "DEBUT()\n"
        "MA = LIRE_MAILLAGE(FORMAT='MED')\n"
        "MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='3D'))\n"
        "F = DEFI_FISS_XFEM(MAILLAGE=MA, DEFI_FISS=_F(FORM_FISS='RECTANGLE', DEMI_GRAND_AXE=0.3, "
        "DEMI_PETIT_AXE=0.15, RAYON_CONGE=0.05, CENTRE=(0.5, 0.5, 1.), VECT_X=(1., 0., 0.), VECT_Y=(0., 0., -1.)), "
        "TYPE_ENRI_FOND='TOPOLOGIQUE')\n"
        "MX = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=F)\n"
        "FIN()\n",
        std::string("--mesh '") + MINIASTER_SHARED_DIR + "/astest/sslv318a.mmed'");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("nodes carry K1..K3"), std::string::npos) << r.output;
}

}  // namespace

// A half-line crack, tip (0.3, 0.45), towards +x: LSN = y - 0.45 and LST = x - 0.3 at every node.
TEST(XfemCrackCommands, HalfLineLevelSetsAndFront) {
    const auto r =
        runComm(kHead +
                    "F = DEFI_FISS_XFEM(MAILLAGE=MA, DEFI_FISS=_F(FORM_FISS='DEMI_DROITE', "
                    "PFON=(0.3, 0.45, 0.), DTAN=(1., 0., 0.)))\n"
                    "LN = CREA_CHAMP(TYPE_CHAM='NOEU_NEUT_R', OPERATION='EXTR', FISSURE=F, NOM_CHAM='LNNO')\n"
                    "LT = CREA_CHAMP(TYPE_CHAM='NOEU_NEUT_R', OPERATION='EXTR', FISSURE=F, NOM_CHAM='LTNO')\n"
                    "GN = CREA_CHAMP(TYPE_CHAM='NOEU_NEUT_R', OPERATION='EXTR', FISSURE=F, "
                    "NOM_CHAM='GRLNNO')\n"
                    "TEST_RESU(CHAM_NO=(\n"
                    "  _F(CHAM_GD=LN, TYPE_TEST='MAX', NOM_CMP='X1', VALE_CALC=4.55, VALE_REFE=4.55,\n"
                    "     REFERENCE='ANALYTIQUE', CRITERE='ABSOLU', PRECISION=1e-14),\n"
                    "  _F(CHAM_GD=LN, TYPE_TEST='MIN', NOM_CMP='X1', VALE_CALC=-5.45, VALE_REFE=-5.45,\n"
                    "     REFERENCE='ANALYTIQUE', CRITERE='ABSOLU', PRECISION=1e-14),\n"
                    "  _F(CHAM_GD=LT, TYPE_TEST='MAX', NOM_CMP='X1', VALE_CALC=4.7, VALE_REFE=4.7,\n"
                    "     REFERENCE='ANALYTIQUE', CRITERE='ABSOLU', PRECISION=1e-14),\n"
                    "  _F(CHAM_GD=LT, TYPE_TEST='MIN', NOM_CMP='X1', VALE_CALC=-5.3, VALE_REFE=-5.3,\n"
                    "     REFERENCE='ANALYTIQUE', CRITERE='ABSOLU', PRECISION=1e-14),\n"
                    "  _F(CHAM_GD=GN, TYPE_TEST='MIN', NOM_CMP='X2', VALE_CALC=1., VALE_REFE=1.,\n"
                    "     REFERENCE='ANALYTIQUE', CRITERE='ABSOLU', PRECISION=1e-12),\n"
                    "  _F(CHAM_GD=GN, TYPE_TEST='SOMM_ABS', NOM_CMP='X1', VALE_CALC=0., VALE_REFE=0.,\n"
                    "     REFERENCE='ANALYTIQUE', CRITERE='ABSOLU', PRECISION=1e-12)))\n"
                    "TF = RECU_TABLE(CO=F, NOM_TABLE='FOND_FISS')\n"
                    "TN = RECU_TABLE(CO=F, NOM_TABLE='NB_FOND_FISS')\n"
                    "IMPR_TABLE(TABLE=TF)\n"
                    "TEST_TABLE(TABLE=TF, NOM_PARA='COOR_X', VALE_CALC=0.3, VALE_REFE=0.3,\n"
                    "           REFERENCE='ANALYTIQUE', CRITERE='ABSOLU', PRECISION=1e-14)\n"
                    "TEST_TABLE(TABLE=TF, NOM_PARA='COOR_Y', VALE_CALC=0.45, VALE_REFE=0.45,\n"
                    "           REFERENCE='ANALYTIQUE', CRITERE='ABSOLU', PRECISION=1e-14)\n"
                    "TEST_TABLE(TABLE=TN, NOM_PARA='NOMBRE', VALE_CALC_I=1)\n"
                    "FIN()\n",
                kMesh);
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("number of crack front points: 1; crack fronts: 1"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("   3.00000E-01   4.50000E-01"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("1 cells containing the front"), std::string::npos) << r.output;
    EXPECT_NE(r.file("out/t.resu").find("NUME_FOND"), std::string::npos) << r.file("out/t.resu");
}

// The same crack from FONC_LN + FONC_LT, then from the extracted fields (CHAM_NO_LSN +
// CHAM_NO_LST): the same front. The model with it is crack-tip enriched (TOPOLOGIQUE: the nodes
// of the cell holding the tip; the default GEOMETRIQUE with NB_COUCHES=2 gives more).
TEST(XfemCrackCommands, FunctionsAndFieldsGiveTheSameFrontModelIsTipEnriched) {
    const auto r =
        runComm(kHead +
                    "LNF = FORMULE(VALE='Y-0.45', NOM_PARA=['X', 'Y'])\n"
                    "LTF = FORMULE(VALE='X-0.3', NOM_PARA=['X', 'Y'])\n"
                    "F1 = DEFI_FISS_XFEM(MAILLAGE=MA, DEFI_FISS=_F(FONC_LN=LNF, FONC_LT=LTF))\n"
                    "LN = CREA_CHAMP(TYPE_CHAM='NOEU_NEUT_R', OPERATION='EXTR', FISSURE=F1, NOM_CHAM='LNNO')\n"
                    "LT = CREA_CHAMP(TYPE_CHAM='NOEU_NEUT_R', OPERATION='EXTR', FISSURE=F1, NOM_CHAM='LTNO')\n"
                    "F2 = DEFI_FISS_XFEM(MAILLAGE=MA, DEFI_FISS=_F(CHAM_NO_LSN=LN, CHAM_NO_LST=LT), "
                    "TYPE_ENRI_FOND='TOPOLOGIQUE')\n"
                    "MX = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=F2)\n"
                    "FIN()\n",
                kMesh);
    EXPECT_EQ(r.status, 0) << r.output;
    size_t at = 0, count = 0;
    while ((at = r.output.find("   3.00000E-01   4.50000E-01", at)) != std::string::npos) ++count, ++at;
    EXPECT_EQ(count, 2u) << r.output;
    EXPECT_NE(r.output.find("crack-tip enrichment of F2: 4 nodes carry K1..K2 (8 unknowns"), std::string::npos)
        << r.output;
}

// A crack whose front is outside the mesh cuts it through: alarm XFEM_58, and the X-FEM model and
// its visualisation mesh are those of an interface.
TEST(XfemCrackCommands, ThroughCrackIsAccepted) {
    const auto r = runComm(kHead +
                               "F = DEFI_FISS_XFEM(MAILLAGE=MA, DEFI_FISS=_F(FORM_FISS='DEMI_DROITE', "
                               "PFON=(20., 0.45, 0.), DTAN=(1., 0., 0.)))\n"
                               "MX = MODI_MODELE_XFEM(MODELE_IN=MO, FISSURE=F)\n"
                               "MV = POST_MAIL_XFEM(MODELE=MX)\n"
                               "FIN()\n",
                           kMesh);
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("XFEM_58"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("on the interfaces in group NFISSU"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("X-FEM model with 1 interface(s)"), std::string::npos) << r.output;
}

// Forms and types that do not fit, and a crack without its tangential level set.
TEST(XfemCrackCommands, MisfitsAreRefused) {
    auto r = runComm(kHead +
                         "F = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='INTERFACE', DEFI_FISS=_F("
                         "FORM_FISS='DEMI_DROITE', PFON=(0.3, 0.45, 0.), DTAN=(1., 0., 0.)))\nFIN()\n",
                     kMesh);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("XFEM_23"), std::string::npos) << r.output;
    r = runComm(kHead +
                    "F = DEFI_FISS_XFEM(MAILLAGE=MA, DEFI_FISS=_F(FORM_FISS='ELLIPSE', DEMI_GRAND_AXE=1., "
                    "DEMI_PETIT_AXE=1., CENTRE=(0., 0., 0.), VECT_X=(1., 0., 0.), VECT_Y=(0., 1., 0.)))\nFIN()\n",
                kMesh);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("is defined on a 3D mesh"), std::string::npos) << r.output;
    r = runComm(kHead +
                    "LNF = FORMULE(VALE='Y-0.45', NOM_PARA=['X', 'Y'])\n"
                    "F = DEFI_FISS_XFEM(MAILLAGE=MA, DEFI_FISS=_F(FONC_LN=LNF, FORM_FISS='DROITE', "
                    "POINT=(0., 0., 0.), DTAN=(1., 0., 0.)))\nFIN()\n",
                kMesh);
    EXPECT_EQ(r.status, 1) << r.output;
    r = runComm(kHead +
                    "LNF = FORMULE(VALE='Y-0.45', NOM_PARA=['X', 'Y'])\n"
                    "F = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='INTERFACE', DEFI_FISS=_F(FONC_LN=LNF))\n"
                    "T = RECU_TABLE(CO=F, NOM_TABLE='FOND_FISS')\nFIN()\n",
                kMesh);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("interface F has no front in the mesh, so no FOND_FISS table"), std::string::npos)
        << r.output;
}

// 3D: sslv318a's RECTANGLE crack on its own 40 x 5 x 40 HEXA8 mesh. The front (FOND_FISS) runs
// from the top face down x = 0.8, round the fillets (r = 0.05), along z = 0.85 and up x = 0.2:
// analytically 0.5 + 2 x 0.1 + pi x 0.05 = 0.857080 long; the fillets' chords (h = 0.025) make
// the polygon 0.3 % shorter.
TEST(XfemCrackCommands, RectangleFrontTable) {
    const auto r = runComm(
        "DEBUT()\n"
        "MA = LIRE_MAILLAGE(FORMAT='MED')\n"
        "F = DEFI_FISS_XFEM(MAILLAGE=MA, DEFI_FISS=_F(FORM_FISS='RECTANGLE', DEMI_GRAND_AXE=0.3, "
        "DEMI_PETIT_AXE=0.15, RAYON_CONGE=0.05, CENTRE=(0.5, 0.5, 1.), VECT_X=(1., 0., 0.), VECT_Y=(0., 0., -1.)))\n"
        "TF = RECU_TABLE(CO=F, NOM_TABLE='FOND_FISS')\n"
        "TN = RECU_TABLE(CO=F, NOM_TABLE='NB_FOND_FISS')\n"
        "TEST_TABLE(TABLE=TN, NOM_PARA='NOMBRE', VALE_CALC_I=1)\n"
        "TEST_TABLE(TABLE=TF, NOM_PARA='ABSC_CURV', TYPE_TEST='MAX', VALE_CALC=0.854443, VALE_REFE=0.857080,\n"
        "           REFERENCE='ANALYTIQUE', PRECISION=0.005)\n"
        "TEST_TABLE(TABLE=TF, NOM_PARA='COOR_Z', TYPE_TEST='MIN', VALE_CALC=0.85, VALE_REFE=0.85,\n"
        "           REFERENCE='ANALYTIQUE', CRITERE='ABSOLU', PRECISION=1e-14)\n"
        "TEST_TABLE(TABLE=TF, NOM_PARA='COOR_Y', TYPE_TEST='MAX', VALE_CALC=0.5, VALE_REFE=0.5,\n"
        "           REFERENCE='ANALYTIQUE', CRITERE='ABSOLU', PRECISION=1e-14)\n"
        "TEST_TABLE(TABLE=TF, NOM_PARA='NUM_PT', TYPE_TEST='MAX', VALE_CALC_I=35)\n"
        "FIN()\n",
        std::string("--mesh '") + MINIASTER_SHARED_DIR + "/astest/sslv318a.mmed'");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("number of crack front points: 35; crack fronts: 1"), std::string::npos) << r.output;
}
