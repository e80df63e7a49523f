#include "core/FortranFormat.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "core/Error.hpp"

namespace ma {
namespace {

std::string trimmed(const std::string& s) {
    const size_t a = s.find_first_not_of(" \t");
    if (a == std::string::npos) return "";
    return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

}  // namespace

std::string fortranToPrintf(const std::string& fortranFormat) {
    const std::string reason = fortranFormatProblem(fortranFormat);
    if (!reason.empty()) throw UserError(fmt::format("FORMAT_R '{}' {}", fortranFormat, reason));
    std::string f = trimmed(fortranFormat);
    size_t at = 0;
    std::string prefix;
    // A scale factor nP: code_aster prints n blanks before the value (fmtF2PY), its mantissa
    // stays d.ddd as Python prints it.
    if (const size_t p = f.find_first_of("pP"); p != std::string::npos) {
        prefix.assign(size_t(std::stoi(f.substr(0, p))), ' ');
        at = p + 1;
    }
    char letter = char(std::toupper(static_cast<unsigned char>(f[at])));
    if (letter == 'D') letter = 'E';
    return fmt::format("{}%{}{}", prefix, f.substr(at + 1), letter == 'F' ? 'f' : letter);
}

std::string fortranFormatProblem(const std::string& fortranFormat) {
    const std::string f = trimmed(fortranFormat);
    size_t at = 0;
    if (const size_t p = f.find_first_of("pP"); p != std::string::npos) {
        if (p == 0 || p > 2 || f.substr(0, p).find_first_not_of("0123456789") != std::string::npos)
            return "has a scale factor that is not nP with n a small integer (e.g. '1PE12.5')";
        at = p + 1;
    }
    if (at >= f.size() || std::string("EeDdFfGg").find(f[at]) == std::string::npos)
        return "is not a Fortran real format such as 'E12.5', '1PE12.5', 'D15.8', 'F10.3' or 'G14.7'";
    const std::string spec = f.substr(at + 1);
    const bool valid = !spec.empty() && spec.find_first_not_of("0123456789.") == std::string::npos &&
                       std::count(spec.begin(), spec.end(), '.') <= 1 &&
                       std::isdigit(static_cast<unsigned char>(spec[0])) && spec.size() <= 6;
    if (!valid) return "is not a Fortran real format such as 'E12.5', '1PE12.5', 'D15.8', 'F10.3' or 'G14.7'";
    return "";
}

}  // namespace ma
