#pragma once
// The supervisor's alarms (docs/messages.md).
#include <string>

#include "core/Message.hpp"

namespace ma {

inline constexpr Message<> SUPERVIS_1{"SUPERVIS_1", "The command file does not start with DEBUT()."};
inline constexpr Message<> SUPERVIS_2{"SUPERVIS_2", "The command file ended without FIN()."};
inline constexpr Message<> SUPERVIS_3{"SUPERVIS_3", "The command file is not UTF-8: it was read as latin-1."};
// The Python exception's text.
inline constexpr Message<std::string> SUPERVIS_4{
    "SUPERVIS_4",
    "the check of the command file before its run failed (a defect of miniaster; the file runs unchecked): {}"};

inline constexpr MessageText parserMessages[] = {entry(SUPERVIS_1), entry(SUPERVIS_2), entry(SUPERVIS_3),
                                                 entry(SUPERVIS_4)};

}  // namespace ma
