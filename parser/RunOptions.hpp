#pragma once
// Expert options of `miniaster run` that are not .comm keywords (`--NAME VALUE`). The parser knows
// none of them: the engine layer that reads one registers it here (from src/commands), with its
// usage text and its check. The supervisor parses every registered option, refuses a bad value
// before the command file starts, announces a given one in the .mess header, and passes the
// values through RunState::runOptions to CommandContext::runOptions as plain texts.
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace ma {

struct RunOption {
    std::string name;       // without the dashes: "subcell-quadrature"
    std::string valueName;  // in the usage line: "RULE"
    std::string help;       // usage paragraph
    // Empty when `value` is valid, else the reason ("'x' is not a rule (...)").
    std::function<std::string(const std::string& value)> check;
    // The .mess header line announcing a given value ("" announces nothing, e.g. for a default).
    std::function<std::string(const std::string& value)> announce;
};

class RunOptionRegistry {
public:
    static RunOptionRegistry& instance();
    void add(RunOption option);
    const RunOption* find(const std::string& name) const;
    const std::map<std::string, RunOption>& options() const { return options_; }

private:
    std::map<std::string, RunOption> options_;
};

struct RunOptionRegistration {
    explicit RunOptionRegistration(RunOption option) { RunOptionRegistry::instance().add(std::move(option)); }
};

}  // namespace ma
