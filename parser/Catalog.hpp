#pragma once
// The command catalog: what every command accepts (keywords, types, occurrences, allowed values,
// defaults, rules, conditional blocks, reentrance, result type), in a compact declarative form.
// The supervisor checks every call of the command file against it and turns the call into a
// typed KeywordSet (parser/KeywordTree.hpp) with the defaults filled in.
//
// Entries live in parser/catalog/*.cpp, written with the builders below, e.g.
//
//   cmd("DEFI_LIST_REEL", "listr8_sdaster")
//       .keywords({R("VALE").many(), R("DEBUT"),
//                  fact("INTERVALLE").many().keywords({R("JUSQU_A").mandatory(), I("NOMBRE"), R("PAS")})
//                      .rules({unParmi({"NOMBRE", "PAS"})})})
//       .rules({unParmi({"VALE", "DEBUT"}), ensemble({"DEBUT", "INTERVALLE"})});
//
// See docs/supervisor.md for the full format.
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/Concept.hpp"
#include "parser/KeywordTree.hpp"

namespace ma {

// A value of the call as Python gave it, before validation (built by the Python bridge; plain
// C++ so that validation can be tested without Python).
struct CallValue {
    enum class Kind { None, Bool, Int, Real, Text, Concept, List, Dict, Other };
    Kind kind = Kind::None;
    long long integer = 0;
    double real = 0.0;
    std::string text;  // Text; the Python type name for Other
    ConceptPtr object;
    std::vector<CallValue> items;                         // List (list or tuple)
    std::vector<std::pair<std::string, CallValue>> dict;  // Dict (_F), in call order

    static CallValue of(long long v) {
        CallValue c;
        c.kind = Kind::Int;
        c.integer = v;
        return c;
    }
    static CallValue of(double v) {
        CallValue c;
        c.kind = Kind::Real;
        c.real = v;
        return c;
    }
    static CallValue of(std::string v) {
        CallValue c;
        c.kind = Kind::Text;
        c.text = std::move(v);
        return c;
    }
    static CallValue of(const char* v) { return of(std::string(v)); }
    static CallValue of(ConceptPtr v) {
        CallValue c;
        c.kind = Kind::Concept;
        c.object = std::move(v);
        return c;
    }
    static CallValue list(std::vector<CallValue> v) {
        CallValue c;
        c.kind = Kind::List;
        c.items = std::move(v);
        return c;
    }
    static CallValue factor(std::vector<std::pair<std::string, CallValue>> d) {
        CallValue c;
        c.kind = Kind::Dict;
        c.dict = std::move(d);
        return c;
    }
    // Short text for error messages: 'abc', 1.5, MAILLAG (maillage_sdaster), [1, 2]...
    std::string describe() const;
};
using CallArguments = std::vector<std::pair<std::string, CallValue>>;

namespace cata {

constexpr int kMany = std::numeric_limits<int>::max();

// Condition of a conditional block (code_aster BLOC): evaluated on the keywords of the level
// where the block sits, defaults included.
struct Condition {
    enum class Kind { Equals, Present, Absent } kind = Kind::Equals;
    std::string keyword;
    std::vector<std::string> values;  // Equals: one of these texts
    bool holds(const KeywordSet& level) const;
    std::string describe() const;  // "OPERATION='FILTRE'", "REFERENCE is given"
};
inline Condition when(std::string keyword, std::vector<std::string> values) {
    return {Condition::Kind::Equals, std::move(keyword), std::move(values)};
}
inline Condition whenPresent(std::string keyword) { return {Condition::Kind::Present, std::move(keyword), {}}; }
inline Condition whenAbsent(std::string keyword) { return {Condition::Kind::Absent, std::move(keyword), {}}; }

// Presence rules between keywords of one level (code_aster names).
struct Rule {
    enum class Kind {
        UnParmi,         // exactly one of
        AuMoinsUn,       // at least one of
        Exclus,          // at most one of
        Ensemble,        // all or none
        PresentPresent,  // if the first is given, all the others must be
        PresentAbsent,   // if the first is given, none of the others may be
    } kind;
    std::vector<std::string> keywords;
    // Empty when satisfied, else the reason (names the rule and the keywords).
    std::string check(const KeywordSet& level, const std::string& where) const;
};
inline Rule unParmi(std::vector<std::string> k) { return {Rule::Kind::UnParmi, std::move(k)}; }
inline Rule auMoinsUn(std::vector<std::string> k) { return {Rule::Kind::AuMoinsUn, std::move(k)}; }
inline Rule exclus(std::vector<std::string> k) { return {Rule::Kind::Exclus, std::move(k)}; }
inline Rule ensemble(std::vector<std::string> k) { return {Rule::Kind::Ensemble, std::move(k)}; }
inline Rule presentPresent(std::vector<std::string> k) { return {Rule::Kind::PresentPresent, std::move(k)}; }
inline Rule presentAbsent(std::vector<std::string> k) { return {Rule::Kind::PresentAbsent, std::move(k)}; }

// One entry of a keyword list: a simple keyword, a factor keyword, a conditional block, or a
// keyword code_aster knows that miniaster does not support.
struct Keyword {
    enum class Kind { Simple, Factor, Block, Unsupported } kind = Kind::Simple;
    std::string name;  // Block: unused

