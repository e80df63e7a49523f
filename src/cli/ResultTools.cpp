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

#include "core/Error.hpp"
#include "med_io/MedResultReader.hpp"
#include "post/VtuWriter.hpp"

namespace fs = std::filesystem;

namespace ma::cli {

namespace {

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Array name of one step: the MED field name, with @NUME_ORDRE when the field has several steps.
std::string stepName(const med::MedField& field, const med::MedFieldStep& step) {
    return field.steps.size() > 1 ? fmt::format("{}@{}", field.name, step.numdt) : field.name;
}

vtu::DataArray nodalArray(const std::string& name, const NodalField& f) {
    vtu::DataArray a{name, f.components, std::vector<double>(f.values.size(), kNoValue)};
    for (size_t i = 0; i < f.values.size(); ++i)
        if (f.present[i]) a.values[i] = f.values[i];
    return a;
}

// Values at points (ELGA/ELNO) as one tuple per cell: the mean over the cell's points (as
// code_aster's GMSH output does); NaN on cells without values.
vtu::DataArray cellMeanArray(const std::string& name, const GaussField& g, int cellCount) {
    const size_t nc = g.components.size();
    vtu::DataArray a{name, g.components, std::vector<double>(size_t(cellCount) * nc, kNoValue)};
    for (size_t e = 0; e < g.cells.size(); ++e) {
        const int first = g.pointOffsets[e], last = g.pointOffsets[e + 1];
        for (size_t c = 0; c < nc; ++c) {
            double sum = 0;
            for (int p = first; p < last; ++p) sum += g.values[size_t(p) * nc + c];
            a.values[size_t(g.cells[e]) * nc + c] = last > first ? sum / (last - first) : kNoValue;
        }
    }
    return a;
}

std::vector<vtu::DataArray> groupArrays(const GroupSet& groups, int count, const std::string& prefix) {
    std::vector<vtu::DataArray> out;
    for (const auto& name : groups.names()) {
        vtu::DataArray a{prefix + name, {name}, std::vector<double>(size_t(count), 0.0), true};
        for (int member : groups.get(name)) a.values[size_t(member)] = 1.0;
        out.push_back(std::move(a));
    }
    return out;
}

// One mesh of the file and its fields -> one .vtu; returns a one-line summary.
std::string convertMesh(const med::MedResultMesh& m, const std::string& path) {
    std::vector<vtu::DataArray> pointData = groupArrays(m.mesh->nodeGroups, m.mesh->nodeCount(), "GROUP_NO:");
    std::vector<vtu::DataArray> cellData = groupArrays(m.mesh->cellGroups, m.mesh->cellCount(), "GROUP_MA:");
    std::vector<std::string> names;
    for (const auto& field : m.fields) {
        for (const auto& step : field.steps) {
            const std::string name = stepName(field, step);
            if (step.nodal) pointData.push_back(nodalArray(name, *step.nodal));
            if (step.cellPoints) cellData.push_back(cellMeanArray(name, *step.cellPoints, m.mesh->cellCount()));
            names.push_back(fmt::format("{} ({}, INST {})", name, step.nodal ? "nodes" : "cells", step.dt));
        }
    }
    vtu::write(path, *m.mesh, pointData, cellData);
    std::string fields;
    for (const auto& n : names) fields += (fields.empty() ? "" : ", ") + n;
    return fmt::format("{}: mesh {} ({} nodes, {} cells, {} groups); fields: {}", path, m.name, m.mesh->nodeCount(),
                       m.mesh->cellCount(), m.mesh->nodeGroups.size() + m.mesh->cellGroups.size(),
                       fields.empty() ? "none" : fields);
}

// Every mesh that carries fields (or the first mesh when none does): OUT.vtu for the first,
// OUT_<mesh>.vtu for the others.
std::vector<std::string> convert(const std::string& input, const std::string& output) {
    if (fs::path(output).extension() != ".vtu") throw UsageError("the output file must end in .vtu: " + output);
    const auto meshes = med::readResults(input);
    std::vector<const med::MedResultMesh*> chosen;
    for (const auto& m : meshes)
        if (!m.fields.empty()) chosen.push_back(&m);
    if (chosen.empty() && !meshes.empty()) chosen.push_back(&meshes.front());
    if (chosen.empty()) throw UserError("MED file '" + input + "' holds no mesh");
    std::vector<std::string> lines;
    for (size_t i = 0; i < chosen.size(); ++i) {
        fs::path path = output;
        if (i > 0) path.replace_filename(path.stem().string() + "_" + chosen[i]->name + ".vtu");
        lines.push_back(convertMesh(*chosen[i], path.string()));
    }
    return lines;
}

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

int failWith(const char* tool, const std::string& what, bool usage) {
    std::fprintf(stderr, "miniaster %s: %s\n", tool, what.c_str());
    if (usage) {
        std::fputs(tool == std::string("convert") ? "usage: miniaster convert RESULT.rmed OUT.vtu\n"
                                                  : "usage: miniaster plot RESULT.rmed [--field NAME] [--component C] "
                                                    "[--deformed SCALE] [--step NUME_ORDRE] -o OUT.png\n",
                   stderr);
    }
    return 1;
}

}  // namespace

int convertMain(int argc, char** argv) {
    try {
        if (argc != 4) throw UsageError(argc < 4 ? "missing arguments" : "too many arguments");
        for (const auto& line : convert(argv[2], argv[3])) std::printf("miniaster convert: %s\n", line.c_str());
        return 0;
    } catch (const UsageError& e) { return failWith("convert", e.what(), true); } catch (const std::exception& e) {
        return failWith("convert", e.what(), false);
    }
}

int plotMain(int argc, char** argv) {
    try {
        if (argc < 3 || argv[2][0] == '-') throw UsageError("missing RESULT.rmed");
        const std::string input = argv[2];
        const fs::path work = fs::temp_directory_path() / fmt::format("miniaster-plot-{}", getpid());
        fs::create_directories(work);
        const std::string vtuPath = (work / "result.vtu").string();
        try {
            convert(input, vtuPath);
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
