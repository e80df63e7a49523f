#include "parser/OutputGuard.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <vector>

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"

namespace fs = std::filesystem;

namespace ma {

namespace {

struct Identity {
    std::string real;                              // the real path (links resolved, the file itself may not exist)
    std::optional<std::pair<dev_t, ino_t>> inode;  // when the file exists
};

bool sameFile(const Identity& a, const Identity& b) { return a.real == b.real || (a.inode && a.inode == b.inode); }

// An output: its folder resolved, the file itself not followed; refused when it is a link or
// not a regular file.
Identity outputIdentity(const NamedPath& out) {
    std::error_code ec;
    const fs::path path(out.path);
    Identity id{(fs::weakly_canonical(path.parent_path(), ec) / path.filename()).string(), std::nullopt};
    struct stat st {};
    if (::lstat(out.path.c_str(), &st) != 0) return id;
    if (S_ISLNK(st.st_mode)) {
        const fs::path target = fs::read_symlink(path, ec);
        throw UserError(
            fmt::format("the {} {} is a symbolic link (to {}): the run does not write through a link it did not create "
                        "(the file it points to would be overwritten); remove the link or choose another output folder",
                        out.role, out.path, ec ? std::string("?") : target.string()));
    }
    if (S_ISDIR(st.st_mode)) throw UserError(fmt::format("the {} {} is a folder", out.role, out.path));
    if (!S_ISREG(st.st_mode))
        throw UserError(
            fmt::format("the {} {} exists and is not a regular file ({}): the run cannot write its "
                        "result there; remove it or choose another output folder",
                        out.role, out.path,
                        S_ISFIFO(st.st_mode)                         ? "a FIFO"
                        : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device"
                                                                     : "a socket"));
    id.inode = std::make_pair(st.st_dev, st.st_ino);
    return id;
}

// An input: every link resolved.
Identity inputIdentity(const NamedPath& in) {
    std::error_code ec;
    Identity id{fs::weakly_canonical(in.path, ec).string(), std::nullopt};
    if (ec) id.real = fs::absolute(in.path, ec).lexically_normal().string();
    struct stat st {};
    if (::stat(in.path.c_str(), &st) == 0) id.inode = std::make_pair(st.st_dev, st.st_ino);
    return id;
}

// The pid of the process holding a flock on the file (from /proc/locks), 0 when not found. The
// device is matched when it can be (a stacked file system may show another one than stat).
long lockHolder(int fd) {
    struct stat st {};
    if (::fstat(fd, &st) != 0) return 0;
    const std::string device = fmt::format("{:02x}:{:02x}:", major(st.st_dev), minor(st.st_dev));
    const std::string inode = fmt::format(":{}", st.st_ino);
    long sameInode = 0;
    std::ifstream locks("/proc/locks");
    for (std::string line; std::getline(locks, line);) {
        std::istringstream fields(line);
        std::vector<std::string> f;
        for (std::string w; fields >> w;) f.push_back(w);
        // "1: FLOCK  ADVISORY  WRITE 1234 08:01:5678 0 EOF" (a waiter's line has "->" after the number)
        if (f.size() < 6 || f[1] != "FLOCK" || !f[5].ends_with(inode)) continue;
        const long pid = std::strtol(f[4].c_str(), nullptr, 10);
        if (f[5] == fmt::format("{}{}", device, st.st_ino)) return pid;
        sameInode = pid;
    }
    return sameInode;
}

}  // namespace

void checkOutputPaths(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs) {
    std::vector<Identity> seen;
    for (size_t k = 0; k < outputs.size(); ++k) {
        const Identity id = outputIdentity(outputs[k]);
        for (size_t j = 0; j < seen.size(); ++j)
            if (sameFile(seen[j], id))
                throw UserError(
                    fmt::format("the {} {} and the {} {} are the same file ({}): one output would "
                                "overwrite the other; give them different names",
                                outputs[j].role, outputs[j].path, outputs[k].role, outputs[k].path, id.real));
        seen.push_back(id);
        for (const auto& in : inputs) {
            if (in.path.empty()) continue;
            if (sameFile(inputIdentity(in), id))
                throw UserError(
                    fmt::format("the {} {} is the {} {} (the same file: {}): the run would overwrite "
                                "its own input; choose another output folder or name",
                                outputs[k].role, outputs[k].path, in.role, in.path, id.real));
        }
    }
}

int openLockedMessageLog(const std::string& path) {
    // Not truncated before the lock is held (it may be another run's log); not followed if a link
    // appeared since the check; a FIFO put there since does not block the open.
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0666);
    if (fd < 0) throw UserError(systemError("cannot create the message log", path, errno));
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        throw UserError("the message log " + path + " is not a regular file");
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
        const int error = errno;
        const long holder = error == EWOULDBLOCK ? lockHolder(fd) : 0;
        ::close(fd);
        if (error != EWOULDBLOCK) throw UserError(systemError("cannot lock the message log", path, error));
        throw UserError(fmt::format(
            "another run of this case is writing in this output folder ({}, still running): its message log {} is "
            "locked; wait for it to end or choose another output folder (--out-dir)",
            holder > 0 ? fmt::format("process {}", holder) : std::string("a process of another machine or user"),
            path));
    }
    if (::ftruncate(fd, 0) != 0 || ::fcntl(fd, F_SETFL, 0) != 0) {
        const int error = errno;
        ::close(fd);
        throw UserError(systemError("cannot create the message log", path, error));
    }
    return fd;
}

}  // namespace ma
