#include "core/Messages.hpp"

#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>

namespace ma {

Messages& Messages::instance() {
    static Messages m;
    return m;
}

void Messages::write(const std::string& text) {
    if (fd_ < 0 || streamError_) return;
    const char* data = text.data();
    size_t left = text.size();
    while (left > 0) {
        const ssize_t n = ::write(fd_, data, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            streamError_ = n < 0 ? errno : ENOSPC;
            return;
        }
        data += n;
        left -= size_t(n);
    }
}

void Messages::streamTo(int fd) {
    std::lock_guard lock(mutex_);
    fd_ = fd;
    write(mess_);
}

void Messages::info(const std::string& text) {
    std::lock_guard lock(mutex_);
    const size_t from = mess_.size();
    mess_ += text;
    if (text.empty() || text.back() != '\n') mess_ += '\n';
    write(mess_.substr(from));
    if (echo_) {
        std::fwrite(text.data(), 1, text.size(), stdout);
        if (text.empty() || text.back() != '\n') std::fputc('\n', stdout);
    }
}

void Messages::freeze() { frozen_ = mutex_.try_lock_for(std::chrono::milliseconds(300)); }

void Messages::emergency(const std::string& text) {
    std::string lines = text;
    if (lines.empty() || lines.back() != '\n') lines += '\n';
    if (frozen_) mess_ += lines;
    write(lines);
    pollfd out{STDOUT_FILENO, POLLOUT, 0};
    // Without the mutex, the thread that holds it may be inside stdout: no echo then.
    if ((echo_ || emergencyEcho_) && frozen_ && ::poll(&out, 1, 0) == 1 && (out.revents & POLLOUT)) {
        std::fwrite(lines.data(), 1, lines.size(), stdout);
        std::fflush(stdout);
    }
}

void Messages::ignoreAlarms(const std::vector<std::string>& ids) {
    std::lock_guard lock(mutex_);
    for (const auto& id : ids) ignored_.emplace(id, 0);
}

void Messages::alarmBox(const std::string& id, const std::string& text) {
    std::lock_guard lock(mutex_);
    if (auto it = ignored_.find(id); it != ignored_.end()) {
        ++it->second;
        return;
    }
    ++alarms_;
    ++raised_[id];
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
    out +=
        "   ! Ceci est une alarme. Si vous ne comprenez pas le sens de cette\n"
        "   ! alarme, vous pouvez obtenir des resultats inattendus !\n";
    out += box;
    info(out);
}

void Messages::result(const std::string& text) {
    std::lock_guard lock(mutex_);
    resu_ += text;
    if (text.empty() || text.back() != '\n') resu_ += '\n';
    info(text);
}

void Messages::reset() {
    std::lock_guard lock(mutex_);
    mess_.clear();
    resu_.clear();
    alarms_ = 0;
    ignored_.clear();
    raised_.clear();
}

}  // namespace ma
