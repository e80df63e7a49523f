// The keywords of AFFE_CHAR_MECA and AFFE_CHAR_MECA_F: imposed dofs and linear relations, pressure
// (on boundaries and on the lips of X-FEM interfaces), surface, edge and volume forces.
#include "parser/catalog/common/Blocks.hpp"

namespace ma::catalog_entries {

namespace {
// A load value: a real (AFFE_CHAR_MECA) or a function/formula (AFFE_CHAR_MECA_F).
Keyword value(const std::string& name, bool functions) { return functions ? CO(name, kAnyFunction) : R(name); }

const std::vector<std::string> kDofs{"DX",  "DY",  "DZ",  "H1X", "H1Y", "H1Z", "H2X", "H2Y",
                                     "H2Z", "H3X", "H3Y", "H3Z", "H4X", "H4Y", "H4Z", "K1",  "K2",  "K3"};

std::vector<Keyword> cellSelection() {
    return {TXM("TOUT").into({"OUI"}), TXM("GROUP_MA").many(), TXM("MAILLE").many()};
}

std::vector<Keyword> exclusions() {
    return {TXM("SANS_GROUP_MA").many(), TXM("SANS_MAILLE").many(), TXM("SANS_GROUP_NO").many(),
            TXM("SANS_NOEUD").many()};
}

// FORCE_CONTOUR, FORCE_FACE, FORCE_ARETE: a force per unit length or area on cells.
Keyword surfaceForce(const std::string& name, bool functions, bool moments) {
    std::vector<Keyword> k{TXM("GROUP_MA").many(), TXM("MAILLE").many(), value("FX", functions),
                           value("FY", functions), value("FZ", functions)};
    std::vector<std::string> any{"FX", "FY", "FZ"};
    if (moments) {
        k = join({k, unsupported({"MX", "MY", "MZ"}, "moments act on shells and beams, not on 2D/3D continua")});
        any = {"FX", "FY", "FZ", "MX", "MY", "MZ"};
    }
    return fact(name).many().keywords(k).rules({auMoinsUn({"GROUP_MA", "MAILLE"}), auMoinsUn(any)});
}

// FACE_IMPO (faces, or edges of a plane model) and ARETE_IMPO (edges of a 3D model).
Keyword imposedOnCells(const std::string& name, bool functions, bool face) {
    std::vector<Keyword> k = join({{TXM("GROUP_MA").many(), TXM("MAILLE").many()}, exclusions(),
                                   {value("DX", functions), value("DY", functions), value("DZ", functions),
                                    value("DTAN", functions)},
                                   unsupported({"PRES", "PHI", "TEMP", "PRE1", "PRE2"},
                                               "only the displacements DX, DY, DZ, DNOR, DTAN")});
    std::vector<Rule> rules{unParmi({"GROUP_MA", "MAILLE"}), exclus({"DTAN", "DX"}), exclus({"DTAN", "DY"}),
                            exclus({"DTAN", "DZ"})};
    if (face) {
        k = join({k, {value("DNOR", functions)},
                  unsupported({"DRX", "DRY", "DRZ", "GRX"}, "only the displacements DX, DY, DZ, DNOR, DTAN")});
        rules.push_back(auMoinsUn({"DX", "DY", "DZ", "DRX", "DRY", "DRZ", "GRX", "PRES", "PHI", "TEMP", "PRE1",
                                   "PRE2", "DNOR", "DTAN"}));
        for (const char* d : {"DX", "DY", "DZ", "DRX", "DRY", "DRZ"}) rules.push_back(exclus({"DNOR", d}));
    } else {
        rules.push_back(auMoinsUn({"DX", "DY", "DZ", "DTAN", "PRES", "PHI", "TEMP", "PRE1", "PRE2"}));
    }
    return fact(name).many().keywords(k).rules(rules);
}

Keyword liaisonDdl(bool functions) {
    std::vector<Keyword> k{TXM("GROUP_NO").many(), TXM("NOEUD").many(), TXM("DDL").many().mandatory(),
                           value("COEF_IMPO", functions).mandatory()};
    std::vector<Rule> rules{unParmi({"GROUP_NO", "NOEUD"})};
    if (functions) {
        k.push_back(R("COEF_MULT").many());
        k.push_back(unsupported("COEF_MULT_FONC", "coefficients that vary with the instant"));
        rules.push_back(unParmi({"COEF_MULT", "COEF_MULT_FONC"}));
    } else {
        k.push_back(R("COEF_MULT").many().mandatory());
    }
    return fact("LIAISON_DDL").many().keywords(k).rules(rules);
}

Keyword liaisonGroup(bool functions) {
    std::vector<Keyword> k{TXM("GROUP_MA_1").many(), TXM("MAILLE_1").many(), TXM("GROUP_NO_1").many(),
                           TXM("NOEUD_1").many(), TXM("GROUP_MA_2").many(), TXM("MAILLE_2").many(),
                           TXM("GROUP_NO_2").many(), TXM("NOEUD_2").many(), TXM("SANS_NOEUD").many(),
                           TXM("SANS_GROUP_NO").many(), TXM("DDL_1").many().mandatory(),
                           R("COEF_MULT_1").many().mandatory(), TXM("DDL_2").many().mandatory(),
                           R("COEF_MULT_2").many().mandatory(), value("COEF_IMPO", functions).mandatory(),
                           R("TRAN").many().max(3), unsupported("CENTRE", "rotated pairings (ANGL_NAUT) are not modelled"),
                           unsupported("ANGL_NAUT", "rotated pairings are not modelled (TRAN is)")};
    std::vector<Rule> rules{unParmi({"GROUP_MA_1", "MAILLE_1", "GROUP_NO_1", "NOEUD_1"}),
                            unParmi({"GROUP_MA_2", "MAILLE_2", "GROUP_NO_2", "NOEUD_2"}),
                            exclus({"SANS_NOEUD", "SANS_GROUP_NO"})};
    for (const auto& [a, b] : std::vector<std::pair<const char*, const char*>>{
             {"GROUP_MA_1", "GROUP_NO_2"}, {"GROUP_MA_1", "NOEUD_2"}, {"GROUP_NO_1", "GROUP_MA_2"},
             {"GROUP_NO_1", "MAILLE_2"}, {"MAILLE_1", "GROUP_NO_2"}, {"MAILLE_1", "NOEUD_2"},
             {"NOEUD_1", "GROUP_MA_2"}, {"NOEUD_1", "MAILLE_2"}})
        rules.push_back(exclus({a, b}));
    return fact("LIAISON_GROUP").many().keywords(k).rules(rules);
}

}  // namespace

std::vector<Keyword> loadKeywords(bool functions) {
    std::vector<Keyword> ddl = join({{TXM("TOUT").into({"OUI"}), TXM("GROUP_MA").many(), TXM("MAILLE").many(),
                                      TXM("GROUP_NO").many(), TXM("NOEUD").many()},
                                     unsupported({"DRX", "DRY", "DRZ", "GRX", "PRES", "PHI", "TEMP", "LIAISON"},
                                                 "only translations DX, DY, DZ and Heaviside dofs H1X..H4Z"),
                                     unsupported({"E1X", "E1Y", "E1Z"},
                                                 "the scalar crack-tip enrichment of code_aster 11 is not modelled "
                                                 "(its vector form K1, K2, K3 is)"),
                                     unsupported({"LAGS_C", "LAGS_F1", "LAGS_F2"}, "contact unknowns cannot be imposed")});
    for (const auto& d : kDofs) ddl.push_back(value(d, functions));
    return join({
        {CO("MODELE", {kModel}).mandatory(),
         fact("DDL_IMPO").many().keywords(ddl).rules(
             {auMoinsUn({"TOUT", "GROUP_MA", "MAILLE", "GROUP_NO", "NOEUD"}), auMoinsUn(kDofs)}),
         fact("PRES_REP").many().keywords(join({cellSelection(), {CO("FISSURE", {kCrack}).many()},
                                                {value("PRES", functions), value("CISA_2D", functions)}}))
             .rules({auMoinsUn({"TOUT", "GROUP_MA", "MAILLE", "FISSURE"}),
                     presentAbsent({"TOUT", "GROUP_MA", "MAILLE", "FISSURE"}),
                     auMoinsUn({"PRES", "CISA_2D"})}),
         imposedOnCells("FACE_IMPO", functions, true), imposedOnCells("ARETE_IMPO", functions, false),
         liaisonDdl(functions), liaisonGroup(functions), surfaceForce("FORCE_CONTOUR", functions, false),
         surfaceForce("FORCE_FACE", functions, false), surfaceForce("FORCE_ARETE", functions, true),
         fact("FORCE_INTERNE").many().keywords(join({cellSelection(), {value("FX", functions), value("FY", functions),
                                                                      value("FZ", functions)}}))
             .rules({unParmi({"TOUT", "GROUP_MA", "MAILLE"}), auMoinsUn({"FX", "FY", "FZ"})}),
         yesNo("DOUBLE_LAGRANGE").def("OUI"), yesNo("VERI_NORM").def("OUI"), info()},
        unsupported({"FORCE_NODALE", "FORCE_POUTRE", "FORCE_COQUE", "PESANTEUR", "ROTATION", "LIAISON_OBLIQUE",
                     "LIAISON_SOLIDE", "LIAISON_UNIF", "LIAISON_MAIL", "LIAISON_ELEM", "LIAISON_CHAMNO",
                     "LIAISON_RBE3", "EPSI_INIT", "PRE_EPSI", "PRE_SIGM", "RELA_CINE_BP", "DDL_POUTRE", "EVOL_CHAR",
                     "ONDE_PLANE", "FLUX_THM_REP", "VITE_FACE", "IMPE_FACE", "LIAISON_COQUE", "FORCE_TUYAU",
                     "FORCE_ELEC", "INTE_ELEC", "CHAMNO_IMPO", "VECT_ASSE", "SIGM_INTERNE", "CARA_ELEM"},
                    "miniaster loads are DDL_IMPO, FACE_IMPO, ARETE_IMPO, LIAISON_DDL, LIAISON_GROUP, PRES_REP, "
                    "FORCE_CONTOUR, FORCE_FACE, FORCE_ARETE and FORCE_INTERNE"),
    });
}

}  // namespace ma::catalog_entries
