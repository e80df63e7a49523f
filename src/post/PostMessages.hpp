#pragma once
// Post-processing's alarms: TEST_TABLE/TEST_RESU, IMPR_TABLE, IMPR_RESU (MED and GMSH) (docs/messages.md).
#include <cstddef>
#include <string>

#include "core/Message.hpp"

namespace ma {

inline constexpr Message<> TEST0_11{
    "TEST0_11",
    "A non-regression test with a null VALE_CALC is meaningless: the check is skipped.\n"
    "Give ORDRE_GRANDEUR (with CRITERE='ABSOLU') or a reference value."};
inline constexpr Message<> TEST0_12{
    "TEST0_12",
    "The non-regression value (VALE_CALC) is zero or below the machine precision: the check is skipped (SKIP).\n"
    "Give ORDRE_GRANDEUR with CRITERE='ABSOLU' to make it effective."};
// TEST_RESU with TYPE_TEST: the occurrence's keyword path, the place keywords it ignores.
inline constexpr Message<std::string, std::string> CALCULEL6_96{
    "CALCULEL6_96", "{}: TYPE_TEST tests a quantity computed over the whole field; {} is not taken into account."};

// IMPR_TABLE: the missing columns, the table.
inline constexpr Message<std::string, std::string> TABLE0_7{
    "TABLE0_7", "IMPR_TABLE: columns {} are not in table {}; they are not printed."};

// IMPR_RESU, the occurrence's keyword path first. FORMAT='MED': the field, NUME_ORDRE, the result.
inline constexpr Message<std::string, std::string, int, std::string> RESULT1_6{
    "RESULT1_6", "{}: field {} does not exist at NUME_ORDRE {} of result {}; it is not printed"};
// FORMAT='GMSH': TYPE_CHAM.
inline constexpr Message<std::string, std::string> PREPOST6_35{
    "PREPOST6_35", "{}: a field at Gauss points is written as scalar views (one per component), not as TYPE_CHAM='{}'"};
// FORMAT='RESULTAT' without NOM_CHAM: the fields at integration points, the result, NUME_ORDRE.
inline constexpr Message<std::string, std::string, std::string, int> PREPOST_LISTING{
    "PREPOST_LISTING",
    "{}: fields {} of result {} at NUME_ORDRE {} are at integration points: miniaster's FORMAT='RESULTAT' lists "
    "nodal fields only, they are not printed"};
// The field, the result.
inline constexpr Message<std::string, std::string, std::string> PREPOST2_59{
    "PREPOST2_59", "{}: no field {} in result {} at the selected steps; nothing written for it"};
// The view, the count of cells, their type.
inline constexpr Message<std::string, std::string, size_t, std::string> ALGELINE_64{
    "ALGELINE_64",
    "{}: view {}: {} cells of type {} are not written (code_aster's GMSH output does not split this type into "
    "linear cells)"};

inline constexpr MessageText postMessages[] = {
    entry(TEST0_11),    entry(TEST0_12),        entry(CALCULEL6_96), entry(TABLE0_7),    entry(RESULT1_6),
    entry(PREPOST6_35), entry(PREPOST_LISTING), entry(PREPOST2_59),  entry(ALGELINE_64),
};

}  // namespace ma
