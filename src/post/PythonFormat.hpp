#pragma once
// Number -> text exactly as code_aster's Python layer prints it (commands_spec.md §1.5.5, §4.2).
// TEST_TABLE lines use Python 3's repr of a float (shortest round-trip digits); IMPR_TABLE uses
// C/Python '%12.5E'. Reproducing these byte for byte is what lets users diff our .resu with
// code_aster's.
#include <cstddef>
#include <string>

namespace ma {

// Python 3 `repr(x)` / `'%s' % x`: shortest digits that read back as x; fixed notation when
// 1e-4 <= |x| < 1e16 (always with a fractional part: '1397500.0'), scientific otherwise with
// a signed exponent of at least two digits ('1e-05', '1e+16'); 'inf', 'nan'.
std::string pythonRepr(double x);

// code_aster's TEST_TABLE rendering S(x): pythonRepr with every 'e' turned into 'E'.
std::string testValueText(double x);

// C printf of one double with a format such as "%12.5E" or "%13.6e" (the formats code_aster's
// printers use; Python's %-operator follows C for these).
std::string printfReal(const char* format, double x);

// Python's str.ljust(width) and str.rstrip(' '): the padding of code_aster's printed columns.
std::string ljust(const std::string& s, size_t width);
std::string rstrip(std::string s);

}  // namespace ma
