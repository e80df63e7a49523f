// POST_ERREUR: error norms against an exact solution.
#include "parser/catalog/common/Types.hpp"

namespace ma::catalog_entries {

namespace {
std::vector<Keyword> formulaList(std::vector<std::string> names) {
    std::vector<Keyword> out;
    for (auto& n : names) out.push_back(CO(std::move(n), kAnyFunction).many());
    return out;
}
}  // namespace

void POST_ERREUR(Catalog& c) {
    c.add(cmd("POST_ERREUR", kTable)
              .keywords({
                  TXM("OPTION").mandatory().into({"DEPL_RELA", "ENER_RELA", "LAGR_RELA"}).notSupported({"LAGR_RELA"}),
                  CO("MODELE", {kModel}).mandatory(), TXM("GROUP_MA").many().mandatory(),
                  bloc(when("OPTION", {"DEPL_RELA"}),
                       join({{CO("CHAM_GD", {kNodalField}).mandatory(), CO("CHAM_MATER", {kMaterialField})},
                             formulaList({"DX", "DY", "DZ"})})),
                  bloc(when("OPTION", {"ENER_RELA"}),
                       join({{CO("CHAM_GD", {kGaussField}).mandatory(), CO("CHAM_MATER", {kMaterialField}).mandatory(),
                              TXM("DEFORMATION").mandatory().into({"PETIT"})},
                             formulaList({"SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ"})})),
                  bloc(when("OPTION", {"LAGR_RELA"}),
                       join({{CO("CHAM_GD", {kNodalField}).mandatory()}, formulaList({"LAGS_C"})})),
              }));
}

}  // namespace ma::catalog_entries
