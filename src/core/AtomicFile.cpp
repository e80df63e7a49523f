#include "core/AtomicFile.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/Error.hpp"

namespace ma {

AtomicPath::AtomicPath(std::string finalPath) : final_(std::move(finalPath)) {
    temp_ = final_ + ".tmp" + std::to_string(::getpid());
    std::error_code ec;
    std::filesystem::remove(temp_, ec);
}

AtomicPath::~AtomicPath() {
    if (!committed_) {
        std::error_code ec;
        std::filesystem::remove(temp_, ec);
    }
}

void AtomicPath::commit() {
    std::error_code ec;
    std::filesystem::rename(temp_, final_, ec);
    if (ec) throw UserError("cannot rename " + temp_ + " to " + final_ + ": " + ec.message());
    committed_ = true;
}

void writeFileAtomically(const std::string& path, const std::string& content) {
    AtomicPath out(path);
    {
        std::ofstream f(out.tempPath(), std::ios::binary);
        if (!f) throw UserError("cannot open " + out.tempPath() + " for writing");
        f << content;
        f.flush();
        if (!f) throw UserError("cannot write " + out.tempPath());
    }
    out.commit();
}

}  // namespace ma
