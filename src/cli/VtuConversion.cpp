#include "cli/VtuConversion.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <limits>
#include <map>
#include <utility>

#include "core/Error.hpp"
#include "med_io/MedResultReader.hpp"
#include "post/VtuWriter.hpp"

namespace fs = std::filesystem;

namespace ma::cli {

namespace {

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

bool isDisplacementLike(const NodalField& f) { return f.componentIndex("DX") >= 0 && f.componentIndex("DY") >= 0; }

// The arrays of one nodal field at one step; `suffix` is "@<NUME_ORDRE>" or "".
// A displacement-like field: the vector (DX, DY, DZ) named as the field, DZ = 0 where the node
// carries DX and the field has no DZ (2D), then one scalar array per other component. Any other
// field: one array with all its components. NaN where a node carries no value.
std::vector<vtu::DataArray> nodalArrays(const std::string& field, const std::string& suffix, const NodalField& f) {
    const size_t n = f.present.size() / std::max<size_t>(f.components.size(), 1);
    auto value = [&](size_t node, int c) { return f.has(int(node), c) ? f.at(int(node), c) : kNoValue; };
    if (!isDisplacementLike(f)) {
        vtu::DataArray a{field + suffix, f.components, std::vector<double>(f.values.size(), kNoValue)};
        for (size_t i = 0; i < f.values.size(); ++i)
            if (f.present[i]) a.values[i] = f.values[i];
        return {a};
    }
    const int dx = f.componentIndex("DX"), dy = f.componentIndex("DY"), dz = f.componentIndex("DZ");
    vtu::DataArray vector{field + suffix, {"DX", "DY", "DZ"}, std::vector<double>(n * 3, kNoValue)};
    for (size_t node = 0; node < n; ++node) {
        vector.values[3 * node] = value(node, dx);
        vector.values[3 * node + 1] = value(node, dy);
        vector.values[3 * node + 2] = dz >= 0 ? value(node, dz) : (f.has(int(node), dx) ? 0.0 : kNoValue);
    }
    std::vector<vtu::DataArray> out{vector};
    for (int c = 0; c < f.componentCount(); ++c) {
        if (c == dx || c == dy || c == dz) continue;
        const std::string& name = f.components[size_t(c)];
        vtu::DataArray scalar{field + "_" + name + suffix, {name}, std::vector<double>(n, kNoValue)};
        for (size_t node = 0; node < n; ++node) scalar.values[node] = value(node, c);
        out.push_back(std::move(scalar));
    }
    return out;
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

// The arrays of one file: the groups, then the given steps of the fields.
struct FileArrays {
    std::vector<vtu::DataArray> points, cells;
    std::string activeVectors;
    std::vector<std::string> described;  // "NAME (nodes, INST t)"

    FileArrays(const Mesh& mesh)
        : points(groupArrays(mesh.nodeGroups, mesh.nodeCount(), "GROUP_NO:")),
          cells(groupArrays(mesh.cellGroups, mesh.cellCount(), "GROUP_MA:")) {}

    void add(const med::MedField& field, const med::MedFieldStep& step, const std::string& suffix, const Mesh& mesh) {
        const std::string name = field.name + suffix;
        if (step.nodal) {
            auto arrays = nodalArrays(field.name, suffix, *step.nodal);
            // DEPL moves the mesh (the last step's in a single file); another vector only while none does
            // (a DEPL field after it takes over).
            if (isDisplacementLike(*step.nodal) && (field.name.ends_with("DEPL") || activeVectors.empty()))
                activeVectors = name;
            for (auto& a : arrays) points.push_back(std::move(a));
        }
        if (step.cellPoints) cells.push_back(cellMeanArray(name, *step.cellPoints, mesh.cellCount()));
        described.push_back(fmt::format("{} ({}, INST {})", name, step.nodal ? "nodes" : "cells", step.dt));
    }

    std::string fieldList() const {
        std::string out;
        for (const auto& d : described) out += (out.empty() ? "" : ", ") + d;
        return out.empty() ? "none" : out;
    }
};

std::string meshSummary(const med::MedResultMesh& m) {
    return fmt::format("mesh {} ({} nodes, {} cells, {} groups)", m.name, m.mesh->nodeCount(), m.mesh->cellCount(),
                       m.mesh->nodeGroups.size() + m.mesh->cellGroups.size());
}

// One .vtu: every step of every field (NAME@NUME_ORDRE when a field has several steps).
std::string writeSingleFile(const med::MedResultMesh& m, const fs::path& path) {
    FileArrays arrays(*m.mesh);
    size_t maxSteps = 0;
    for (const auto& field : m.fields) {
        maxSteps = std::max(maxSteps, field.steps.size());
        for (const auto& step : field.steps)
            arrays.add(field, step, field.steps.size() > 1 ? fmt::format("@{}", step.numdt) : "", *m.mesh);
    }
    vtu::write(path.string(), *m.mesh, arrays.points, arrays.cells, arrays.activeVectors);
    std::string line = fmt::format("{}: {}; fields: {}", path.string(), meshSummary(m), arrays.fieldList());
    if (maxSteps > 1)
        line += fmt::format(" ({} steps in one file; {} gives ParaView a time series)", maxSteps,
                            fs::path(path).replace_extension(".pvd").string());
    return line;
}

// A time series: <stem>_<NUME_ORDRE>.vtu per step beside the .pvd, then the .pvd.
std::string writeCollection(const med::MedResultMesh& m, const fs::path& pvd) {
    std::map<std::pair<int, int>, double> steps;  // (numdt, numit) -> INST
    for (const auto& field : m.fields)
        for (const auto& step : field.steps) steps.emplace(std::pair{step.numdt, step.numit}, step.dt);
    if (steps.empty()) steps.emplace(std::pair{0, 0}, 0.0);  // the mesh alone
    std::map<int, int> sameNumdt;  // MED's iteration number joins the name only where NUME_ORDRE repeats
    for (const auto& [key, inst] : steps) ++sameNumdt[key.first];
    std::vector<vtu::CollectionStep> written;
    std::string fields;
    for (const auto& [key, inst] : steps) {
        FileArrays arrays(*m.mesh);
        for (const auto& field : m.fields)
            for (const auto& step : field.steps)
                if (std::pair{step.numdt, step.numit} == key) arrays.add(field, step, "", *m.mesh);
        const std::string name = fmt::format("{}_{}{}.vtu", pvd.stem().string(), key.first,
                                             sameNumdt[key.first] > 1 ? fmt::format(".{}", key.second) : "");
        vtu::write((pvd.parent_path() / name).string(), *m.mesh, arrays.points, arrays.cells, arrays.activeVectors);
        written.push_back({inst, name});
        fields += fmt::format("{}{} (INST {}): {}", fields.empty() ? "" : "; ", name, inst, arrays.fieldList());
    }
    vtu::writeCollection(pvd.string(), written);
    return fmt::format("{}: {}; {} step(s): {}", pvd.string(), meshSummary(m), written.size(), fields);
}

}  // namespace

std::vector<std::string> convertResult(const std::string& input, const std::string& output) {
    const std::string extension = fs::path(output).extension().string();
    if (extension != ".vtu" && extension != ".pvd")
        throw UserError("the output file must end in .vtu (one file) or .pvd (a time series): " + output);
    const auto meshes = med::readResults(input);
    std::vector<const med::MedResultMesh*> chosen;
    for (const auto& m : meshes)
        if (!m.fields.empty()) chosen.push_back(&m);
    if (chosen.empty() && !meshes.empty()) chosen.push_back(&meshes.front());
    if (chosen.empty()) throw UserError("MED file '" + input + "' holds no mesh");
    std::vector<std::string> lines;
    for (size_t i = 0; i < chosen.size(); ++i) {
        fs::path path = fs::path(output).lexically_normal();
        if (i > 0) path.replace_filename(path.stem().string() + "_" + chosen[i]->name + extension);
        lines.push_back(extension == ".pvd" ? writeCollection(*chosen[i], path) : writeSingleFile(*chosen[i], path));
    }
    return lines;
}

}  // namespace ma::cli
