// docs/commands.md maps every command to its code: this test keeps the map complete. Every
// command the registry dispatches (src/commands) and every command of the catalog (with DEBUT,
// FIN, FORMULE, PRE_GIBI, run by the supervisor itself), and _F, has its row "| `NAME` |"; and
// every row names a command that exists.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "parser/Catalog.hpp"
#include "parser/CommandRegistry.hpp"

namespace {

std::string commandMap() {
    std::ifstream in(std::string(MINIASTER_SOURCE_DIR) + "/docs/commands.md");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::set<std::string> everyCommand() {
    std::set<std::string> names{"_F"};
    for (const auto& n : ma::CommandRegistry::instance().names()) names.insert(n);
    for (const auto& [n, c] : ma::Catalog::instance().commands()) names.insert(n);
    return names;
}

TEST(CommandMap, NamesEveryRegisteredAndCataloguedCommand) {
    const std::string doc = commandMap();
    ASSERT_FALSE(doc.empty()) << "docs/commands.md is missing";
    const auto names = everyCommand();
    EXPECT_GE(names.size(), 29u);  // 24 registered + DEBUT, FIN, FORMULE, PRE_GIBI + _F today
    for (const auto& n : names) EXPECT_NE(doc.find("| `" + n + "` |"), std::string::npos) << n << " has no row";
}

TEST(CommandMap, NamesNoCommandThatDoesNotExist) {
    const std::string doc = commandMap();
    const auto names = everyCommand();
    const std::regex row(R"(\n\| `([A-Z_][A-Z0-9_]*)` \|)");
    int rows = 0;
    for (std::sregex_iterator it(doc.begin(), doc.end(), row), end; it != end; ++it, ++rows)
        EXPECT_TRUE(names.count((*it)[1])) << (*it)[1] << " is in docs/commands.md but not a command";
    EXPECT_EQ(rows, static_cast<int>(names.size()));
}

}  // namespace
