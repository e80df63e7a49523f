#include "mesh/AsterMeshWriter.hpp"

#include <fmt/format.h>

#include <iterator>

namespace ma {
namespace {

// Fortran 1X,A8: a blank, then the name left-justified in 8 columns (a longer one written whole).
void a8(std::string& out, const std::string& s) { fmt::format_to(std::back_inserter(out), " {:<8}", s); }

// '(7(1X,A8))' lines of names.
void nameLines(std::string& out, const std::vector<std::string>& names, const std::vector<int>& members) {
    for (size_t i = 0; i < members.size(); ++i) {
        a8(out, names[size_t(members[i])]);
        if (i % 7 == 6 || i + 1 == members.size()) out += "\n";
    }
}

void endBlock(std::string& out) { out += " FINSF\n %\n"; }

// A cell: '(8(1X,A8))' with its name and 7 nodes, then '(9X,7(1X,A8))' for the next 7.
void cellLine(std::string& out, const Mesh& mesh, int cell) {
    a8(out, mesh.cellNames[size_t(cell)]);
    const auto nodes = mesh.cellNodes(cell);
    for (size_t i = 0; i < nodes.size(); ++i) {
        if (i > 0 && i % 7 == 0) out += "\n         ";
        a8(out, mesh.nodeNames[size_t(nodes[i])]);
    }
    out += "\n";
}

}  // namespace

std::string asterMeshText(const Mesh& mesh, const std::vector<std::string>& title) {
    std::string out = " TITRE\n";
    for (const auto& line : title) out += line + "\n";
    endBlock(out);
    out += mesh.dim == 3 ? " COOR_3D\n" : " COOR_2D\n";
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        a8(out, mesh.nodeNames[size_t(n)]);
        for (int j = 0; j < mesh.dim; ++j)
            fmt::format_to(std::back_inserter(out), " {:21.14E}", mesh.coords[size_t(n)][size_t(j)]);
        out += "\n";
    }
    bool open = false;
    for (int c = 0; c < mesh.cellCount(); ++c) {
        if (c == 0 || mesh.cellTypes[size_t(c)] != mesh.cellTypes[size_t(c - 1)]) {
            endBlock(out);  // closes the coordinates, then each block of cells of one type
            a8(out, cellTypeName(mesh.cellTypes[size_t(c)]));
            out += '\n';
            open = true;
        }
        cellLine(out, mesh, c);
    }
    if (open || mesh.cellCount() == 0) endBlock(out);
    for (const auto& g : mesh.nodeGroups.names()) {
        fmt::format_to(std::back_inserter(out), " GROUP_NO\n {}\n", g);
        nameLines(out, mesh.nodeNames, mesh.nodeGroups.get(g));
        endBlock(out);
    }
    for (const auto& g : mesh.cellGroups.names()) {
        fmt::format_to(std::back_inserter(out), " GROUP_MA\n {}\n", g);
        nameLines(out, mesh.cellNames, mesh.cellGroups.get(g));
        endBlock(out);
    }
    return out + " FIN\n";
}

}  // namespace ma
