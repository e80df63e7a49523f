// COMPORTEMENT (and its legacy name COMP_ELAS): the constitutive relation and the strain measure.
#include "parser/catalog/common/Blocks.hpp"

namespace ma::catalog_entries {

Keyword comportement(const std::string& name) {
    auto k = fact(name).many().keywords({
        TXM("RELATION")
            .into({"ELAS", "VMIS_ISOT_LINE", "VMIS_ISOT_TRAC", "VMIS_CINE_LINE", "ELAS_VMIS_LINE", "ENDO_ISOT_BETON",
                   "MAZARS", "ELAS_HYPER"})
            .notSupported({"VMIS_ISOT_LINE", "VMIS_ISOT_TRAC", "VMIS_CINE_LINE", "ELAS_VMIS_LINE", "ENDO_ISOT_BETON",
                           "MAZARS", "ELAS_HYPER"})
            .def("ELAS"),
        TXM("DEFORMATION").into({"PETIT", "PETIT_REAC", "GROT_GDEP", "SIMO_MIEHE", "GDEF_LOG"})
            .notSupported({"PETIT_REAC", "GROT_GDEP", "SIMO_MIEHE", "GDEF_LOG"}).def("PETIT"),
        TXM("TOUT").into({"OUI"}), TXM("GROUP_MA").many(), TXM("MAILLE").many(),
        // Local integration of non-linear behaviours: accepted, meaningless for ELAS (said in the .mess).
        R("RESI_INTE_RELA").range(0.0, std::nullopt), I("ITER_INTE_MAXI").range(0.0, std::nullopt),
        I("ITER_INTE_PAS"),
    }).rules({exclus({"TOUT", "GROUP_MA", "MAILLE"})});
    if (name != "COMPORTEMENT") k.storeAs("COMPORTEMENT");
    return k;
}

}  // namespace ma::catalog_entries
