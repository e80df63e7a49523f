#include "parser/KeywordTree.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace ma {

namespace {
const std::vector<KeywordSet> kNoOccurrence;
}

std::string KeywordSet::pathOf(const std::string& keyword) const {
    return path_.empty() ? keyword : path_ + "/" + keyword;
}

bool KeywordSet::has(const std::string& keyword) const {
    return simple_.count(keyword) > 0 || factor_.count(keyword) > 0;
}

const std::vector<KeywordValue>& KeywordSet::values(const std::string& keyword) const {
    auto it = simple_.find(keyword);
    if (it == simple_.end())
        throw InternalError("keyword " + pathOf(keyword) +
                            " is read but absent from the call, and the catalog gives it no default");
    return it->second;
}

namespace {
template <class T>
const T& single(const KeywordSet& set, const std::string& keyword, const char* what) {
    const auto& v = set.values(keyword);
    if (v.size() != 1)
        throw UserError(fmt::format("keyword {} expects one {} value, got {}", set.pathOf(keyword), what, v.size()));
    if (!std::holds_alternative<T>(v[0]))
        throw UserError(fmt::format("keyword {} is not of type {}", set.pathOf(keyword), what));
    return std::get<T>(v[0]);
}
}  // namespace

double KeywordSet::real(const std::string& keyword) const {
    const auto& v = values(keyword);
    if (v.size() == 1 && std::holds_alternative<long long>(v[0])) return static_cast<double>(std::get<long long>(v[0]));
    return single<double>(*this, keyword, "real");
}

long long KeywordSet::integer(const std::string& keyword) const { return single<long long>(*this, keyword, "integer"); }

const std::string& KeywordSet::text(const std::string& keyword) const {
    return single<std::string>(*this, keyword, "text");
}

std::vector<double> KeywordSet::reals(const std::string& keyword) const {
    std::vector<double> out;
    for (const auto& v : values(keyword)) {
        if (std::holds_alternative<double>(v)) out.push_back(std::get<double>(v));
        else if (std::holds_alternative<long long>(v)) out.push_back(double(std::get<long long>(v)));
        else throw UserError("keyword " + pathOf(keyword) + " expects reals");
    }
    return out;
}

std::vector<long long> KeywordSet::integers(const std::string& keyword) const {
    std::vector<long long> out;
    for (const auto& v : values(keyword)) {
        if (!std::holds_alternative<long long>(v)) throw UserError("keyword " + pathOf(keyword) + " expects integers");
        out.push_back(std::get<long long>(v));
    }
    return out;
}

std::vector<std::string> KeywordSet::texts(const std::string& keyword) const {
    std::vector<std::string> out;
    for (const auto& v : values(keyword)) {
        if (!std::holds_alternative<std::string>(v)) throw UserError("keyword " + pathOf(keyword) + " expects texts");
        out.push_back(std::get<std::string>(v));
    }
    return out;
}

ConceptPtr KeywordSet::rawObject(const std::string& keyword) const {
    return single<ConceptPtr>(*this, keyword, "concept");
}

const std::vector<KeywordSet>& KeywordSet::factor(const std::string& keyword) const {
    auto it = factor_.find(keyword);
    return it == factor_.end() ? kNoOccurrence : it->second;
}

void KeywordSet::setValues(const std::string& keyword, std::vector<KeywordValue> values) {
    simple_[keyword] = std::move(values);
}

KeywordSet& KeywordSet::addOccurrence(const std::string& keyword) {
    auto& occ = factor_[keyword];
    occ.emplace_back(fmt::format("{}{}[{}]", path_.empty() ? "" : path_ + "/", keyword, occ.size() + 1));
    return occ.back();
}

void KeywordSet::setFactor(const std::string& keyword, std::vector<KeywordSet> occurrences) {
    factor_[keyword] = std::move(occurrences);
}

void KeywordSet::remove(const std::string& keyword) {
    simple_.erase(keyword);
    factor_.erase(keyword);
}

std::string boundedText(const std::string& text, size_t limit) {
    if (text.size() <= limit) return text;
    size_t cut = limit;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // a continuation byte
    return fmt::format("{}... ({} characters)", text.substr(0, cut), text.size());
}

std::string formatKeywordValue(const KeywordValue& v) {
    if (std::holds_alternative<long long>(v)) return std::to_string(std::get<long long>(v));
    if (std::holds_alternative<double>(v)) return fmt::format("{}", std::get<double>(v));
    if (std::holds_alternative<std::string>(v)) return fmt::format("'{}'", boundedText(std::get<std::string>(v)));
    const auto& c = std::get<ConceptPtr>(v);
    return c ? c->name : "None";
}

std::string KeywordSet::echo(int indent) const {
    std::string pad(indent, ' ');
    std::string out;
    for (const auto& [k, vals] : simple_) {
        out += pad + k + "=";
        if (vals.size() == 1) {
            out += formatKeywordValue(vals[0]);
        } else {
            out += "(";
            for (size_t i = 0; i < std::min(vals.size(), kEchoedValues); ++i) {
                if (i) out += ", ";
                out += formatKeywordValue(vals[i]);
            }
            if (vals.size() > kEchoedValues) out += fmt::format(", ... ({} values)", vals.size());
            out += ")";
        }
        out += ",\n";
    }
    for (const auto& [k, occs] : factor_) {
        for (size_t i = 0; i < std::min(occs.size(), kEchoedValues); ++i)
            out += pad + k + "=_F(\n" + occs[i].echo(indent + 4) + pad + "    ),\n";
        if (occs.size() > kEchoedValues) out += fmt::format("{}... ({} occurrences of {})\n", pad, occs.size(), k);
    }
    return out;
}

}  // namespace ma
