// The header lines of TEST_TABLE / TEST_RESU (post/TestHeader), as code_aster's tresu_* routines
// build them: a 21-column start, then 17-column fields, values cut to 16 characters.
#include <gtest/gtest.h>

#include "post/TestHeader.hpp"

using ma::TestHeader;

TEST(TestHeader, FieldsOfSeventeenColumns) {
    TestHeader h("RESULTAT", "RES_XFEM");
    h.add("NUME_ORDRE", "1");
    h.add("NOM_CHAM", "DEPL");
    h.add("TYPE_TEST", "SOMM_ABS");
    h.add("NOM_CMP", "DY");
    EXPECT_EQ(h.text(),
              " ---- RESULTAT         NUME_ORDRE       NOM_CHAM         TYPE_TEST        NOM_CMP\n"
              "      RES_XFEM         1                DEPL             SOMM_ABS         DY\n");
    EXPECT_EQ(h.describe(), "RESULTAT=RES_XFEM NUME_ORDRE=1 NOM_CHAM=DEPL TYPE_TEST=SOMM_ABS NOM_CMP=DY");
}

TEST(TestHeader, LongValuesAreCutAndTrchelHasNoLeadingBlank) {
    TestHeader h("CHAM_ELEM", "SI");
    h.add("GROUP_MA", "A_GROUP_NAME_OF_24_CHARS");
    h.add("POINT", "3");
    EXPECT_EQ(h.text(false),
              "---- CHAM_ELEM        GROUP_MA         POINT\n"
              "      SI               A_GROUP_NAME_OF_ 3\n");
    EXPECT_EQ(h.describe(), "CHAM_GD=SI GROUP_MA=A_GROUP_NAME_OF_24_CHARS POINT=3");
}

TEST(TestHeader, TableNamesArePaddedToEight) {
    TestHeader h("TABLE", "T");
    h.add("NOM_PARA", "DX");
    EXPECT_EQ(h.text(), " ---- TABLE            NOM_PARA\n      T                DX\n");
}
