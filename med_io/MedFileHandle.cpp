#include "med_io/MedFileHandle.hpp"
#include "med_io/MedLibrary.hpp"

#include <hdf5.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/Error.hpp"
#include "core/Messages.hpp"

namespace ma::med {

namespace {

// fd 2 redirected to a memory file while MED files are open (nested opens share it).
struct Capture {
    int depth = 0;
    int saved = -1, file = -1;
};
Capture gCapture;

std::string capturedText() {
    if (gCapture.file < 0) return {};
    std::fflush(stderr);
    const off_t size = ::lseek(gCapture.file, 0, SEEK_END);
    std::string text(size > 0 ? size_t(size) : 0, '\0');
    if (size > 0 && ::pread(gCapture.file, text.data(), text.size(), 0) != size) text.clear();
    return text;
}

}  // namespace

void silenceHdf5Errors() {
    static const bool done = [] {
        // HDF5's exit handler closes files left open and crashed on one whose close had failed
        // (disk full): every file is closed explicitly (MedFile), so it is not installed.
        H5dont_atexit();
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
        return true;
    }();
    (void)done;
}

void initialiseBeforeMpi() { silenceHdf5Errors(); }

StderrCapture::StderrCapture() {
    if (gCapture.depth++ > 0) return;
    std::fflush(stderr);
    gCapture.file = ::memfd_create("med-library-output", MFD_CLOEXEC);
    gCapture.saved = gCapture.file >= 0 ? ::dup(STDERR_FILENO) : -1;
    if (gCapture.saved < 0 || ::dup2(gCapture.file, STDERR_FILENO) < 0) {
        if (gCapture.file >= 0) ::close(gCapture.file);
        if (gCapture.saved >= 0) ::close(gCapture.saved);
        gCapture.file = gCapture.saved = -1;
    }
}

StderrCapture::~StderrCapture() {
    if (--gCapture.depth > 0 || gCapture.file < 0) return;
    const std::string text = capturedText();
    ::dup2(gCapture.saved, STDERR_FILENO);
    ::close(gCapture.saved);
    ::close(gCapture.file);
    gCapture.file = gCapture.saved = -1;
    if (text.empty()) return;
    // Kept in the log (the library's own words, partly French), never on the terminal.
    std::string block = "    output of the MED/HDF5 library (captured):\n";
    size_t lines = 0, at = 0;
    for (size_t next; at < text.size() && lines < 6; at = next + 1, ++lines) {
        next = text.find('\n', at);
        if (next == std::string::npos) next = text.size();
        block += "      " + text.substr(at, next - at) + "\n";
    }
    if (at < text.size()) block += "      ...\n";
    msg().info(block);
}

std::string libraryCause() {
    // errno of the failed write, before anything else can change it; only the errors of a write
    // (older values of other kinds would be stale).
    const int error = errno;
    const std::string text = capturedText();
    const std::string key = "error message = '";
    const auto at = text.find(key);
    const auto end = at == std::string::npos ? at : text.find('\'', at + key.size());
    if (end != std::string::npos)
        return " (the HDF5 library reports: " + text.substr(at + key.size(), end - at - key.size()) + ")";
    for (int writeError : {ENOSPC, EDQUOT, EFBIG, EIO, EROFS})
        if (error == writeError) return std::string(" (system error: ") + std::strerror(error) + ")";
    return {};
}

void throwMedError(const std::string& text) {
    const std::string cause = libraryCause();
    throw UserError(text + cause);
}

void checkReadableMedFile(const std::string& path) {
    namespace fs = std::filesystem;
    silenceHdf5Errors();
    StderrCapture capture;
    std::error_code ec;
    if (!fs::exists(path, ec)) throw UserError("MED file '" + path + "' does not exist");
    if (!fs::is_regular_file(path, ec)) throw UserError("MED file '" + path + "' is not a regular file");
    {
        std::ifstream probe(path, std::ios::binary);
        if (!probe) throw UserError("MED file '" + path + "' cannot be opened for reading (permissions?)");
    }
    if (H5Fis_hdf5(path.c_str()) <= 0)
        throw UserError("file '" + path + "' is not a MED file: it is not in HDF5 format");
    // A truncated file keeps its HDF5 signature but HDF5 refuses to open it (end of file before
    // the end address written in the superblock).
    const hid_t h5 = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (h5 < 0) throw UserError("MED file '" + path + "' is damaged or truncated: HDF5 cannot open it");
    // Every MED file has the group /INFOS_GENERALES (version numbers); checked here so that the
    // MED library does not print its own error messages on other HDF5 files.
    const bool hasMedHeader = H5Lexists(h5, "INFOS_GENERALES", H5P_DEFAULT) > 0;
    H5Fclose(h5);
    if (!hasMedHeader)
        throw UserError("file '" + path + "' is an HDF5 file but not a MED file (no MED header /INFOS_GENERALES)");
    med_bool hdfOk = MED_FALSE, medOk = MED_FALSE;
    if (MEDfileCompatibility(path.c_str(), &hdfOk, &medOk) < 0 || !hdfOk)
        throw UserError("MED file '" + path +
                        "' cannot be opened: the HDF5 structure is damaged (truncated or corrupt file?)");
    if (!medOk)
        throw UserError("file '" + path +
                        "' is an HDF5 file but not a MED file this MED library (4.x) can read "
                        "(no MED header, or a MED version older than 3.0 / newer than 4.x)");
}

namespace {

// Opens one object of the file and what describes it (dataspace and type of a dataset, every
// attribute): a damaged object header fails here rather than later as "no data".
herr_t checkObject(hid_t group, const char* name, const H5L_info_t* info, void* failedAt) {
    if (info->type != H5L_TYPE_HARD) return 0;
    auto fail = [&] {
        *static_cast<std::string*>(failedAt) = name;
        return herr_t(1);  // stops the visit
    };
    const hid_t object = H5Oopen(group, name, H5P_DEFAULT);
    if (object < 0) return fail();
    bool ok = true;
    H5O_info_t oinfo{};
    if (H5Oget_info2(object, &oinfo, H5O_INFO_BASIC | H5O_INFO_NUM_ATTRS) < 0) {
        ok = false;
    } else {
        if (oinfo.type == H5O_TYPE_DATASET) {
            const hid_t space = H5Dget_space(object), type = H5Dget_type(object);
            ok = space >= 0 && type >= 0 && H5Sget_simple_extent_npoints(space) >= 0;
            if (space >= 0) H5Sclose(space);
            if (type >= 0) H5Tclose(type);
        }
        for (hsize_t a = 0; ok && a < oinfo.num_attrs; ++a) {
            const hid_t attr =
                H5Aopen_by_idx(object, ".", H5_INDEX_CRT_ORDER, H5_ITER_NATIVE, a, H5P_DEFAULT, H5P_DEFAULT);
            ok = attr >= 0;
            if (attr >= 0) {
                const hid_t space = H5Aget_space(attr);
                ok = space >= 0;
                if (space >= 0) H5Sclose(space);
                H5Aclose(attr);
            }
        }
    }
    H5Oclose(object);
    return ok ? 0 : fail();
}

}  // namespace

namespace {

// The visit of every object; "" when all of them read, else the first that does not ("/" for a
// structure that cannot be read to its end).
std::string firstDamagedObject(const std::string& path) {
    const hid_t h5 = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (h5 < 0) return "/";
    std::string failedAt;
    const herr_t rc = H5Lvisit(h5, H5_INDEX_NAME, H5_ITER_NATIVE, checkObject, &failedAt);
    H5Fclose(h5);
    return failedAt.empty() && rc < 0 ? "/" : failedAt;
}

}  // namespace

// The visit runs in a child process: on some damaged object headers HDF5 itself crashes (a
// segmentation fault while it frees them at H5Fclose), which must end as a clear error, not as
// the end of the run. The child only reads the file and reports through a pipe.
void checkMedStructure(const std::string& path) {
    silenceHdf5Errors();
    StderrCapture capture;
    int fds[2];
    if (::pipe(fds) != 0)
        throw UserError("MED file '" + path + "': cannot check its structure (no pipe: " + std::strerror(errno) + ")");
    std::fflush(nullptr);
    const pid_t child = ::fork();
    if (child < 0) {
        ::close(fds[0]), ::close(fds[1]);
        throw UserError("MED file '" + path + "': cannot check its structure (fork: " + std::strerror(errno) + ")");
    }
    if (child == 0) {
        // The run's handlers (its fatal-signal paragraph, its stop signals) are the parent's.
        for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTERM, SIGINT, SIGHUP, SIGXCPU})
            std::signal(sig, SIG_DFL);
        ::close(fds[0]);
        const std::string failedAt = firstDamagedObject(path);
        const ssize_t written = ::write(fds[1], failedAt.data(), failedAt.size());
        ::_exit(written == ssize_t(failedAt.size()) ? 0 : 3);
    }
    ::close(fds[1]);
    std::string failedAt;
    char buffer[512];
    for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) != 0;) {
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) break;
        failedAt.append(buffer, size_t(n));
    }
    ::close(fds[0]);
    int status = 0;
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {}
    if (WIFSIGNALED(status))
        throw UserError("MED file '" + path + "' is damaged: the HDF5 library fails on its structure (signal " +
                        std::to_string(WTERMSIG(status)) + " while reading it)");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw UserError("MED file '" + path + "' is damaged: its structure cannot be read to the end");
    if (failedAt == "/") throw UserError("MED file '" + path + "' is damaged: its structure cannot be read to the end");
    if (!failedAt.empty())
        throw UserError("MED file '" + path + "' is damaged: its object /" + failedAt + " cannot be read");
}

