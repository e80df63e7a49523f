#include "med_io/MedFileHandle.hpp"

#include <hdf5.h>

#include <filesystem>
#include <fstream>

#include "core/Error.hpp"

namespace ma::med {

void silenceHdf5Errors() {
    static const bool done = [] {
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
        return true;
    }();
    (void)done;
}

void checkReadableMedFile(const std::string& path) {
    namespace fs = std::filesystem;
    silenceHdf5Errors();
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
    if (h5 < 0)
        throw UserError("MED file '" + path + "' is damaged or truncated: HDF5 cannot open it");
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

MedFile::MedFile(const std::string& path, med_access_mode mode) : path_(path) {
    silenceHdf5Errors();
    fid_ = MEDfileOpen(path.c_str(), mode);
    if (fid_ < 0) {
        if (mode == MED_ACC_RDONLY)
            throw UserError("MED file '" + path + "' cannot be opened (truncated or corrupt file?)");
        throw UserError("MED file '" + path + "' cannot be opened for writing");
    }
}

MedFile::~MedFile() {
    if (fid_ >= 0) MEDfileClose(fid_);
}

void MedFile::close() {
    if (fid_ < 0) return;
    med_err rc = MEDfileClose(fid_);
    fid_ = -1;
    if (rc < 0) throw UserError("MED file '" + path_ + "': closing failed (disk full?)");
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
