// docs/commands.md maps every command to its code: this test keeps the map complete. Every
// command the registry dispatches (src/commands) and every command of the catalog (with DEBUT,
// FIN, FORMULE, PRE_GIBI, run by the supervisor itself), and _F, has its row "| `NAME` |"; and
// every row names a command that exists, and every file or header it names exists. The catalog
// column is each command's own file, and the tests a row lists call that command.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "parser/Catalog.hpp"
#include "parser/CommandRegistry.hpp"
#include "parser/catalog/Commands.hpp"

namespace {

std::string commandMap() {
    std::ifstream in(std::string(MINIASTER_SOURCE_DIR) + "/docs/commands.md");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string fileText(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// The rows of the map: command name and its cells (catalog entry, implementation, engine pieces, tests).
std::vector<std::pair<std::string, std::vector<std::string>>> commandRows() {
    const std::string doc = commandMap();
    const std::regex row(R"(\n\| `([A-Z_][A-Z0-9_]*)` \|([^\n]*))");
    std::vector<std::pair<std::string, std::vector<std::string>>> rows;
    for (std::sregex_iterator it(doc.begin(), doc.end(), row), end; it != end; ++it) {
        std::vector<std::string> cells;
        std::istringstream line((*it)[2]);
        for (std::string cell; std::getline(line, cell, '|');) {
            const auto b = cell.find_first_not_of(' '), e = cell.find_last_not_of(' ');
            if (b != std::string::npos) cells.push_back(cell.substr(b, e - b + 1));
        }
        rows.emplace_back((*it)[1], cells);
    }
    return rows;
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
            const bool exists =
                (*p)[3].matched ? std::filesystem::exists(root / name) || std::filesystem::exists(root / "tests" / name)
                                : std::filesystem::exists(root / "src" / (name + ".hpp")) ||
                                      std::filesystem::exists(root / (name + ".hpp"));
            EXPECT_TRUE(exists) << name << " in the row " << line.substr(0, line.find(" |", 2)) << " |";
        }
    }
    EXPECT_GT(files, 100);
}

// parser/catalog/*.cpp are the catalogued commands, one file each, named after the command; each
// is listed in parser/catalog/Commands.hpp and adds exactly its own command.
TEST(CommandMap, CatalogHasOneFilePerCommand) {
    const std::filesystem::path folder = std::filesystem::path(MINIASTER_SOURCE_DIR) / "parser" / "catalog";
    std::set<std::string> files, listed;
    for (const auto& f : std::filesystem::directory_iterator(folder))
        if (f.path().extension() == ".cpp") files.insert(f.path().stem().string());
    for (const auto& file : ma::catalog_entries::commandFiles()) {
        listed.insert(file.command);
        ma::Catalog one;
        file.add(one);
        ASSERT_EQ(one.commands().size(), 1u) << "parser/catalog/" << file.command << ".cpp adds several commands";
        EXPECT_EQ(one.commands().begin()->first, file.command) << "parser/catalog/" << file.command << ".cpp";
        EXPECT_NE(
            fileText(folder / (std::string(file.command) + ".cpp")).find(std::string("cmd(\"") + file.command + "\""),
            std::string::npos)
            << file.command << " is not defined in its own file";
    }
    EXPECT_EQ(files, listed) << "parser/catalog/*.cpp and parser/catalog/Commands.hpp differ";
    std::set<std::string> catalogued;
    for (const auto& [n, c] : ma::Catalog::instance().commands()) catalogued.insert(n);
    EXPECT_EQ(catalogued, listed);
}

// The catalog column is the command's own file, or a dash for _F (not a command of the catalog).
TEST(CommandMap, CatalogColumnIsTheCommandsFile) {
    const auto& catalog = ma::Catalog::instance();
    int rows = 0;
    for (const auto& [name, cells] : commandRows()) {
        ASSERT_GE(cells.size(), 4u) << name;
        ++rows;
        if (catalog.find(name)) EXPECT_EQ(cells[0], "`parser/catalog/" + name + ".cpp`") << name;
        else EXPECT_EQ(cells[0].rfind("—", 0), 0u) << name << " is not catalogued: its catalog entry is a dash";
    }
    EXPECT_EQ(rows, static_cast<int>(everyCommand().size()));
}

// A test file listed in a row calls the command: its name appears as a word in the file or in the
// tests/support/ headers it includes (the scenes that build the command files).
std::string testSources(const std::filesystem::path& file, std::set<std::string>& seen) {
    if (!seen.insert(file.string()).second || !std::filesystem::exists(file)) return {};
    std::string text = fileText(file);
    const std::regex include(R"re(#include "([a-z_0-9]+\.hpp)")re");
    const std::string own = text;
    for (std::sregex_iterator it(own.begin(), own.end(), include), end; it != end; ++it)
        text += testSources(std::filesystem::path(MINIASTER_SOURCE_DIR) / "tests" / "support" / (*it)[1].str(), seen);
    return text;
}

TEST(CommandMap, ListedTestsCallTheCommand) {
    const std::filesystem::path tests = std::filesystem::path(MINIASTER_SOURCE_DIR) / "tests";
    const std::regex testFile(R"(`((cli|unit)/[a-z_0-9]+\.cpp)`)");
    int checked = 0;
    for (const auto& [name, cells] : commandRows()) {
        const std::string& listed = cells.back();
        const std::regex word("(^|[^A-Z0-9_])" + name + "($|[^A-Z0-9_])");
        for (std::sregex_iterator it(listed.begin(), listed.end(), testFile), end; it != end; ++it, ++checked) {
            std::set<std::string> seen;
            const std::string text = testSources(tests / (*it)[1].str(), seen);
            EXPECT_TRUE(std::regex_search(text, word))
                << (*it)[1] << " is listed for " << name << " but does not call it";
        }
    }
    EXPECT_GT(checked, 100);
}

}  // namespace
