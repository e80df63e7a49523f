#pragma once
// Shared helpers of the med_* / mesh_* tests: run the independent reader (meshio, h5py) and parse
// its text output.
#include <array>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace ma::test {

inline std::string runCommand(const std::string& cmd, int* status = nullptr) {
    std::string out;
    FILE* p = popen((cmd + " 2>&1").c_str(), "r");
    if (!p) throw std::runtime_error("cannot run " + cmd);
    char buf[65536];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
    int rc = pclose(p);
    if (status) *status = rc;
    else if (rc != 0) throw std::runtime_error("command failed: " + cmd + "\n" + out);
    return out;
}

inline std::string probeScript() { return std::string(MINIASTER_SOURCE_DIR) + "/tests/med_meshio_probe.py"; }
inline std::string astest(const std::string& file) { return std::string(MINIASTER_SHARED_DIR) + "/astest/" + file; }

// A fresh scratch folder per test.
inline std::string scratchDir(const std::string& name) {
    auto dir = std::filesystem::temp_directory_path() / ("miniaster_" + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

struct ProbeMesh {
    std::vector<std::array<double, 3>> nodes;
    std::vector<int> cellType;            // MED code
    std::vector<std::vector<int>> cells;  // MED node order, 0-based
    std::map<std::string, std::vector<int>> cellGroups, nodeGroups;
};

inline ProbeMesh probeMesh(const std::string& path) {
    std::istringstream in(runCommand("/usr/bin/python3 " + probeScript() + " dump '" + path + "'"));
    ProbeMesh m;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream ls(line);
        std::string kind;
        ls >> kind;
        if (kind == "node") {
            int i;
            std::array<double, 3> x{};
            ls >> i >> x[0] >> x[1] >> x[2];
            m.nodes.push_back(x);
        } else if (kind == "cell") {
            int i, code, v;
            ls >> i >> code;
            std::vector<int> row;
            while (ls >> v) row.push_back(v);
            m.cellType.push_back(code);
            m.cells.push_back(row);
        } else if (kind == "cellgroup" || kind == "nodegroup") {
            std::string name;
            int v;
            ls >> name;
            auto& target = kind == "cellgroup" ? m.cellGroups[name] : m.nodeGroups[name];
            while (ls >> v) target.push_back(v);
        } else {
            throw std::runtime_error("unexpected probe output: " + line);
        }
    }
    return m;
}

// Nodal field values read back by meshio: rows of components.
inline std::vector<std::vector<double>> probeField(const std::string& path, const std::string& name) {
    std::istringstream in(runCommand("/usr/bin/python3 " + probeScript() + " field '" + path + "' '" + name + "'"));
    std::string word;
    size_t rows = 0, cols = 0;
    in >> word >> rows >> cols;
    if (word != "shape") throw std::runtime_error("unexpected probe output for field " + name);
    std::vector<std::vector<double>> out(rows, std::vector<double>(cols));
    for (auto& r : out)
        for (auto& v : r) in >> v;
    return out;
}

}  // namespace ma::test
