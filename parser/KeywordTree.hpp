#pragma once
// The typed keyword tree a command receives, after the supervisor has checked the call against
// the catalog: simple keywords hold lists of typed values (a scalar is a 1-element list), factor
// keywords hold their occurrences. Defaults of the catalog are already filled in.
#include <map>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "core/Concept.hpp"
#include "core/Error.hpp"

namespace ma {

// One value of a simple keyword. Reals given as Python ints are stored as double when the
// catalog says R; texts are stored as given (code_aster is case-sensitive for values).
using KeywordValue = std::variant<long long, double, std::string, ConceptPtr>;

class KeywordSet {
public:
    KeywordSet() = default;
    explicit KeywordSet(std::string path) : path_(std::move(path)) {}

    // Where this set sits in the call, for error messages: "" (top), "AFFE[2]".
    const std::string& path() const { return path_; }
    std::string pathOf(const std::string& keyword) const;

    bool has(const std::string& keyword) const;  // simple or factor keyword present

    // Simple keywords. The scalar accessors require exactly one value (UserError otherwise). The
    // catalog is the single source of defaults: reading a keyword that is absent (neither given
    // nor defaulted by the catalog) is a bug of the command, an InternalError naming the keyword
    // path; a command checks has() for a keyword without a default.
    double real(const std::string& keyword) const;
    long long integer(const std::string& keyword) const;
    const std::string& text(const std::string& keyword) const;
    std::vector<double> reals(const std::string& keyword) const;
    std::vector<long long> integers(const std::string& keyword) const;
    std::vector<std::string> texts(const std::string& keyword) const;

    template <class T>
    std::shared_ptr<T> object(const std::string& keyword) const {
        auto c = std::dynamic_pointer_cast<T>(rawObject(keyword));
        if (!c) throw UserError("keyword " + pathOf(keyword) + ": wrong concept type");
        return c;
    }
    template <class T>
    std::vector<std::shared_ptr<T>> objects(const std::string& keyword) const {
        std::vector<std::shared_ptr<T>> out;
        for (const auto& v : values(keyword)) {
            auto c = std::dynamic_pointer_cast<T>(std::get<ConceptPtr>(v));
            if (!c) throw UserError("keyword " + pathOf(keyword) + ": wrong concept type");
            out.push_back(c);
        }
        return out;
    }
    ConceptPtr rawObject(const std::string& keyword) const;

    const std::vector<KeywordValue>& values(const std::string& keyword) const;
    // Factor keywords: the occurrences (empty when absent).
    const std::vector<KeywordSet>& factor(const std::string& keyword) const;

    // Building (used by the supervisor and by tests).
    void setValues(const std::string& keyword, std::vector<KeywordValue> values);
    KeywordSet& addOccurrence(const std::string& keyword);
    void setFactor(const std::string& keyword, std::vector<KeywordSet> occurrences);
    void remove(const std::string& keyword);

    const std::map<std::string, std::vector<KeywordValue>>& simpleKeywords() const { return simple_; }
    const std::map<std::string, std::vector<KeywordSet>>& factorKeywords() const { return factor_; }

    // The echo of the call in code_aster's style, for the message log.
    std::string echo(int indent = 0) const;

private:
    std::string path_;
    std::map<std::string, std::vector<KeywordValue>> simple_;
    std::map<std::string, std::vector<KeywordSet>> factor_;
};

// A value as the .mess shows it: a text beyond kEchoedCharacters is cut (see boundedText).
std::string formatKeywordValue(const KeywordValue& v);

// What the .mess echoes of one input, so that a huge input (a list of 10^6 group names, a text of
// 50 MB) does not make a huge log: texts cut to kEchoedCharacters, lists to kEchoedValues values,
// factor keywords to kEchoedValues occurrences, each with the count it had.
constexpr size_t kEchoedCharacters = 400;
constexpr size_t kEchoedValues = 100;
constexpr size_t kEchoedParagraph = 8000;  // an error paragraph
// `text` when at most `limit` bytes, else its first `limit` (not inside a UTF-8 character) and
// "... (N characters)".
std::string boundedText(const std::string& text, size_t limit = kEchoedCharacters);

}  // namespace ma
