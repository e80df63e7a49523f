#pragma once
// Tokens of a .mail text, after code_aster's lexer (lxscan): free format, separators blank, TAB
// and = ( ) : ; , & * / !, a lone sign followed by a blank, '%' comments to the end of the line,
// identifiers [A-Za-z][A-Za-z0-9_]*, integers, reals with E or D exponents (docs/mesh.md).
#include <cstdint>
#include <istream>
#include <string>
#include <vector>

namespace ma {

struct AsterToken {
    enum class Kind { Name, Integer, Real, End };
    Kind kind = Kind::End;
    std::string text;    // as written
    double value = 0;    // Integer and Real
    int line = 0;        // 1-based line of the file
    bool first = false;  // first item of its line (records and block keywords must be)

    bool isNumber() const { return kind == Kind::Integer || kind == Kind::Real; }
    bool is(const char* name) const { return kind == Kind::Name && text == name; }
};

class AsterLexer {
public:
    AsterLexer(std::istream& in, std::string source);

    const AsterToken& peek();
    // Whether the line of the last token holds more items (looks no further than that line, so
    // that header lines skipped by NBLIGE are never scanned).
    bool moreOnLine() const;
    AsterToken next();
    // Moves to the start of 1-based line `line` (NBLIGE header lines, TITRE lines).
    void restartAt(int line);
    int lineCount() const { return static_cast<int>(lines_.size()); }
    // Line `line` (1-based) as written, first 80 columns (all code_aster reads).
    std::string rawLine(int line) const { return lines_[size_t(line - 1)].substr(0, kColumns); }
    static constexpr size_t kColumns = 80;

    // UserError "mesh file '<source>', line <line>: <what>".
    [[noreturn]] void fail(int line, const std::string& what) const;

private:
    AsterToken scan();
    // Number starting at s[col] (columns before `limit` only).
    void scanNumber(const std::string& s, size_t limit, size_t& col, AsterToken& tok) const;

    std::string source_;
    std::vector<std::string> lines_;
    size_t line_ = 0, col_ = 0;        // position of the next character to scan
    size_t lastTokenLine_ = SIZE_MAX;  // 0-based line of the last token scanned
    bool peeked_ = false;
    AsterToken peek_;
};

}  // namespace ma
