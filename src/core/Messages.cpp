#include "core/Messages.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>

namespace ma {

Messages& Messages::instance() {
    static Messages m;
    return m;
}

bool Messages::streamIsTheLog() const {
    struct stat st {};
    return ::fstat(fd_, &st) == 0 && st.st_dev == dev_ && st.st_ino == ino_;
}

// The command file closed the log's descriptor (its number may now be one of its own files): the
// log is opened again by its path, locked again (the lock may have gone with the descriptor).
void Messages::reopenStream() {
    const int fd = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_NOFOLLOW | O_CLOEXEC);
    struct stat st {};
    if (fd < 0 || ::fstat(fd, &st) != 0 || st.st_dev != dev_ || st.st_ino != ino_) {
        if (fd >= 0) ::close(fd);
        streamError_ = EBADF;
        return;
    }
    ::flock(fd, LOCK_EX | LOCK_NB);
    fd_ = fd;
    const std::string note =
        "\n <I> the descriptor of the message log was closed by the command file: the log is opened again at its end "
        "(nothing written before is lost)\n";
    [[maybe_unused]] const ssize_t n = ::write(fd_, note.data(), note.size());
}

void Messages::write(const std::string& text) {
    if (fd_ < 0 || streamError_ || ::getpid() != owner_) return;
    if (!path_.empty() && !streamIsTheLog()) reopenStream();
    if (streamError_) return;
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

void Messages::streamTo(int fd, const std::string& path) {
    std::lock_guard lock(mutex_);
    fd_ = fd;
    path_ = path;
    owner_ = ::getpid();
    struct stat st {};
    if (fd >= 0 && ::fstat(fd, &st) == 0) {
        dev_ = st.st_dev;
        ino_ = st.st_ino;
    }
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
    if (echo_ && frozen_ && ::poll(&out, 1, 0) == 1 && (out.revents & POLLOUT)) {
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
}

}  // namespace ma
