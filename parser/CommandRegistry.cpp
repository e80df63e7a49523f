#include "parser/CommandRegistry.hpp"

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

}  // namespace ma
