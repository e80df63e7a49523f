// docs/commands.md maps every command to its code: this test keeps the map complete. Every
// command the registry dispatches (src/commands) and every command of the catalog (with DEBUT,
// FIN, FORMULE, PRE_GIBI, run by the supervisor itself), and _F, has its row "| `NAME` |"; and
// every row names a command that exists, and every file or header it names exists.
#include <gtest/gtest.h>

#include <filesystem>
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

// The catalog entries, implementations and tests a row names are files of the checkout, its engine
// pieces headers of src/ (or med_io/): a file that moves leaves no stale row behind.
TEST(CommandMap, NamesOnlyFilesThatExist) {
    const std::string doc = commandMap();
    const std::filesystem::path root = MINIASTER_SOURCE_DIR;
    const std::regex row(R"(\n\| `[A-Z_][A-Z0-9_]*` \|[^\n]*)");
    const std::regex path(R"(`([a-z_]+(/[A-Za-z0-9_]+)+(\.cpp)?)`)");
    int files = 0;
    for (std::sregex_iterator it(doc.begin(), doc.end(), row), end; it != end; ++it) {
        const std::string line = std::string((*it)[0]).substr(1);
        for (std::sregex_iterator p(line.begin(), line.end(), path); p != end; ++p, ++files) {
            const std::string name = (*p)[1];
            const bool exists = (*p)[3].matched
                                    ? std::filesystem::exists(root / name) || std::filesystem::exists(root / "tests" / name)
                                    : std::filesystem::exists(root / "src" / (name + ".hpp")) ||
                                          std::filesystem::exists(root / (name + ".hpp"));
            EXPECT_TRUE(exists) << name << " in the row " << line.substr(0, line.find(" |", 2)) << " |";
        }
    }
    EXPECT_GT(files, 100);
}

}  // namespace