MedFile::MedFile(const std::string& path, med_access_mode mode) : path_(path) {
    silenceHdf5Errors();
    fid_ = MEDfileOpen(path.c_str(), mode);
    if (fid_ < 0) {
        if (mode == MED_ACC_RDONLY)
            throw UserError("MED file '" + path + "' cannot be opened (truncated or corrupt file?)");
        throw UserError("MED file '" + path + "' cannot be opened for writing");
    }
}

// A failed MEDfileClose (disk full) is not retried: HDF5 1.10 leaves the file half-destroyed in its
// tables and a second H5Fclose crashes; with H5dont_atexit nothing touches it again either.
MedFile::~MedFile() {
    if (fid_ >= 0) MEDfileClose(fid_);
}

void MedFile::close() {
    if (fid_ < 0) return;
    const med_err rc = MEDfileClose(fid_);
    fid_ = -1;
    if (rc < 0) {
        const std::string cause = libraryCause();
        throw UserError("MED file '" + path_ + "': the file cannot be completed (closing failed" +
                        (cause.empty() ? ")" : ";" + cause.substr(1)));
    }
}

std::string trimName(const char* buffer, size_t width) {
    std::string s(buffer, width);
    auto end = s.find('\0');
    if (end != std::string::npos) s.resize(end);
    while (!s.empty() && (s.back() == ' ')) s.pop_back();
    return s;
}

std::string padName(const std::string& name, size_t width) {
    std::string s = name.substr(0, width);
    s.resize(width, ' ');
    return s;
}

}  // namespace ma::med