    // Simple keywords: accepted types (several allowed: e.g. R or a function).
    bool acceptsReal = false, acceptsInt = false, acceptsText = false;
    std::vector<std::string> conceptTypes;

    // Simple: number of values; Factor: number of occurrences.
    int minCount = 1, maxCount = 1;
    bool isMandatory = false;
    std::vector<std::string> intoTexts;            // allowed text values (empty: any)
    std::vector<long long> intoInts;               // allowed integer values (empty: any)
    std::optional<double> lowerBound, upperBound;  // numeric range (inclusive)
    std::vector<KeywordValue> defaultValues;       // filled when absent (simple only)
    std::vector<std::string> unsupportedValues;    // allowed by code_aster, not by miniaster
    std::string why;                               // Unsupported: short reason (e.g. "friction is not modelled")
    bool defaultOccurrence = false;                // Factor: one occurrence with its defaults when absent
    // Older syntaxes: a value replaced by its current equivalent ('OUI' -> 'STANDARD'), and a
    // keyword stored under its current name (COMP_ELAS -> COMPORTEMENT), so that commands only
    // read the current syntax. Error messages keep the name the user wrote.
    std::map<std::string, std::string> legacyValues;
    std::string storedAs;
    // Text values: a check beyond `into`, run by the static check (empty when accepted, else why
    // not: "is not a Fortran real format ..."), e.g. FORMAT_R.
    std::function<std::string(const std::string&)> textCheck;
    // A keyword of a factor that miniaster does only for some values of a keyword of the command
    // (IMPR_RESU's RESU/GROUP_NO with FORMAT='RESULTAT'): the static check refuses it otherwise.
    std::string onlyWithKeyword;
    std::vector<std::string> onlyWithValues;

    // Factor keyword content, or block content.
    std::vector<Keyword> content;
    std::vector<Rule> rulesList;
    Condition condition;  // Block

    // Builders.
    Keyword& mandatory() {
        isMandatory = true;
        return *this;
    }
    Keyword& many() {
        maxCount = kMany;
        return *this;
    }
    Keyword& max(int n) {
        maxCount = n;
        return *this;
    }
    Keyword& min(int n) {
        minCount = n;
        return *this;
    }
    Keyword& into(std::vector<std::string> v) {
        intoTexts = std::move(v);
        return *this;
    }
    Keyword& intoInt(std::vector<long long> v) {
        intoInts = std::move(v);
        return *this;
    }
    Keyword& range(std::optional<double> lo, std::optional<double> hi) {
        lowerBound = lo;
        upperBound = hi;
        return *this;
    }
    Keyword& def(double v) {
        defaultValues = {v};
        return *this;
    }
    Keyword& def(int v) {
        defaultValues = {static_cast<long long>(v)};
        return *this;
    }
    Keyword& def(const char* v) {
        defaultValues = {std::string(v)};
        return *this;
    }
    Keyword& defs(std::vector<KeywordValue> v) {
        defaultValues = std::move(v);
        return *this;
    }
    Keyword& notSupported(std::vector<std::string> values) {
        unsupportedValues = std::move(values);
        return *this;
    }
    Keyword& byDefault() {
        defaultOccurrence = true;
        return *this;
    }
    Keyword& legacy(std::map<std::string, std::string> values) {
        legacyValues = std::move(values);
        return *this;
    }
    Keyword& checkedBy(std::function<std::string(const std::string&)> check) {
        textCheck = std::move(check);
        return *this;
    }
    Keyword& onlyWith(std::string commandKeyword, std::vector<std::string> values) {
        onlyWithKeyword = std::move(commandKeyword);
        onlyWithValues = std::move(values);
        return *this;
    }
    Keyword& storeAs(std::string current) {
        storedAs = std::move(current);
        return *this;
    }
    Keyword& keywords(std::vector<Keyword> k) {
        content = std::move(k);
        return *this;
    }
    Keyword& rules(std::vector<Rule> r) {
        rulesList = std::move(r);
        return *this;
    }
    // Also accept a concept of these types (e.g. R keyword that may be a function).
    Keyword& orConcept(std::vector<std::string> types) {
        conceptTypes = std::move(types);
        return *this;
    }

