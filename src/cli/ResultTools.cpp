#include "cli/ResultTools.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/VtuConversion.hpp"
#include "core/Error.hpp"

namespace fs = std::filesystem;

namespace ma::cli {

namespace {

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The plotting script: installed next to the binary (../share/miniaster) or in the checkout.
std::string plotScript() {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    const std::vector<fs::path> candidates = {exe.parent_path().parent_path() / "share" / "miniaster" / "plot.py",
                                              fs::path(MINIASTER_SOURCE_DIR) / "tools" / "plot" / "plot.py"};
    for (const auto& c : candidates)
        if (fs::is_regular_file(c)) return c.string();
    throw UserError("the plotting script plot.py is neither in " + candidates[0].string() + " nor in " +
                    candidates[1].string());
}

const char* const kConvertUsage =
    "usage: miniaster convert RESULT.rmed OUT.vtu    every field and step in one VTU file\n"
    "       miniaster convert RESULT.rmed OUT.pvd    a time series: OUT_<NUME_ORDRE>.vtu per step and the collection\n"
    "DEPL is a 3-component vector (DZ = 0 in 2D), ParaView's active vectors (Warp By Vector); its other\n"
    "components (H1X..., LAGS_C) are scalar arrays <field>_<component> (docs/visualisation.md).\n";

int failWith(const char* tool, const std::string& what, bool usage) {
    std::fprintf(stderr, "miniaster %s: %s\n", tool, what.c_str());
    if (usage) {
        std::fputs(tool == std::string("convert") ? kConvertUsage
                                                  : "usage: miniaster plot RESULT.rmed [--field NAME] [--component C] "
                                                    "[--deformed SCALE] [--step NUME_ORDRE] [--view AZIMUTH,ELEVATION] "
                                                    "[--clip X,Y,Z,NX,NY,NZ] -o OUT.png (--help: every option)\n",
                   stderr);
    }
    return 1;
}

}  // namespace

int convertMain(int argc, char** argv) {
    try {
        if (argc == 3 && (std::string(argv[2]) == "--help" || std::string(argv[2]) == "-h")) {
            std::fputs(kConvertUsage, stdout);
            return 0;
        }
        if (argc != 4) throw UsageError(argc < 4 ? "missing arguments" : "too many arguments");
        const std::string extension = fs::path(argv[3]).extension().string();
        if (extension != ".vtu" && extension != ".pvd")
            throw UsageError(std::string("the output file must end in .vtu (one file) or .pvd (a time series): ") +
                             argv[3]);
        for (const auto& line : convertResult(argv[2], argv[3])) std::printf("miniaster convert: %s\n", line.c_str());
        return 0;
    } catch (const UsageError& e) { return failWith("convert", e.what(), true); } catch (const std::exception& e) {
        return failWith("convert", e.what(), false);
    }
}

int plotMain(int argc, char** argv) {
    try {
        if (argc >= 3 && (std::string(argv[2]) == "--help" || std::string(argv[2]) == "-h")) {
            std::string python = "/usr/bin/python3", script = plotScript(), help = "--help";
            std::vector<char*> raw{python.data(), script.data(), help.data(), nullptr};
            ::execv(raw[0], raw.data());
            throw UserError(fmt::format("cannot start {}: {}", raw[0], std::strerror(errno)));
        }
        if (argc < 3 || argv[2][0] == '-') throw UsageError("missing RESULT.rmed");
        const std::string input = argv[2];
        const fs::path work = fs::temp_directory_path() / fmt::format("miniaster-plot-{}", getpid());
        fs::create_directories(work);
        const std::string vtuPath = (work / "result.vtu").string();
        try {
            convertResult(input, vtuPath);
        } catch (...) {
            fs::remove_all(work);
            throw;
        }
        std::vector<std::string> args = {"/usr/bin/python3", plotScript(), vtuPath, "--source", input,
                                         "--remove-folder",  work.string()};
        for (int i = 3; i < argc; ++i) args.push_back(argv[i]);
        std::vector<char*> raw;
        for (auto& a : args) raw.push_back(a.data());
        raw.push_back(nullptr);
        ::execv(raw[0], raw.data());
        fs::remove_all(work);
        throw UserError(fmt::format("cannot start {}: {}", raw[0], std::strerror(errno)));
    } catch (const UsageError& e) { return failWith("plot", e.what(), true); } catch (const std::exception& e) {
        return failWith("plot", e.what(), false);
    }
}

}  // namespace ma::cli
