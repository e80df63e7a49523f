#pragma once
// The MED reader's and writer's alarms (docs/messages.md).
#include <string>

#include "core/Message.hpp"

namespace ma {

// The name in the file, the file, the name kept.
inline constexpr Message<std::string, std::string, std::string> MED_7{
    "MED_7", "the group name '{}' of MED file '{}' is longer than 24 characters; it is renamed '{}'"};
// The field, the count of elements, their types (separated by spaces).
inline constexpr Message<std::string, int, std::string> MED_ELGA{
    "MED_ELGA",
    "field {}: {} elements of types {} have no reference element in miniaster; their values are not printed"};
inline constexpr Message<std::string> MED_NO_VALUE{"MED_NO_VALUE",
                                                   "field {} has no value on any node: it is not printed"};

inline constexpr MessageText medMessages[] = {entry(MED_7), entry(MED_ELGA), entry(MED_NO_VALUE)};

}  // namespace ma
