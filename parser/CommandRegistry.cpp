#include "parser/CommandRegistry.hpp"

#include "parser/RunOptions.hpp"

namespace ma {

CommandRegistry& CommandRegistry::instance() {
    static CommandRegistry r;
    return r;
}

void CommandRegistry::add(const std::string& name, CommandFunction fn) { commands_[name] = std::move(fn); }

const CommandFunction* CommandRegistry::find(const std::string& name) const {
    auto it = commands_.find(name);
    return it == commands_.end() ? nullptr : &it->second;
}

std::vector<std::string> CommandRegistry::names() const {
    std::vector<std::string> out;
    for (const auto& [name, fn] : commands_) out.push_back(name);
    return out;
}

RunOptionRegistry& RunOptionRegistry::instance() {
    static RunOptionRegistry r;
    return r;
}

void RunOptionRegistry::add(RunOption option) {
    const std::string name = option.name;
    options_[name] = std::move(option);
}

const RunOption* RunOptionRegistry::find(const std::string& name) const {
    auto it = options_.find(name);
    return it == options_.end() ? nullptr : &it->second;
}

}  // namespace ma
