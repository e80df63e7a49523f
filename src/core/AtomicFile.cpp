#include "core/AtomicFile.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <set>

#include <fmt/format.h>

#include "core/Error.hpp"

namespace fs = std::filesystem;

namespace ma {

namespace {

constexpr const char* kMarker = ".miniaster-tmp.";

std::string hostName() {
    char name[256] = {};
    if (::gethostname(name, sizeof(name) - 1) != 0) return "localhost";
    std::string host = name;
    host = host.substr(0, host.find('.'));  // the marker's fields are separated by dots
    return host.empty() ? "localhost" : host;
}

struct Registry {
    std::mutex mutex;
    std::set<std::string> paths;
};
Registry& registry() {
    static auto* r = new Registry();  // leaked: used until _exit
    return *r;
}

void writeAll(int fd, const std::string& path, const std::string& content) {
    const char* data = content.data();
    size_t left = content.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, data, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw UserError(systemError("cannot write", path, n < 0 ? errno : ENOSPC));
        data += n;
        left -= size_t(n);
    }
}

// Flushes a complete file to the disk: an error here (disk full on a delayed allocation, I/O
// error) would otherwise show only as a truncated file after a crash of the machine.
void syncFile(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw UserError(systemError("cannot reopen", path, errno));
    const bool ok = ::fsync(fd) == 0 || errno == EINVAL;  // EINVAL: a file system without fsync
    const int error = errno;
    ::close(fd);
    if (!ok) throw UserError(systemError("cannot write (fsync)", path, error));
}

}  // namespace

std::string systemError(const std::string& what, const std::string& path, int error) {
    return what + " " + path + ": " + std::strerror(error) +
           (error == ENOSPC  ? " (the disk is full)"
            : error == EFBIG ? " (file size limit of the process)"
                             : "");
}

std::string temporaryPathFor(const std::string& finalPath) {
    static const std::string suffix = kMarker + hostName() + "." + std::to_string(::getpid());
    // A name near the file system's limit (255 bytes) has no room for the suffix: its head and a
    // hash of the whole name instead (still unique, still recognised as a temporary).
    const fs::path path(finalPath);
    const std::string name = path.filename().string();
    constexpr size_t kNameMax = 255;
    if (name.size() + suffix.size() <= kNameMax) return finalPath + suffix;
    const std::string hash = fmt::format("{:016x}", std::hash<std::string>{}(name));
    const std::string head = name.substr(0, kNameMax - suffix.size() - hash.size() - 1);
    return (path.parent_path() / (head + "." + hash + suffix)).string();
}

void registerTemporary(const std::string& path) {
    auto& r = registry();
    std::lock_guard lock(r.mutex);
    r.paths.insert(path);
}

void forgetTemporary(const std::string& path) {
    auto& r = registry();
    std::lock_guard lock(r.mutex);
    r.paths.erase(path);
}

void removeLiveTemporaries() {
    auto& r = registry();
    r.mutex.lock();  // never released: no temporary may be created after this point
    for (const auto& p : r.paths) {
        std::error_code ec;
        fs::remove_all(p, ec);
    }
    r.paths.clear();
}

std::vector<std::string> removeStaleTemporaries(const std::string& folder, const std::string& stem) {
    std::vector<std::string> removed;
    const std::string ours = kMarker + hostName() + ".";
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        const auto at = name.rfind(ours);
        if (at == std::string::npos || at == 0 || !name.starts_with(stem)) continue;
        const std::string pidText = name.substr(at + ours.size());
        if (pidText.empty() || pidText.find_first_not_of("0123456789") != std::string::npos || pidText.size() > 9)
            continue;
        const pid_t pid = pid_t(std::stol(pidText));
        if (pid == ::getpid() || ::kill(pid, 0) == 0 || errno != ESRCH) continue;  // alive (or not ours to judge)
        std::error_code rmError;
        if (fs::remove_all(it->path(), rmError) > 0) removed.push_back(name);
    }
    return removed;
}

AtomicPath::AtomicPath(std::string finalPath) : final_(std::move(finalPath)) {
    temp_ = temporaryPathFor(final_);
    registerTemporary(temp_);
    std::error_code ec;
    fs::remove(temp_, ec);
}

AtomicPath::~AtomicPath() {
    if (!committed_) {
        std::error_code ec;
        fs::remove(temp_, ec);
    }
    forgetTemporary(temp_);
}

void AtomicPath::commit() {
    syncFile(temp_);
    if (::rename(temp_.c_str(), final_.c_str()) != 0)
        throw UserError("cannot rename " + temp_ + " to " + final_ + ": " + std::strerror(errno));
    committed_ = true;
}

void writeFileAtomically(const std::string& path, const std::string& content) {
    AtomicPath out(path);
    const int fd = ::open(out.tempPath().c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) throw UserError(systemError("cannot create", out.tempPath(), errno));
    try {
        writeAll(fd, out.tempPath(), content);
        if (::fsync(fd) != 0 && errno != EINVAL)
            throw UserError(systemError("cannot write (fsync)", out.tempPath(), errno));
    } catch (...) {
        ::close(fd);
        throw;
    }
    if (::close(fd) != 0) throw UserError(systemError("cannot write (close)", out.tempPath(), errno));
    out.commit();
}

}  // namespace ma
