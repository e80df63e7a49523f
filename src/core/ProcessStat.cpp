#include "core/ProcessStat.hpp"

#include <fcntl.h>
#include <unistd.h>

namespace ma {

std::optional<std::string> processStatFields(int pid) {
    const std::string path = "/proc/" + std::to_string(pid) + "/stat";
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return std::nullopt;
    std::string text;
    char buffer[1024];
    for (ssize_t n; (n = ::read(fd, buffer, sizeof(buffer))) > 0;) text.append(buffer, size_t(n));
    ::close(fd);
    const auto end = text.rfind(')');  // the command name may hold spaces and parentheses
    if (end == std::string::npos || end + 2 > text.size()) return std::nullopt;
    return text.substr(end + 2);
}

}  // namespace ma
