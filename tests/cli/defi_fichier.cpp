// DEFI_FICHIER through the binary (ssnv511a's mesh): ASSOCIER and LIBERER restart a text unit, so
// the tables written after them replace what the unit held; nothing is written for an associated
// unit nothing is printed on; FICHIER and the run's own units are refused.
#include <gtest/gtest.h>

#include "parser_run.hpp"

using namespace ma::test;

namespace {

const std::string kMesh = std::string("--mesh '") + MINIASTER_SHARED_DIR + "/astest/ssnv511a.mmed'";

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

TEST(DefiFichier, AssociateAndFreeRestartTheUnit) {
    const auto r = runComm(R"(DEBUT()
MA = LIRE_MAILLAGE(FORMAT='MED')
MA = DEFI_GROUP(reuse=MA, MAILLAGE=MA, CREA_GROUP_NO=_F(GROUP_MA='SURF', NOM='TOUS'))
MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA='SURF', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
MAT = DEFI_MATERIAU(ELAS=_F(E=100.0E6, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=MA, AFFE=_F(TOUT='OUI', MATER=MAT))
UX = FORMULE(VALE='1.e-3*(X+2.)', NOM_PARA=['X', 'Y'])
CH = AFFE_CHAR_MECA_F(MODELE=MO, DDL_IMPO=_F(GROUP_MA='SURF', DX=UX, DY=UX))
U = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=CH))
T = POST_RELEVE_T(ACTION=_F(INTITULE='MARK', GROUP_NO='TOUS', RESULTAT=U, NOM_CHAM='DEPL', NUME_ORDRE=1,
                            NOM_CMP='DX', OPERATION='EXTRACTION'))
DEFI_FICHIER(UNITE=82)
IMPR_TABLE(TABLE=T, UNITE=82)
IMPR_TABLE(TABLE=T, UNITE=82)
DEFI_FICHIER(UNITE=83)
DEFI_FICHIER(ACTION='LIBERER', UNITE=83)
DEFI_FICHIER(ACTION='LIBERER', UNITE=82)
IMPR_TABLE(TABLE=T, UNITE=82)
FIN()
)",
                           kMesh);
    ASSERT_EQ(r.status, 0) << r.output;
    // Two tables appended, then LIBERER: the third write starts the file afresh.
    EXPECT_EQ(count(r.file("out/fort.82"), "MARK"), 36u) << r.file("out/fort.82");
    EXPECT_FALSE(r.exists("out/fort.83"));
}

TEST(DefiFichier, FileNamesAndTheRunsUnitsAreRefused) {
    const auto s = runComm("DEBUT()\nDEFI_FICHIER(UNITE=82, FICHIER='./x.txt')\nFIN()\n");
    EXPECT_EQ(s.status, 1) << s.output;
    EXPECT_NE(s.file("out/t.mess").find("keyword FICHIER is not supported by miniaster"), std::string::npos)
        << s.file("out/t.mess");
    const auto r = runComm("DEBUT()\nDEFI_FICHIER(UNITE=8)\nFIN()\n");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.file("out/t.mess").find("the message, result and error units of the run cannot be redefined"),
              std::string::npos)
        << r.file("out/t.mess");
}

}  // namespace
