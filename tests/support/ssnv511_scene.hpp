#pragma once
// The .comm preamble the binary-driven tests share: the ssnv511 junction scene on the mesh of unit
// 20 (given with --mesh). DEBUT, LIRE_MAILLAGE, AFFE_MODELE on `groups`, the level sets LN1
// (`ln1`, default y) and LN2 (x), and the interfaces <prefix>1 (LN1) and, when `interfaces` is 3,
// <prefix>2 and <prefix>3 (LN2) branching on <prefix>1 at (0, 5) and (0, -5).
#include <string>

namespace ma::test {

struct Ssnv511Scene {
    std::string groups = "'SURF'";  // GROUP_MA of AFFE_MODELE, as written in Python
    bool threeD = false;            // MODELISATION='3D', level sets of X, Y, Z, junction points at z = 0
    std::string ln1 = "Y";          // level set of the first interface
    std::string prefix = "F";       // names of the interfaces
    int interfaces = 3;             // 1: the first only
};

inline std::string ssnv511Preamble(const Ssnv511Scene& s = {}) {
    const std::string para = s.threeD ? "['X', 'Y', 'Z']" : "['X', 'Y']";
    const std::string z = s.threeD ? ", 0" : "";
    const std::string f = s.prefix;
    std::string comm =
        "DEBUT()\n"
        "MA = LIRE_MAILLAGE(FORMAT='MED')\n"
        "MO = AFFE_MODELE(MAILLAGE=MA, AFFE=_F(GROUP_MA=" +
        s.groups + ", PHENOMENE='MECANIQUE', MODELISATION='" + (s.threeD ? "3D" : "D_PLAN") +
        "'))\n"
        "LN1 = FORMULE(VALE='" +
        s.ln1 + "', NOM_PARA=" + para +
        ")\n"
        "LN2 = FORMULE(VALE='X', NOM_PARA=" +
        para + ")\n" + f +
        "1 = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='INTERFACE', DEFI_FISS=_F(FONC_LN=LN1))\n";
    if (s.interfaces == 3)
        for (const char* branch : {"2", "3"})
            comm += f + branch +
                    " = DEFI_FISS_XFEM(MAILLAGE=MA, TYPE_DISCONTINUITE='INTERFACE', DEFI_FISS=_F(FONC_LN=LN2), "
                    "JONCTION=_F(FISSURE=" +
                    f + "1, POINT=(0, " + (branch[0] == '2' ? "5" : "-5") + z + ")))\n";
    return comm;
}

}  // namespace ma::test