    bool hasDefault() const { return !defaultValues.empty(); }
    std::string typeText() const;  // "real", "integer", "text or fonction_sdaster"...
};

// Simple keywords by type (code_aster: R, I, TXM, concept types).
Keyword R(std::string name);
Keyword I(std::string name);
Keyword TXM(std::string name);
Keyword CO(std::string name, std::vector<std::string> types);
// A factor keyword (_F): max 1 occurrence unless .many()/.max(n).
Keyword fact(std::string name);
// A conditional block of keywords and rules.
Keyword bloc(Condition condition, std::vector<Keyword> content, std::vector<Rule> rules = {});
// A keyword that code_aster knows and miniaster refuses with "not supported by miniaster".
Keyword unsupported(std::string name, std::string why);
// Several unsupported keywords sharing one reason.
std::vector<Keyword> unsupported(std::initializer_list<const char*> names, const std::string& why);

enum class Reuse { No, Optional, Mandatory };

struct Command {
    std::string name;
    // code_aster type of the result ("" for procedures such as IMPR_TABLE), or a function of
    // the validated keywords when it depends on them (CREA_CHAMP, POST_CHAM_XFEM).
    std::string result;
    std::function<std::string(const KeywordSet&)> resultOf;
    Reuse reentrant = Reuse::No;
    std::vector<Keyword> content;
    std::vector<Rule> rulesList;
    // FORMULE: keywords that are not in the catalog are context objects, not errors.
    bool acceptsContextKeywords = false;
    // A short comment shown in docs / error hints.
    std::string help;

    Command& keywords(std::vector<Keyword> k) {
        content = std::move(k);
        return *this;
    }
    Command& rules(std::vector<Rule> r) {
        rulesList = std::move(r);
        return *this;
    }
    Command& reuse(Reuse r) {
        reentrant = r;
        return *this;
    }
    Command& resultFrom(std::function<std::string(const KeywordSet&)> f) {
        resultOf = std::move(f);
        return *this;
    }
    Command& contextKeywords() {
        acceptsContextKeywords = true;
        return *this;
    }

    std::string resultType(const KeywordSet& kw) const { return resultOf ? resultOf(kw) : result; }
};

Command cmd(std::string name, std::string resultType = "");

// Helpers for keyword lists: concatenate lists (for shared groups such as mesh-entity selectors).
std::vector<Keyword> join(std::vector<std::vector<Keyword>> parts);

}  // namespace cata

// All catalogued commands.
class Catalog {
public:
    static const Catalog& instance();
    const cata::Command* find(const std::string& name) const;
    const std::map<std::string, cata::Command>& commands() const { return commands_; }
    void add(cata::Command c);

private:
    std::map<std::string, cata::Command> commands_;
};

// What the run would refuse in these values of keyword `def`, given literally in the command file
// (allowed and supported values, range, textCheck), or "" : the static check's value test.
std::string literalValueProblem(const cata::Keyword& def, const std::vector<KeywordValue>& values,
                                const std::string& path);

// Commands of code_aster that miniaster does not provide at all (so that calling one gives
// "not supported by miniaster" instead of an unknown name).
const std::vector<std::string>& unsupportedCommands();

// Check a call against its catalog entry and build the typed keyword tree, defaults filled.
// Throws UserError with the keyword path and the offending value. `context` receives the
// arguments that are not catalog keywords when the command accepts context keywords (FORMULE).
KeywordSet validateCall(const cata::Command& command, const CallArguments& args, CallArguments* context = nullptr);

// The same check for a keyword tree built in C++ (tests): `kw` as a call of `command`, returned
// with the catalog's defaults filled in. UserError as validateCall.
KeywordSet validateKeywords(const std::string& command, const KeywordSet& kw);

}  // namespace ma
