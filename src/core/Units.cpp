#include "core/Units.hpp"

#include <sys/stat.h>

#include "core/Error.hpp"

namespace ma {

std::string Units::input(int unit) const {
    auto it = inputs_.find(unit);
    if (it == inputs_.end())
        throw UserError("logical unit " + std::to_string(unit) +
                        " is not associated with any file (add an F line with unit " + std::to_string(unit) +
                        " to the .export, or use --mesh)");
    return it->second;
}

std::string Units::output(int unit) const {
    auto it = outputs_.find(unit);
    if (it != outputs_.end()) return it->second;
    auto data = inputs_.find(unit);
    if (data != inputs_.end())
        throw UserError("logical unit " + std::to_string(unit) + " is the data file " + data->second +
                        ": a result cannot be written on it (choose another UNITE, or declare the unit as a "
                        "result with an F ... R line)");
    const std::string path = outDir_ + "/fort." + std::to_string(unit);
    struct stat st {};
    if (::lstat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
        throw UserError("the result file " + path + " of logical unit " + std::to_string(unit) + " is " +
                        (S_ISLNK(st.st_mode)
                             ? "a symbolic link: the run does not write through a link it did not create"
                             : "not a regular file (a folder, a FIFO, a device or a socket)") +
                        "; remove it or choose another output folder");
    return path;
}

}  // namespace ma
