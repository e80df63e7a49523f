// Catalog builders and the validation of a call against a catalog entry.
#include "parser/Catalog.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "parser/catalog/Commands.hpp"

namespace ma {

// One file per command (parser/catalog/Commands.hpp). Explicit calls, not static registration:
// ma_parser is a static library and unreferenced registration objects would be dropped.
const Catalog& Catalog::instance() {
    static const Catalog catalog = [] {
        Catalog c;
        for (const auto& file : catalog_entries::commandFiles()) file.add(c);
        return c;
    }();
    return catalog;
}

const cata::Command* Catalog::find(const std::string& name) const {
    auto it = commands_.find(name);
    return it == commands_.end() ? nullptr : &it->second;
}

void Catalog::add(cata::Command c) {
    std::string name = c.name;
    commands_.emplace(std::move(name), std::move(c));
}

const std::vector<std::string>& unsupportedCommands() {
    // code_aster commands that a user of this class of studies may try; miniaster has none of them.
    static const std::vector<std::string> names{
        "POURSUITE",      "INCLUDE",
        "CALC_CHAM_ELEM", "TEST_FONCTION",
        "DYNA_NON_LINE",  "DYNA_LINE",
        "MECA_NON_LINE",  "THER_LINEAIRE",
        "THER_NON_LINE",  "CALC_G_XFEM",
        "PROPA_FISS",     "DEFI_FISS_XFEM_PROPA",
        "CREA_MAILLAGE",  "CREA_RESU",
        "CREA_TABLE",     "PROJ_CHAMP",
        "AFFE_CARA_ELEM", "AFFE_CHAR_CINE",
        "DEFI_COMPOR",    "DEFI_NAPPE",
        "CALC_FONCTION",  "IMPR_FONCTION",
        "LIRE_RESU",      "EXTR_RESU",
        "MACR_ADAP_MAIL", "RAFF_XFEM",
        "CALC_MATR_ELEM", "NUME_DDL",
        "ASSE_MATRICE",   "RESOUDRE",
        "FACTORISER",     "MODE_ITER_SIMULT",
        "CALC_MODES",     "DEFI_LIST_INST",
        "LIRE_TABLE",     "MACRO_ELAS_MULT",
        "POST_ELEM",      "STAT_NON_LINE_XFEM",
    };
    return names;
}

// ------------------------------------------------------------------------------------------
// Builders

namespace cata {

Keyword R(std::string name) {
    Keyword k;
    k.name = std::move(name);
    k.acceptsReal = true;
    return k;
}
Keyword I(std::string name) {
    Keyword k;
    k.name = std::move(name);
    k.acceptsInt = true;
    return k;
}
Keyword TXM(std::string name) {
    Keyword k;
    k.name = std::move(name);
    k.acceptsText = true;
    return k;
}
Keyword CO(std::string name, std::vector<std::string> types) {
    Keyword k;
    k.name = std::move(name);
    k.conceptTypes = std::move(types);
    return k;
}
Keyword fact(std::string name) {
    Keyword k;
    k.kind = Keyword::Kind::Factor;
    k.name = std::move(name);
    return k;
}
Keyword bloc(Condition condition, std::vector<Keyword> content, std::vector<Rule> rules) {
    Keyword k;
    k.kind = Keyword::Kind::Block;
    k.condition = std::move(condition);
    k.content = std::move(content);
    k.rulesList = std::move(rules);
    return k;
}
Keyword unsupported(std::string name, std::string why) {
    Keyword k;
    k.kind = Keyword::Kind::Unsupported;
    k.name = std::move(name);
    k.why = std::move(why);
    return k;
}
std::vector<Keyword> unsupported(std::initializer_list<const char*> names, const std::string& why) {
    std::vector<Keyword> out;
    for (const char* n : names) out.push_back(unsupported(std::string(n), why));
    return out;
}

std::vector<Keyword> join(std::vector<std::vector<Keyword>> parts) {
    std::vector<Keyword> out;
    for (auto& p : parts)
        for (auto& k : p) out.push_back(std::move(k));
    return out;
}

Command cmd(std::string name, std::string resultType) {
    Command c;
    c.name = std::move(name);
    c.result = std::move(resultType);
    return c;
}

std::string Keyword::typeText() const {
    std::vector<std::string> parts;
    if (acceptsReal) parts.push_back("real");
    if (acceptsInt) parts.push_back("integer");
    if (acceptsText) parts.push_back("text");
    for (const auto& t : conceptTypes) parts.push_back(t);
    return fmt::format("{}", fmt::join(parts, " or "));
}

namespace {
std::string valueText(const KeywordValue& v) {
    if (std::holds_alternative<std::string>(v)) return std::get<std::string>(v);
    return formatKeywordValue(v);
}
std::string listNames(const std::vector<std::string>& names) { return fmt::format("{}", fmt::join(names, ", ")); }
}  // namespace

bool Condition::holds(const KeywordSet& level) const {
    switch (kind) {
        case Kind::Present: return level.has(keyword);
        case Kind::Absent: return !level.has(keyword);
        case Kind::Equals: {
            if (!level.simpleKeywords().count(keyword)) return false;
            for (const auto& v : level.values(keyword))
                if (std::find(values.begin(), values.end(), valueText(v)) != values.end()) return true;
            return false;
        }
    }
    return false;
}

std::string Condition::describe() const {
    switch (kind) {
        case Kind::Present: return keyword + " is given";
        case Kind::Absent: return keyword + " is absent";
        case Kind::Equals: {
            std::vector<std::string> quoted;
            for (const auto& v : values) quoted.push_back("'" + v + "'");
            return keyword + (values.size() == 1 ? "=" : " in (") + listNames(quoted) + (values.size() == 1 ? "" : ")");
        }
    }
    return {};
}

std::string Rule::check(const KeywordSet& level, const std::string& where) const {
    std::vector<std::string> given;
    for (const auto& k : keywords)
        if (level.has(k)) given.push_back(k);
    const std::string all = listNames(keywords);
    const std::string got = given.empty() ? "none" : listNames(given);
    switch (kind) {
        case Kind::UnParmi:
            if (given.size() == 1) return {};
            return fmt::format("exactly one of {} must be given{} (rule UN_PARMI), got {}", all, where, got);
        case Kind::AuMoinsUn:
            if (!given.empty()) return {};
            return fmt::format("at least one of {} must be given{} (rule AU_MOINS_UN)", all, where);
        case Kind::Exclus:
            if (given.size() <= 1) return {};
            return fmt::format("{} cannot be given together{} (rule EXCLUS: at most one of {})", got, where, all);
        case Kind::Ensemble:
            if (given.empty() || given.size() == keywords.size()) return {};
            return fmt::format("{} must be given together{} (rule ENSEMBLE), got only {}", all, where, got);
        case Kind::PresentPresent: {
            if (!level.has(keywords[0])) return {};
            for (size_t i = 1; i < keywords.size(); ++i)
                if (!level.has(keywords[i]))
                    return fmt::format("{} requires {}{} (rule PRESENT_PRESENT)", keywords[0], keywords[i], where);
            return {};
        }
        case Kind::PresentAbsent: {
            if (!level.has(keywords[0])) return {};
            for (size_t i = 1; i < keywords.size(); ++i)
                if (level.has(keywords[i]))
                    return fmt::format("{} and {} cannot be given together{} (rule PRESENT_ABSENT)", keywords[0],
                                       keywords[i], where);
            return {};
        }
    }
    return {};
}

}  // namespace cata

// ------------------------------------------------------------------------------------------
// CallValue

std::string CallValue::describe() const {
    switch (kind) {
        case Kind::None: return "None";
        case Kind::Bool: return integer ? "True" : "False";
        case Kind::Int: return std::to_string(integer);
        case Kind::Real: return fmt::format("{}", real);
        case Kind::Text: return "'" + text + "'";
        case Kind::Concept:
            return object
                       ? fmt::format("{} ({})", object->name.empty() ? "<unnamed>" : object->name, object->typeName())
                       : "None";
        case Kind::List: {
            std::string out = "(";
            for (size_t i = 0; i < items.size() && i < 6; ++i) out += (i ? ", " : "") + items[i].describe();
            if (items.size() > 6) out += ", ...";
            return out + ")";
        }
        case Kind::Dict: return "_F(...)";
        case Kind::Other: return "an object of Python type " + text;
    }
    return {};
}

// ------------------------------------------------------------------------------------------
// Validation

namespace {

using cata::Keyword;
using cata::Rule;

struct Level {
    const std::vector<Keyword>& content;
    const std::vector<Rule>& rules;
};

// Every keyword name that appears at this level (unconditional or in any block), with the entry.
using BlockConditions = std::map<std::string, std::vector<const cata::Condition*>>;
void collectNames(const std::vector<Keyword>& content, std::map<std::string, const Keyword*>& names,
                  const cata::Condition* inBlock, BlockConditions& blockOf) {
    for (const auto& k : content) {
        if (k.kind == Keyword::Kind::Block) {
            collectNames(k.content, names, &k.condition, blockOf);
        } else {
            names.emplace(k.name, &k);
            if (inBlock) blockOf[k.name].push_back(inBlock);
        }
    }
}

std::string quotedList(const std::vector<std::string>& v) {
    std::vector<std::string> q;
    for (const auto& s : v) q.push_back("'" + s + "'");
    return fmt::format("{}", fmt::join(q, ", "));
}

KeywordValue convertItem(const Keyword& def, const CallValue& item, const std::string& path) {
    using K = CallValue::Kind;
    auto wrongType = [&]() {
        return UserError(fmt::format("keyword {}: {} is not of type {}", path, item.describe(), def.typeText()));
    };
    switch (item.kind) {
        case K::Int:
            if (def.acceptsInt) return item.integer;
            if (def.acceptsReal) return static_cast<double>(item.integer);
            throw wrongType();
        case K::Real:
            if (def.acceptsReal) return item.real;
            throw wrongType();
        case K::Text:
            if (def.acceptsText) return item.text;
            throw wrongType();
        case K::Concept: {
            const std::string type = item.object ? item.object->typeName() : "";
            if (item.object &&
                std::find(def.conceptTypes.begin(), def.conceptTypes.end(), type) != def.conceptTypes.end())
                return item.object;
            throw wrongType();
        }
        default: throw wrongType();
    }
}

void checkAllowed(const Keyword& def, const KeywordValue& v, const std::string& path) {
    if (std::holds_alternative<std::string>(v)) {
        const auto& s = std::get<std::string>(v);
        if (!def.intoTexts.empty() && std::find(def.intoTexts.begin(), def.intoTexts.end(), s) == def.intoTexts.end())
            throw UserError(fmt::format("keyword {}: value '{}' is not allowed (allowed values: {})", path, s,
                                        quotedList(def.intoTexts)));
        if (std::find(def.unsupportedValues.begin(), def.unsupportedValues.end(), s) != def.unsupportedValues.end())
            throw NotImplemented(fmt::format("keyword {}: value '{}' is not supported by miniaster", path, s));
        if (def.textCheck)
            if (const std::string why = def.textCheck(s); !why.empty())
                throw UserError(fmt::format("keyword {}: value '{}' {}", path, s, why));
    }
    if (std::holds_alternative<long long>(v)) {
        const long long i = std::get<long long>(v);
        if (!def.intoInts.empty() && std::find(def.intoInts.begin(), def.intoInts.end(), i) == def.intoInts.end())
            throw UserError(fmt::format("keyword {}: value {} is not allowed (allowed values: {})", path, i,
                                        fmt::join(def.intoInts, ", ")));
    }
    if (std::holds_alternative<double>(v) || std::holds_alternative<long long>(v)) {
        const double x = std::holds_alternative<double>(v) ? std::get<double>(v) : double(std::get<long long>(v));
        if (!std::isfinite(x)) throw UserError(fmt::format("keyword {}: value {} is not a finite number", path, x));
        if ((def.lowerBound && x < *def.lowerBound) || (def.upperBound && x > *def.upperBound))
            throw UserError(fmt::format("keyword {}: value {} is out of range [{}, {}]", path, x,
                                        def.lowerBound ? fmt::format("{}", *def.lowerBound) : "-inf",
                                        def.upperBound ? fmt::format("{}", *def.upperBound) : "+inf"));
    }
}

std::string countText(int n) { return n == cata::kMany ? "any number of" : std::to_string(n); }

void convertSimple(const Keyword& def, const CallValue& given, KeywordSet& out, const std::string& command) {
    const std::string path = out.pathOf(def.name);
    std::vector<const CallValue*> items;
    if (given.kind == CallValue::Kind::List) {
        for (const auto& i : given.items) items.push_back(&i);
    } else {
        items.push_back(&given);
    }
    if (int(items.size()) > def.maxCount)
        throw UserError(fmt::format("keyword {} accepts at most {} value{}, got {}: {}", path, def.maxCount,
                                    def.maxCount > 1 ? "s" : "", items.size(), given.describe()));
    if (int(items.size()) < def.minCount)
        throw UserError(fmt::format("keyword {} needs at least {} values, got {}", path, def.minCount, items.size()));
    std::vector<KeywordValue> values;
    for (const auto* item : items) {
        KeywordValue v = convertItem(def, *item, path);
        checkAllowed(def, v, path);
        if (std::holds_alternative<std::string>(v)) {
            auto legacy = def.legacyValues.find(std::get<std::string>(v));
            if (legacy != def.legacyValues.end()) {
                msg().infof("    {}: {}='{}' (an older code_aster syntax) is read as {}='{}'", command, path,
                            legacy->first, path, legacy->second);
                v = legacy->second;
            }
        }
        values.push_back(std::move(v));
    }
    out.setValues(def.name, std::move(values));
}

void validateLevel(const std::vector<Keyword>& content, const std::vector<Rule>& rules, const CallArguments& args,
                   KeywordSet& out, const std::string& command, CallArguments* context);

void convertFactor(const Keyword& def, const CallValue& given, KeywordSet& out, const std::string& command) {
    const std::string path = out.pathOf(def.name);
    std::vector<const CallValue*> occurrences;
    if (given.kind == CallValue::Kind::Dict) {
        occurrences.push_back(&given);
    } else if (given.kind == CallValue::Kind::List) {
        for (const auto& o : given.items) {
            if (o.kind != CallValue::Kind::Dict)
                throw UserError(
                    fmt::format("factor keyword {} expects _F(...) occurrences, got {}", path, o.describe()));
            occurrences.push_back(&o);
        }
    } else {
        throw UserError(fmt::format("factor keyword {} expects _F(...), got {}", path, given.describe()));
    }
    if (int(occurrences.size()) > def.maxCount)
        throw UserError(fmt::format("factor keyword {} accepts at most {} occurrence{}, got {}", path, def.maxCount,
                                    def.maxCount > 1 ? "s" : "", occurrences.size()));
    if (int(occurrences.size()) < def.minCount)
        throw UserError(fmt::format("factor keyword {} needs at least {} occurrences, got {}", path,
                                    countText(def.minCount), occurrences.size()));
    for (const auto* o : occurrences) {
        KeywordSet& occ = out.addOccurrence(def.name);
        validateLevel(def.content, def.rulesList, o->dict, occ, command, nullptr);
    }
}

struct LevelState {
    const CallArguments& args;
    std::set<std::string> consumed;
    std::vector<const Rule*> rules;
    std::vector<const Keyword*> active;
};

const CallValue* findArg(const CallArguments& args, const std::string& name) {
    for (const auto& [k, v] : args)
        if (k == name) return v.kind == CallValue::Kind::None ? nullptr : &v;
    return nullptr;
}

// Converts the keywords of `content` (recursing into active blocks) that were given, and fills
// defaults of the absent ones.
void applyContent(const std::vector<Keyword>& content, LevelState& st, KeywordSet& out, const std::string& command) {
    // Plain keywords first, so that the conditions of blocks see them (with their defaults).
    for (const auto& k : content) {
        if (k.kind != Keyword::Kind::Simple && k.kind != Keyword::Kind::Factor) continue;
        if (st.consumed.count(k.name)) continue;  // already defined by an enclosing active entry
        st.active.push_back(&k);
        const CallValue* given = findArg(st.args, k.name);
        if (given) {
            st.consumed.insert(k.name);
            if (k.kind == Keyword::Kind::Simple) convertSimple(k, *given, out, command);
            else convertFactor(k, *given, out, command);
            if (!k.storedAs.empty()) {
                if (out.has(k.storedAs))
                    throw UserError(fmt::format("{} (older name of {}) cannot be given together with {}",
                                                out.pathOf(k.name), k.storedAs, k.storedAs));
                if (k.kind == Keyword::Kind::Simple) {
                    auto values = out.values(k.name);
                    out.remove(k.name);
                    out.setValues(k.storedAs, std::move(values));
                } else {
                    auto occurrences = out.factor(k.name);
                    out.remove(k.name);
                    out.setFactor(k.storedAs, std::move(occurrences));
                }
            }
        } else if (k.kind == Keyword::Kind::Simple && k.hasDefault()) {
            st.consumed.insert(k.name);
            out.setValues(k.name, k.defaultValues);
        } else if (k.kind == Keyword::Kind::Factor && k.defaultOccurrence) {
            // A factor keyword with a default occurrence (code_aster statut 'd').
            st.consumed.insert(k.name);
            KeywordSet& occ = out.addOccurrence(k.name);
            validateLevel(k.content, k.rulesList, {}, occ, command, nullptr);
        }
    }
    for (const auto& k : content) {
        if (k.kind != Keyword::Kind::Block || !k.condition.holds(out)) continue;
        for (const auto& r : k.rulesList) st.rules.push_back(&r);
        applyContent(k.content, st, out, command);
    }
}

void validateLevel(const std::vector<Keyword>& content, const std::vector<Rule>& rules, const CallArguments& args,
                   KeywordSet& out, const std::string& command, CallArguments* context) {
    std::map<std::string, const Keyword*> names;
    BlockConditions blockOf;
    collectNames(content, names, nullptr, blockOf);
    const std::string where = out.path().empty() ? "" : " in " + out.path();

    // 1. Unknown and unsupported keywords, in call order.
    std::set<std::string> seen;
    for (const auto& [name, value] : args) {
        if (!seen.insert(name).second) throw UserError(fmt::format("keyword {} is given twice", out.pathOf(name)));
        auto it = names.find(name);
        if (it == names.end()) {
            if (context) {
                context->emplace_back(name, value);
                continue;
            }
            std::vector<std::string> allowed;
            for (const auto& [n, k] : names)
                if (k->kind != Keyword::Kind::Unsupported) allowed.push_back(n);
            throw UserError(fmt::format("unknown keyword {} for {} (known keywords{}: {})", out.pathOf(name), command,
                                        where, fmt::join(allowed, ", ")));
        }
        if (it->second->kind == Keyword::Kind::Unsupported)
            throw NotImplemented(
                fmt::format("keyword {} is not supported by miniaster ({})", out.pathOf(name), it->second->why));
    }

    // 2. Conversion of the active keywords, defaults.
    LevelState st{args, {}, {}, {}};
    for (const auto& r : rules) st.rules.push_back(&r);
    applyContent(content, st, out, command);

    // 3. Given keywords that belong to blocks whose condition does not hold.
    for (const auto& [name, value] : args) {
        if (value.kind == CallValue::Kind::None || st.consumed.count(name) || !names.count(name)) continue;
        std::vector<std::string> conditions;
        for (const auto* c : blockOf[name]) conditions.push_back(c->describe());
        throw UserError(fmt::format("keyword {} is not allowed here: it is only accepted when {}", out.pathOf(name),
                                    conditions.empty() ? std::string("another keyword selects it")
                                                       : fmt::format("{}", fmt::join(conditions, " or "))));
    }

    // 4. Mandatory keywords.
    for (const auto* k : st.active)
        if (k->isMandatory && !out.has(k->name))
            throw UserError(fmt::format("mandatory keyword {} is missing", out.pathOf(k->name)));

    // 5. Rules.
    for (const auto* r : st.rules) {
        std::string why = r->check(out, where);
        if (!why.empty()) throw UserError(why);
    }
}

}  // namespace

std::string literalValueProblem(const cata::Keyword& def, const std::vector<KeywordValue>& values,
                                const std::string& path) {
    try {
        for (const auto& v : values) checkAllowed(def, v, path);
    } catch (const std::exception& e) { return e.what(); }
    return "";
}

KeywordSet validateCall(const cata::Command& command, const CallArguments& args, CallArguments* context) {
    KeywordSet out;
    validateLevel(command.content, command.rulesList, args, out, command.name,
                  command.acceptsContextKeywords ? context : nullptr);
    return out;
}

}  // namespace ma
