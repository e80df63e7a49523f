#include "mesh/AsterMeshLexer.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/Error.hpp"

namespace ma {

namespace {
bool isSeparator(char c) { return c == ' ' || c == '\t' || c == '\r' || std::strchr("=():;,&*/!", c) != nullptr; }
bool isLetter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool isBlankAt(const std::string& s, size_t i) { return i >= s.size() || s[i] == ' ' || s[i] == '\t' || s[i] == '\r'; }
// First column at or after `col` that is not a separator (a lone sign followed by a blank is one).
size_t skipSeparators(const std::string& s, size_t col, size_t limit) {
    while (col < limit) {
        const bool loneSign = (s[col] == '+' || s[col] == '-') && isBlankAt(s, col + 1);
        if (!isSeparator(s[col]) && !loneSign) break;
        ++col;
    }
    return col;
}
}  // namespace

AsterLexer::AsterLexer(std::istream& in, std::string source) : source_(std::move(source)) {
    for (std::string line; std::getline(in, line);) lines_.push_back(std::move(line));
}

void AsterLexer::fail(int line, const std::string& what) const {
    throw UserError("mesh file '" + source_ + "', line " + std::to_string(line) + ": " + what);
}

const AsterToken& AsterLexer::peek() {
    if (!peeked_) {
        peek_ = scan();
        peeked_ = true;
    }
    return peek_;
}

bool AsterLexer::moreOnLine() const {
    if (peeked_) return !peek_.first && peek_.kind != AsterToken::Kind::End;
    if (line_ >= lines_.size() || line_ != lastTokenLine_) return false;
    const std::string& s = lines_[line_];
    const size_t limit = std::min(s.size(), kColumns);
    const size_t col = skipSeparators(s, col_, limit);
    return col < limit && s[col] != '%';
}

AsterToken AsterLexer::next() {
    peek();
    peeked_ = false;
    return std::move(peek_);
}

void AsterLexer::restartAt(int line) {
    line_ = size_t(line - 1);
    col_ = 0;
    lastTokenLine_ = SIZE_MAX;
    peeked_ = false;
}

AsterToken AsterLexer::scan() {
    while (line_ < lines_.size()) {
        const std::string& s = lines_[line_];
        const size_t limit = std::min(s.size(), kColumns);
        col_ = skipSeparators(s, col_, limit);
        if (col_ >= limit || s[col_] == '%') {
            if (col_ >= limit && s.find_first_not_of(" \t\r", limit) != std::string::npos)
                fail(int(line_ + 1),
                     "text beyond column 80 (code_aster reads columns 1 to 80 only and "
                     "would drop it without a word): wrap the line");
            ++line_;
            col_ = 0;
            continue;
        }
        AsterToken tok;
        tok.line = int(line_ + 1);
        tok.first = lastTokenLine_ != line_;
        lastTokenLine_ = line_;
        const char c = s[col_];
        if (isLetter(c)) {
            const size_t start = col_;
            while (col_ < limit && (isLetter(s[col_]) || isDigit(s[col_]) || s[col_] == '_')) ++col_;
            tok.kind = AsterToken::Kind::Name;
            tok.text = s.substr(start, col_ - start);
        } else if (isDigit(c) || c == '.' || c == '+' || c == '-') {
            scanNumber(s, limit, col_, tok);
        } else if (c == '\'' || c == '"') {
            fail(tok.line, "quoted text where a name or a number is expected");
        } else {
            // A byte that is not printable ASCII goes into the message as its code, never raw.
            const auto byte = static_cast<unsigned char>(c);
            char shown[16];
            if (byte >= 0x20 && byte < 0x7f) std::snprintf(shown, sizeof(shown), "'%c'", c);
            else std::snprintf(shown, sizeof(shown), "byte 0x%02X", byte);
            fail(tok.line, std::string("unexpected character ") + shown +
                               " (names are a letter followed by letters, digits or '_')");
        }
        return tok;
    }
    AsterToken end;
    end.line = lineCount();
    end.first = true;
    return end;
}

// [+-]digits, or [+-]digits.digits / [+-].digits with an optional E|D exponent (blanks allowed
// after the letter, as code_aster's lexer does); "1E5" without a decimal point is refused.
void AsterLexer::scanNumber(const std::string& s, size_t limit, size_t& col, AsterToken& tok) const {
    const size_t start = col;
    // The number in from_chars' syntax: no '+', 'E' for the exponent, no blank (at most 80 columns).
    char normalised[kColumns + 1];
    size_t length = 0;
    auto take = [&](bool keep) {
        if (keep && s[col] != '+') normalised[length++] = s[col];
        ++col;
    };
    if (s[col] == '+' || s[col] == '-') take(true);
    size_t digits = 0;
    while (col < limit && isDigit(s[col])) take(true), ++digits;
    bool real = false;
    if (col < limit && s[col] == '.') {
        real = true;
        take(true);
        while (col < limit && isDigit(s[col])) take(true), ++digits;
    }
    if (digits == 0) fail(tok.line, "'" + s.substr(start, col - start + 1) + "' is not a number");
    if (col < limit && std::strchr("EeDd", s[col]) != nullptr) {
        if (!real)
            fail(tok.line, "'" + s.substr(start, col - start + 2) +
                               "...': a number with an exponent needs a decimal point (write 1.E5, not 1E5)");
        normalised[length++] = 'E';
        ++col;
        while (col < limit && (s[col] == ' ' || s[col] == '\t')) ++col;
        if (col < limit && (s[col] == '+' || s[col] == '-')) take(true);
        size_t expDigits = 0;
        while (col < limit && isDigit(s[col])) take(true), ++expDigits;
        if (expDigits == 0) fail(tok.line, "'" + s.substr(start, col - start) + "': exponent without digits");
    }
    if (col < limit && (isLetter(s[col]) || s[col] == '_' || s[col] == '.'))
        fail(tok.line, "malformed number '" + s.substr(start, col - start + 1) + "'");
    tok.kind = real ? AsterToken::Kind::Real : AsterToken::Kind::Integer;
    tok.text = s.substr(start, col - start);
    // from_chars leaves the value unset out of double's range: an underflow (below 1e-308) is 0,
    // an overflow an error rather than a coordinate of no meaning.
    if (std::from_chars(normalised, normalised + length, tok.value).ec == std::errc::result_out_of_range) {
        normalised[length] = '\0';
        tok.value = std::strtod(normalised, nullptr);
        if (std::abs(tok.value) > 1.0)
            fail(tok.line, "the number '" + tok.text + "' is beyond double precision (magnitude 1.8E+308 at most)");
        tok.value = 0.0;
    }
}

}  // namespace ma
