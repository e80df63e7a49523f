// A keyword tree built by hand (tests, internal calls) checked against the catalog as a .comm
// call would be, so that the command receives the catalog's defaults.
#include "parser/Catalog.hpp"

namespace ma {

namespace {

CallValue callValue(const KeywordValue& v) {
    if (auto* i = std::get_if<long long>(&v)) return CallValue::of(*i);
    if (auto* d = std::get_if<double>(&v)) return CallValue::of(*d);
    if (auto* s = std::get_if<std::string>(&v)) return CallValue::of(*s);
    return CallValue::of(std::get<ConceptPtr>(v));
}

CallArguments callArguments(const KeywordSet& kw) {
    CallArguments args;
    for (const auto& [name, values] : kw.simpleKeywords()) {
        if (values.size() == 1) {
            args.emplace_back(name, callValue(values.front()));
            continue;
        }
        std::vector<CallValue> items;
        for (const auto& v : values) items.push_back(callValue(v));
        args.emplace_back(name, CallValue::list(std::move(items)));
    }
    for (const auto& [name, occurrences] : kw.factorKeywords()) {
        std::vector<CallValue> items;
        for (const auto& occ : occurrences) items.push_back(CallValue::factor(callArguments(occ)));
        args.emplace_back(name, items.size() == 1 ? items.front() : CallValue::list(std::move(items)));
    }
    return args;
}

}  // namespace

KeywordSet validateKeywords(const std::string& command, const KeywordSet& kw) {
    const cata::Command* entry = Catalog::instance().find(command);
    if (!entry) throw UserError("unknown command " + command);
    return validateCall(*entry, callArguments(kw));
}

}  // namespace ma
