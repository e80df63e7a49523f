#pragma once
// What the outputs of a run may not be, checked before anything is created or run:
// - a symbolic link (the run never writes through a link it did not create), a FIFO, a device or
//   a socket;
// - an input of the run (the command file, the .export, the mesh or another data file): compared
//   by real path (folders resolved, a symlinked folder included) and by device and inode (a hard
//   link, a file reached through another path);
// - another output of the run (F mess and F resu naming one file, two units naming one .rmed).
// And the lock of a case in its output folder: the .mess is opened without truncating it and
// locked (flock, released by the kernel when the process ends, however it ends); a second run of
// the same case there is refused, naming the process that holds it.
#include <string>
#include <vector>

namespace ma {

struct NamedPath {
    std::string path;
    std::string role;  // "message log", "command file", "data file of unit 20"...
};

// UserError naming both paths and why, at the first problem.
void checkOutputPaths(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs);

// The .mess opened for writing (created, or truncated once locked), its descriptor. UserError when
// it cannot be, or when another run holds it (its pid named).
int openLockedMessageLog(const std::string& path);

}  // namespace ma
