#pragma once
// Outputs are written under a temporary name and renamed when complete, so that an interrupted
// or failed run never leaves a half-written file behind.
#include <string>

namespace ma {

// Write `content` to `path` atomically (temporary file in the same folder, then rename).
void writeFileAtomically(const std::string& path, const std::string& content);

// For files written by a library (MED): write to tempPath(), then commit(). If commit() is not
// reached (exception), the destructor removes the temporary file.
class AtomicPath {
public:
    explicit AtomicPath(std::string finalPath);
    ~AtomicPath();
    AtomicPath(const AtomicPath&) = delete;
    AtomicPath& operator=(const AtomicPath&) = delete;
    const std::string& tempPath() const { return temp_; }
    void commit();

private:
    std::string final_, temp_;
    bool committed_ = false;
};

}  // namespace ma
