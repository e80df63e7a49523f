#pragma once
// Results are written under a temporary name in their final folder and renamed only when complete
// and checked (every write, fsync and close), so that a failed, killed or interrupted run never
// leaves a half-written result and never replaces a previous one with an incomplete file.
//
// Temporary names: <final>.miniaster-tmp.<host>.<pid>. Every live temporary of the process is
// registered, so that an emergency stop (time limit, signal) removes them; those of dead runs
// (a process of this host that no longer exists) are recognised and removed by the next run.
#include <string>
#include <vector>

namespace ma {

// Write `content` to `path` atomically (temporary file in the same folder, then rename).
void writeFileAtomically(const std::string& path, const std::string& content);

// For files written by a library (MED): write to tempPath(), then commit() (fsync, rename). If
// commit() is not reached (exception), the destructor removes the temporary file.
class AtomicPath {
public:
    explicit AtomicPath(std::string finalPath);
    ~AtomicPath();
    AtomicPath(const AtomicPath&) = delete;
    AtomicPath& operator=(const AtomicPath&) = delete;
    const std::string& tempPath() const { return temp_; }
    const std::string& finalPath() const { return final_; }
    void commit();

private:
    std::string final_, temp_;
    bool committed_ = false;
};

// The temporary name of `finalPath` for this process.
std::string temporaryPathFor(const std::string& finalPath);
// Removes the temporaries of dead runs in `folder` (only those whose name starts with `stem`
// when given); returns the names removed.
std::vector<std::string> removeStaleTemporaries(const std::string& folder, const std::string& stem = {});
// Registers / forgets a temporary file or folder that removeLiveTemporaries() must remove.
void registerTemporary(const std::string& path);
void forgetTemporary(const std::string& path);
// Emergency stop: removes every registered temporary and blocks later registrations (the process
// is about to end).
void removeLiveTemporaries();

// The message of a failed system call: "<what> <path>: <strerror(errno)>".
std::string systemError(const std::string& what, const std::string& path, int error);

}  // namespace ma
