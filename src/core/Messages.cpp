#include "core/Messages.hpp"

#include <cstdio>

namespace ma {

Messages& Messages::instance() {
    static Messages m;
    return m;
}

void Messages::info(const std::string& text) {
    mess_ += text;
    if (text.empty() || text.back() != '\n') mess_ += '\n';
    if (echo_) {
        std::fwrite(text.data(), 1, text.size(), stdout);
        if (text.empty() || text.back() != '\n') std::fputc('\n', stdout);
    }
}

void Messages::alarm(const std::string& id, const std::string& text) {
    ++alarms_;
    std::string box = "   !" + std::string(70, '-') + "!\n";
    std::string out = box + "   ! <A> <" + id + ">\n";
    std::string line;
    for (char c : text) {
        if (c == '\n') {
            out += "   ! " + line + "\n";
            line.clear();
        } else {
            line += c;
        }
    }
    if (!line.empty()) out += "   ! " + line + "\n";
    out += "   ! Ceci est une alarme. Si vous ne comprenez pas le sens de cette\n"
           "   ! alarme, vous pouvez obtenir des resultats inattendus !\n";
    out += box;
    info(out);
}

void Messages::result(const std::string& text) {
    resu_ += text;
    if (text.empty() || text.back() != '\n') resu_ += '\n';
    info(text);
}

void Messages::reset() {
    mess_.clear();
    resu_.clear();
    alarms_ = 0;
}

}  // namespace ma
