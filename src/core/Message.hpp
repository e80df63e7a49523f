#pragma once
// A message with an id (<A> XFEM_63), its text checked against its arguments at compile time.
// Each area keeps its messages in one table (src/<area>/<Area>Messages.hpp, listed in
// docs/messages.md), as code_aster's message catalogues do.
#include <fmt/format.h>

#include <string>
#include <type_traits>

namespace ma {

namespace detail {
// Replacement fields of a format text ("{{" and "}}" are literal braces).
consteval int replacementFields(const char* text) {
    int fields = 0;
    for (const char* p = text; *p; ++p) {
        if (*p == '{' && p[1] == '{') ++p;
        else if (*p == '{') ++fields;
    }
    return fields;
}
}  // namespace detail

template <class... A>
struct Message {
    const char* id;
    const char* text;
    // fmt checks every field against its argument type; it allows unused arguments, which the
    // count refuses (a throw in a consteval call is a compile error).
    consteval Message(const char* i, const char* t) : id(i), text(t) {
        (void)fmt::format_string<A...>(t);
        if (detail::replacementFields(t) != int(sizeof...(A))) throw "a message takes one argument per {} field";
    }
};

// A table row: the messages of an area, whatever their arguments.
struct MessageText {
    const char* id;
    const char* text;
};

template <class... A>
constexpr MessageText entry(const Message<A...>& m) {
    return {m.id, m.text};
}

template <class... A>
std::string format(const Message<A...>& m, const std::type_identity_t<A>&... a) {
    return fmt::vformat(m.text, fmt::make_format_args(a...));
}

// A message formatted where its facts are known and raised later (a reader's report).
struct FormattedMessage {
    std::string id;
    std::string text;
};

template <class... A>
FormattedMessage formatted(const Message<A...>& m, const std::type_identity_t<A>&... a) {
    return {m.id, format(m, a...)};
}

}  // namespace ma
