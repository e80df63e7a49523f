#pragma once
// code_aster concept type names used by the catalog (Concept::typeName() of the C++ classes), and
// the one-line keywords many commands share.
#include <string>
#include <vector>

#include "parser/Catalog.hpp"

namespace ma::cata::types {

inline const std::string kMesh = "maillage_sdaster";
inline const std::string kModel = "modele_sdaster";
inline const std::string kMaterial = "mater_sdaster";
inline const std::string kMaterialField = "cham_mater";
inline const std::string kMechanicalLoad = "char_meca";
inline const std::string kContact = "char_contact";
inline const std::string kStaticResult = "evol_elas";
inline const std::string kNonlinearResult = "evol_noli";
inline const std::string kTable = "table_sdaster";
inline const std::string kFunction = "fonction_sdaster";
inline const std::string kFormula = "formule";
inline const std::string kRealList = "listr8_sdaster";
inline const std::string kCrack = "fiss_xfem";
inline const std::string kNodalField = "cham_no_sdaster";
inline const std::string kGaussField = "cham_elem";

// A function of named parameters: DEFI_FONCTION or FORMULE.
inline const std::vector<std::string> kAnyFunction{kFunction, kFormula};
inline const std::vector<std::string> kAnyResult{kStaticResult, kNonlinearResult};
inline const std::vector<std::string> kAnyField{kNodalField, kGaussField};
// Any concept (IMPR_CO, DETRUIRE).
inline const std::vector<std::string> kAnyConcept{kMesh,           kModel,          kMaterial, kMaterialField,
                                                  kMechanicalLoad, kContact,        kStaticResult,
                                                  kNonlinearResult, kTable,         kFunction, kFormula,
                                                  kRealList,       kCrack,          kNodalField, kGaussField};

// Keywords shared by many commands.
inline Keyword info(std::vector<long long> levels = {1, 2}) { return I("INFO").intoInt(std::move(levels)).def(1); }
inline Keyword yesNo(std::string name) { return TXM(std::move(name)).into({"OUI", "NON"}); }
inline Keyword titre() { return TXM("TITRE").many(); }
inline Keyword critere() { return TXM("CRITERE").into({"RELATIF", "ABSOLU"}).def("RELATIF"); }

}  // namespace ma::cata::types

// The catalog files are written in the builders' vocabulary (parser/Catalog.hpp, the types above).
namespace ma::catalog_entries {
using namespace cata;
using namespace cata::types;
}  // namespace ma::catalog_entries
