// docs/messages.md lists every message of the area tables (src/<area>/<Area>Messages.hpp): one
// "## ... `<table header>`" section per area, one "### ID" per id, each text of the id quoted
// ("> ") with named placeholders ({file}) where the table has {} or {:.3e}. This test keeps the two
// the same both ways, and keeps alarm texts in the tables: no alarm is raised from a literal id.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <span>
#include <sstream>
#include <string>
#include <tuple>

#include "contact/ContactMessages.hpp"
#include "fe/FeMessages.hpp"
#include "fracture/FractureMessages.hpp"
#include "med_io/MedMessages.hpp"
#include "mesh/MeshMessages.hpp"
#include "parser/ParserMessages.hpp"
#include "post/PostMessages.hpp"
#include "solver/SolverMessages.hpp"
#include "xfem/XfemMessages.hpp"

namespace {

const std::filesystem::path kRoot = MINIASTER_SOURCE_DIR;

// Header (as the docs name it) -> its table.
const std::map<std::string, std::span<const ma::MessageText>>& tables() {
    static const std::map<std::string, std::span<const ma::MessageText>> t{
        {"parser/ParserMessages.hpp", ma::parserMessages},
        {"src/mesh/MeshMessages.hpp", ma::meshMessages},
        {"med_io/MedMessages.hpp", ma::medMessages},
        {"src/solver/SolverMessages.hpp", ma::solverMessages},
        {"src/fe/FeMessages.hpp", ma::feMessages},
        {"src/xfem/XfemMessages.hpp", ma::xfemMessages},
        {"src/contact/ContactMessages.hpp", ma::contactMessages},
        {"src/fracture/FractureMessages.hpp", ma::fractureMessages},
        {"src/post/PostMessages.hpp", ma::postMessages},
    };
    return t;
}

std::string fileText(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Placeholders compared by position only: {file} in the docs is {} or {:.3e} in the table.
std::string placeholdersErased(const std::string& text) {
    static const std::regex field(R"(\{[^{}]*\})");
    return std::regex_replace(text, field, "{}");
}

using Listed = std::multiset<std::tuple<std::string, std::string, std::string>>;  // (header, id, text)

Listed fromTables() {
    Listed out;
    for (const auto& [header, table] : tables())
        for (const auto& m : table) out.emplace(header, m.id, placeholdersErased(m.text));
    return out;
}

// The quoted texts of docs/messages.md under their section's header and their id; a quote's lines
// are the text's lines (an empty "> " line between them renders the break).
Listed fromDocs(std::set<std::string>& unknownSections) {
    std::istringstream doc(fileText(kRoot / "docs" / "messages.md"));
    static const std::regex section(R"(^## .*`([^`]+Messages\.hpp)`)");
    Listed out;
    std::string header, id, quote;
    auto flush = [&] {
        if (!quote.empty()) out.emplace(header, id, placeholdersErased(quote));
        quote.clear();
    };
    for (std::string line; std::getline(doc, line);) {
        std::smatch m;
        if (line.rfind(">", 0) == 0) {
            const std::string text = line.substr(line.rfind("> ", 0) == 0 ? 2 : 1);
            if (!text.empty()) quote += (quote.empty() ? "" : "\n") + text;
            continue;
        }
        flush();
        if (std::regex_search(line, m, section)) {
            header = m[1];
            if (!tables().count(header)) unknownSections.insert(header);
            id.clear();
        } else if (line.rfind("## ", 0) == 0) {
            header.clear();
        } else if (line.rfind("### ", 0) == 0) {
            id = line.substr(4);
        }
    }
    flush();
    return out;
}

TEST(MessageDocs, ListsEveryTableText) {
    std::set<std::string> unknown;
    const Listed docs = fromDocs(unknown);
    for (const auto& entry : fromTables())
        EXPECT_TRUE(docs.count(entry)) << std::get<1>(entry) << " of " << std::get<0>(entry)
                                       << " is not in docs/messages.md with this text:\n"
                                       << std::get<2>(entry);
    EXPECT_GE(docs.size(), 40u);
}

TEST(MessageDocs, ListsNothingElse) {
    std::set<std::string> unknown;
    const Listed tabled = fromTables();
    for (const auto& entry : fromDocs(unknown))
        EXPECT_TRUE(tabled.count(entry)) << "docs/messages.md quotes under " << std::get<1>(entry) << " ("
                                         << std::get<0>(entry) << ") a text no table has:\n"
                                         << std::get<2>(entry);
    EXPECT_TRUE(unknown.empty()) << *unknown.begin() << " is not a table of this test";
}

// Every id's texts sit under one heading: the ids of the docs and of the tables are the same set.
TEST(MessageDocs, HasOneHeadingPerId) {
    std::set<std::string> ids;
    for (const auto& [header, table] : tables())
        for (const auto& m : table) ids.insert(m.id);
    const std::string doc = fileText(kRoot / "docs" / "messages.md");
    const std::regex heading(R"(\n### ([^\n]*))");
    std::multiset<std::string> headings;
    for (std::sregex_iterator it(doc.begin(), doc.end(), heading), end; it != end; ++it) headings.insert((*it)[1]);
    for (const auto& id : ids) EXPECT_EQ(headings.count(id), 1u) << id;
    for (const auto& h : headings) EXPECT_TRUE(ids.count(h)) << "### " << h << " is not a message id";
}

// Every <Area>Messages.hpp of the sources is a table of this test (core/Messages.hpp is the log).
TEST(MessageDocs, KnowsEveryAreaTable) {
    std::set<std::string> found;
    for (const char* dir : {"src", "parser", "med_io"})
        for (const auto& f : std::filesystem::recursive_directory_iterator(kRoot / dir)) {
            const std::string name = f.path().filename().string();
            if (name.ends_with("Messages.hpp") && name != "Messages.hpp")
                found.insert(std::filesystem::relative(f.path(), kRoot).string());
        }
    std::set<std::string> known;
    for (const auto& [header, table] : tables()) known.insert(header);
    EXPECT_EQ(found, known);
}

// An alarm's text comes from a table: no msg().alarm("ID", ...) nor a FormattedMessage{"ID", ...}.
TEST(MessageDocs, NoAlarmFromALiteralId) {
    const std::regex literal(R"re((alarm\s*\(|FormattedMessage\s*\{)\s*")re");
    int files = 0;
    for (const char* dir : {"src", "parser", "med_io"})
        for (const auto& f : std::filesystem::recursive_directory_iterator(kRoot / dir)) {
            const auto ext = f.path().extension();
            if (ext != ".cpp" && ext != ".hpp") continue;
            ++files;
            const std::string text = fileText(f.path());
            std::smatch m;
            EXPECT_FALSE(std::regex_search(text, m, literal))
                << std::filesystem::relative(f.path(), kRoot).string() << ": " << m.str();
        }
    EXPECT_GT(files, 100);
}

}  // namespace
