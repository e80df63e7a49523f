#pragma once
// The catalogued commands, one file each: parser/catalog/<NAME>.cpp defines
// catalog_entries::NAME(Catalog&), which adds that one command to the catalog. Keyword blocks that
// several commands share are in parser/catalog/common/. A new command: its file, and its line in
// both lists below (tests/unit/docs_commands.cpp checks files, lists and docs/commands.md agree).
#include <vector>

#include "parser/Catalog.hpp"

namespace ma::catalog_entries {

void AFFE_CHAR_MECA(Catalog&);
void AFFE_CHAR_MECA_F(Catalog&);
void AFFE_MATERIAU(Catalog&);
void AFFE_MODELE(Catalog&);
void CALC_CHAMP(Catalog&);
void CALC_G(Catalog&);
void CALC_TABLE(Catalog&);
void COPIER(Catalog&);
void CREA_CHAMP(Catalog&);
void DEBUT(Catalog&);
void DEFI_CONSTANTE(Catalog&);
void DEFI_CONTACT(Catalog&);
void DEFI_FICHIER(Catalog&);
void DEFI_FISS_XFEM(Catalog&);
void DEFI_FONCTION(Catalog&);
void DEFI_GROUP(Catalog&);
void DEFI_LIST_REEL(Catalog&);
void DEFI_MATERIAU(Catalog&);
void DETRUIRE(Catalog&);
void FIN(Catalog&);
void FORMULE(Catalog&);
void IMPR_CO(Catalog&);
void IMPR_RESU(Catalog&);
void IMPR_TABLE(Catalog&);
void LIRE_MAILLAGE(Catalog&);
void MECA_STATIQUE(Catalog&);
void MODI_MAILLAGE(Catalog&);
void MODI_MODELE_XFEM(Catalog&);
void POST_CHAM_XFEM(Catalog&);
void POST_ERREUR(Catalog&);
void POST_K1_K2_K3(Catalog&);
void POST_MAIL_XFEM(Catalog&);
void POST_RELEVE_T(Catalog&);
void PRE_GIBI(Catalog&);
void RECU_TABLE(Catalog&);
void STAT_NON_LINE(Catalog&);
void TEST_RESU(Catalog&);
void TEST_TABLE(Catalog&);

struct CommandFile {
    const char* command;
    void (*add)(Catalog&);
};

inline const std::vector<CommandFile>& commandFiles() {
    static const std::vector<CommandFile> files{
        {"AFFE_CHAR_MECA", AFFE_CHAR_MECA},
        {"AFFE_CHAR_MECA_F", AFFE_CHAR_MECA_F},
        {"AFFE_MATERIAU", AFFE_MATERIAU},
        {"AFFE_MODELE", AFFE_MODELE},
        {"CALC_CHAMP", CALC_CHAMP},
        {"CALC_G", CALC_G},
        {"CALC_TABLE", CALC_TABLE},
        {"COPIER", COPIER},
        {"CREA_CHAMP", CREA_CHAMP},
        {"DEBUT", DEBUT},
        {"DEFI_CONSTANTE", DEFI_CONSTANTE},
        {"DEFI_CONTACT", DEFI_CONTACT},
        {"DEFI_FICHIER", DEFI_FICHIER},
        {"DEFI_FISS_XFEM", DEFI_FISS_XFEM},
        {"DEFI_FONCTION", DEFI_FONCTION},
        {"DEFI_GROUP", DEFI_GROUP},
        {"DEFI_LIST_REEL", DEFI_LIST_REEL},
        {"DEFI_MATERIAU", DEFI_MATERIAU},
        {"DETRUIRE", DETRUIRE},
        {"FIN", FIN},
        {"FORMULE", FORMULE},
        {"IMPR_CO", IMPR_CO},
        {"IMPR_RESU", IMPR_RESU},
        {"IMPR_TABLE", IMPR_TABLE},
        {"LIRE_MAILLAGE", LIRE_MAILLAGE},
        {"MECA_STATIQUE", MECA_STATIQUE},
        {"MODI_MAILLAGE", MODI_MAILLAGE},
        {"MODI_MODELE_XFEM", MODI_MODELE_XFEM},
        {"POST_CHAM_XFEM", POST_CHAM_XFEM},
        {"POST_ERREUR", POST_ERREUR},
        {"POST_K1_K2_K3", POST_K1_K2_K3},
        {"POST_MAIL_XFEM", POST_MAIL_XFEM},
        {"POST_RELEVE_T", POST_RELEVE_T},
        {"PRE_GIBI", PRE_GIBI},
        {"RECU_TABLE", RECU_TABLE},
        {"STAT_NON_LINE", STAT_NON_LINE},
        {"TEST_RESU", TEST_RESU},
        {"TEST_TABLE", TEST_TABLE},
    };
    return files;
}

}  // namespace ma::catalog_entries
