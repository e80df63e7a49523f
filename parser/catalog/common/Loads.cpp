// The keywords of AFFE_CHAR_MECA and AFFE_CHAR_MECA_F: imposed dofs, pressure, volume force.
#include "parser/catalog/common/Blocks.hpp"

namespace ma::catalog_entries {

namespace {
// A load value: a real (AFFE_CHAR_MECA) or a function/formula (AFFE_CHAR_MECA_F).
Keyword value(const std::string& name, bool functions) { return functions ? CO(name, kAnyFunction) : R(name); }

const std::vector<std::string> kDofs{"DX",  "DY",  "DZ",  "H1X", "H1Y", "H1Z", "H2X", "H2Y",
                                     "H2Z", "H3X", "H3Y", "H3Z", "H4X", "H4Y", "H4Z"};

std::vector<Keyword> cellSelection() {
    return {TXM("TOUT").into({"OUI"}), TXM("GROUP_MA").many(), TXM("MAILLE").many()};
}

}  // namespace

std::vector<Keyword> loadKeywords(bool functions) {
    std::vector<Keyword> ddl = join({{TXM("TOUT").into({"OUI"}), TXM("GROUP_MA").many(), TXM("MAILLE").many(),
                                      TXM("GROUP_NO").many(), TXM("NOEUD").many()},
                                     unsupported({"DRX", "DRY", "DRZ", "GRX", "PRES", "PHI", "TEMP", "LIAISON"},
                                                 "only translations DX, DY, DZ and Heaviside dofs H1X..H4Z"),
                                     unsupported({"E1X", "E1Y", "E1Z", "K1", "K2", "K3"},
                                                 "crack-tip enrichment is not modelled"),
                                     unsupported({"LAGS_C", "LAGS_F1", "LAGS_F2"}, "contact unknowns cannot be imposed")});
    for (const auto& d : kDofs) ddl.push_back(value(d, functions));
    return join({
        {CO("MODELE", {kModel}).mandatory(),
         fact("DDL_IMPO").many().keywords(ddl).rules(
             {auMoinsUn({"TOUT", "GROUP_MA", "MAILLE", "GROUP_NO", "NOEUD"}), auMoinsUn(kDofs)}),
         fact("PRES_REP").many().keywords(join({cellSelection(), {value("PRES", functions)},
                                                {unsupported("CISA_2D", "tangential surface loads")},
                                                {unsupported("FISSURE", "pressure on X-FEM crack lips")}}))
             .rules({unParmi({"TOUT", "GROUP_MA", "MAILLE"}), auMoinsUn({"PRES"})}),
         fact("FORCE_INTERNE").many().keywords(join({cellSelection(), {value("FX", functions), value("FY", functions),
                                                                      value("FZ", functions)}}))
             .rules({unParmi({"TOUT", "GROUP_MA", "MAILLE"}), auMoinsUn({"FX", "FY", "FZ"})}),
         yesNo("DOUBLE_LAGRANGE").def("OUI"), yesNo("VERI_NORM").def("OUI"), info()},
        unsupported({"FORCE_NODALE", "FORCE_FACE", "FORCE_ARETE", "FORCE_CONTOUR", "FORCE_POUTRE", "FORCE_COQUE",
                     "PESANTEUR", "ROTATION", "LIAISON_DDL", "LIAISON_OBLIQUE", "LIAISON_GROUP", "LIAISON_SOLIDE",
                     "LIAISON_UNIF", "LIAISON_MAIL", "LIAISON_ELEM", "LIAISON_CHAMNO", "LIAISON_RBE3", "FACE_IMPO",
                     "ARETE_IMPO", "EPSI_INIT", "PRE_EPSI", "PRE_SIGM", "RELA_CINE_BP", "DDL_POUTRE", "EVOL_CHAR",
                     "ONDE_PLANE", "FLUX_THM_REP", "VITE_FACE", "IMPE_FACE", "LIAISON_COQUE", "FORCE_TUYAU",
                     "FORCE_ELEC", "INTE_ELEC", "CHAMNO_IMPO", "VECT_ASSE", "SIGM_INTERNE", "CARA_ELEM"},
                    "miniaster loads are DDL_IMPO, PRES_REP and FORCE_INTERNE"),
    });
}

}  // namespace ma::catalog_entries
