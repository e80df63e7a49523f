// IMPR_RESU FORMAT='RESULTAT' of nodal fields: code_aster's listing (titles, header, values 6 to a
// line in FORMAT_R, VALE_MAX / VALE_MIN), on a classical D_PLAN square whose displacement is a
// closed form (uniform stresses SIXX = -1 MPa, SIYY = -2 MPa, E = 2e11, nu = 0.3, plane strain:
// eps_xx = -6.5e-7, eps_yy = -7.15e-6, supports at x = -5 and y = -5).
#include <gtest/gtest.h>

#include "med_test_support.hpp"
#include "parser_run.hpp"

namespace {

const char* kListing = R"(DEBUT()
MA = LIRE_MAILLAGE(FORMAT='MED')
MA = DEFI_GROUP(reuse=MA, MAILLAGE=MA, CREA_GROUP_NO=_F(GROUP_MA='LB'))
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA=('SURF', 'LH', 'LD'), PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
ACIER = DEFI_MATERIAU(ELAS=_F(E=2.E11, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=ACIER))
CH = AFFE_CHAR_MECA(MODELE=MO, PRES_REP=(_F(GROUP_MA='LH', PRES=2.E6), _F(GROUP_MA='LD', PRES=1.E6)),
                    DDL_IMPO=(_F(GROUP_MA='LB', DY=0.), _F(GROUP_MA='LG', DX=0.)))
RES = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH))
IMPR_RESU(FORMAT='RESULTAT', RESU=_F(RESULTAT=RES, NOM_CHAM='DEPL', GROUP_NO='LB', IMPR_COOR='OUI', FORMAT_R='1PE12.5'))
IMPR_RESU(FORMAT='RESULTAT', RESU=_F(RESULTAT=RES, NOM_CHAM='DEPL', NOM_CMP='DY', VALE_MAX='OUI', VALE_MIN='OUI'))
IMPR_RESU(FORMAT='RESULTAT', UNITE=30, RESU=_F(RESULTAT=RES))
FIN()
)";

TEST(ImprResuListing, NodalValuesAsCodeAsterListsThem) {
    const auto dir = ma::test::freshDir();
    ma::test::writeText(dir / "t.comm", kListing);
    const auto r = ma::test::runMiniaster(dir, "t.comm", "--mesh '" + ma::test::astest("ssnv511a.mmed") + "'");
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string resu = r.file("out/t.resu");
    // The order's mark, the subtitle, the header (A12 cells of E12.5) and a node of LB at x = 5:
    // DX = 10 * eps_xx.
    EXPECT_NE(resu.find("\n ======>\n\n ------>\n CHAMP AUX NOEUDS DE NOM SYMBOLIQUE  DEPL\n NUMERO D'ORDRE: 1 "
                        "INST:  0.00000E+00\n NOEUD        X            Y            DX           DY      \n"),
              std::string::npos)
        << resu;
    EXPECT_NE(resu.find(" N2        5.00000E+00 -5.00000E+00 -6.50000E-06  0.00000E+00\n"), std::string::npos) << resu;
    // VALE_MAX / VALE_MIN: the extremes only; DY = 0 on the six nodes of LB, -7.15e-5 on top.
    EXPECT_NE(resu.find(" LA VALEUR MAXIMALE DE DY       EST  0.00000000000000E+00 EN    6 NOEUD(S) : N1      \n"),
              std::string::npos)
        << resu;
    EXPECT_NE(resu.find(" LA VALEUR MINIMALE DE DY       EST -7.1500000000000"), std::string::npos) << resu;
    // Without NOM_CHAM: DEPL on unit 30, SIEF_ELGA left out with an alarm saying so.
    const std::string unit30 = r.file("out/fort.30");
    EXPECT_NE(unit30.find(" NOEUD                 DX                    DY      \n"), std::string::npos) << unit30;
    EXPECT_EQ(unit30.find("SIEF_ELGA"), std::string::npos);
    EXPECT_NE(r.file("out/t.mess").find("fields SIEF_ELGA of result RES at NUME_ORDRE 1 are at integration points"),
              std::string::npos);
}

// Keywords of the listing given with another format are refused before the first command.
TEST(ImprResuListing, ListingKeywordsWithMedAreRefusedBeforeTheSolve) {
    const auto dir = ma::test::freshDir();
    std::string comm = kListing;
    comm.insert(comm.rfind("FIN()"), "IMPR_RESU(FORMAT='MED', RESU=_F(RESULTAT=RES, GROUP_NO='LB', VALE_MAX='OUI'))\n");
    ma::test::writeText(dir / "t.comm", comm);
    const auto r = ma::test::runMiniaster(dir, "t.comm", "--mesh '" + ma::test::astest("ssnv511a.mmed") + "'");
    EXPECT_EQ(r.status, 1) << r.output;
    const std::string mess = r.file("out/t.mess");
    EXPECT_NE(mess.find("keyword RESU[1]/GROUP_NO is not supported by miniaster with FORMAT='MED' (only with "
                        "FORMAT='RESULTAT')"),
              std::string::npos)
        << mess;
    EXPECT_NE(mess.find("keyword RESU[1]/VALE_MAX is not supported by miniaster with FORMAT='MED'"), std::string::npos);
    EXPECT_EQ(mess.find("MECA_STATIQUE("), std::string::npos);  // nothing ran
}

}  // namespace
