#pragma once
// PRIVATE to med_io: the only header that includes med.h. Never include it from a header that
// other libraries see (they do not get the MED/HDF5-OpenMPI include paths).
#include <med.h>

#include <string>

namespace ma::med {

// HDF5 prints its error stack on stderr by default; MED calls that fail are reported by us as
// UserError, so the spew is switched off once per process (OpenMPI HDF5 flavour: the one
// libmedC is linked with, see docs/med.md "One HDF5 in the process").
void silenceHdf5Errors();

// Checks that `path` is an existing, readable MED file before the MED library touches it
// (missing file, not HDF5, not MED): UserError naming the file otherwise.
void checkReadableMedFile(const std::string& path);

// While one lives, what the MED and HDF5 libraries print on stderr (fd 2) is captured; at the
// end it goes to the message log. Nested captures share the outermost one.
class StderrCapture {
public:
    StderrCapture();
    ~StderrCapture();
    StderrCapture(const StderrCapture&) = delete;
    StderrCapture& operator=(const StderrCapture&) = delete;
};

// The system cause HDF5 printed in the current capture, " (the HDF5 library reports: ...)", or "".
std::string libraryCause();
// UserError(text + libraryCause()).
[[noreturn]] void throwMedError(const std::string& text);

// Every object of the file opened with its dataspace, type and attributes (cheap: no data read):
// UserError "damaged: its object /ENS_MAA/.../FAM cannot be read" naming the first that fails.
void checkMedStructure(const std::string& path);

// An open MED file, closed by the destructor (every HDF5 object of the file on a failed close).
class MedFile {
public:
    MedFile(const std::string& path, med_access_mode mode);
    ~MedFile();
    MedFile(const MedFile&) = delete;
    MedFile& operator=(const MedFile&) = delete;
    med_idt id() const { return fid_; }
    const std::string& path() const { return path_; }
    // Closes now and reports a failure (the destructor cannot).
    void close();

private:
    StderrCapture capture_;
    std::string path_;
    med_idt fid_ = -1;
};

// Fixed-width, blank-padded MED name fields.
std::string trimName(const char* buffer, size_t width);
std::string padName(const std::string& name, size_t width);

}  // namespace ma::med
