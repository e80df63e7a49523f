#include "post/PythonFormat.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace ma {

std::string pythonRepr(double x) {
    if (std::isnan(x)) return "nan";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    if (x == 0.0) return std::signbit(x) ? "-0.0" : "0.0";

    // Shortest round-trip digits in scientific form: "-d.ddde-XX".
    char buf[64];
    auto res = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::scientific);
    std::string sci(buf, res.ptr);
    const bool negative = sci[0] == '-';
    if (negative) sci.erase(0, 1);
    const size_t epos = sci.find('e');
    const int exponent = std::atoi(sci.c_str() + epos + 1);
    std::string digits;  // significant digits without the point
    for (size_t i = 0; i < epos; ++i)
        if (sci[i] != '.') digits += sci[i];

    std::string out = negative ? "-" : "";
    // Python's float_repr_style 'short': scientific when the decimal point position
    // (exponent + 1) is below -3 or above 16.
    if (exponent < -4 || exponent >= 16) {
        out += digits[0];
        if (digits.size() > 1) {
            out += '.';
            out.append(digits, 1);
        }
        char e[16];
        std::snprintf(e, sizeof e, "e%c%02d", exponent < 0 ? '-' : '+', std::abs(exponent));
        out += e;
    } else if (exponent >= 0) {
        const size_t intDigits = size_t(exponent) + 1;
        if (digits.size() <= intDigits) {
            out += digits;
            out.append(intDigits - digits.size(), '0');
            out += ".0";
        } else {
            out.append(digits, 0, intDigits);
            out += '.';
            out.append(digits, intDigits);
        }
    } else {
        out += "0.";
        out.append(size_t(-exponent - 1), '0');
        out += digits;
    }
    return out;
}

std::string testValueText(double x) {
    std::string s = pythonRepr(x);
    for (char& c : s)
        if (c == 'e') c = 'E';
    return s;
}

std::string printfReal(const char* format, double x) {
    char buf[128];
    std::snprintf(buf, sizeof buf, format, x);
    return buf;
}

std::string ljust(const std::string& s, size_t width) {
    return s.size() >= width ? s : s + std::string(width - s.size(), ' ');
}

std::string rstrip(std::string s) {
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
}

}  // namespace ma
