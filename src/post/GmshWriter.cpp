#include "post/GmshWriter.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <map>

#include "core/Error.hpp"

namespace ma::gmsh {

namespace {

// The written (linear) cell kinds in the order of the file's count lines and records; version 1.0
// has only the first four (points, lines, triangles, tetrahedra).
enum Kind { kPoint, kLine, kTriangle, kQuad, kTetra, kHexa, kPrism, kPyramid, kKinds };

struct Piece {
    Kind kind;
    std::vector<int> nodes;  // local (0-based) nodes of the parent cell
};
using Split = std::vector<Piece>;

Split pieces(Kind kind, std::initializer_list<std::initializer_list<int>> oneBased) {
    Split out;
    for (const auto& p : oneBased) {
        Piece piece{kind, {}};
        for (int n : p) piece.nodes.push_back(n - 1);
        out.push_back(std::move(piece));
    }
    return out;
}

Split whole(Kind kind, int n) {
    Piece p{kind, {}};
    for (int i = 0; i < n; ++i) p.nodes.push_back(i);
    return {p};
}

// code_aster's irgmtb: what each cell becomes, in code_aster's node numbering (empty: not written).
Split splitOf(CellType t, int version) {
    const bool v12 = version == 2;
    switch (t) {
        case CellType::POI1: return whole(kPoint, 1);
        case CellType::SEG2: return whole(kLine, 2);
        case CellType::SEG3: return pieces(kLine, {{1, 3}, {3, 2}});
        case CellType::SEG4: return pieces(kLine, {{1, 3}, {3, 4}, {4, 2}});
        case CellType::TRIA3: return whole(kTriangle, 3);
        case CellType::TRIA6:
        case CellType::TRIA7: return pieces(kTriangle, {{1, 4, 6}, {4, 2, 5}, {5, 3, 6}, {4, 5, 6}});
        case CellType::QUAD4: return v12 ? whole(kQuad, 4) : pieces(kTriangle, {{1, 2, 3}, {1, 3, 4}});
        case CellType::QUAD8:
        case CellType::QUAD9:
            return pieces(kTriangle, {{1, 5, 8}, {5, 2, 6}, {6, 3, 7}, {7, 4, 8}, {5, 7, 8}, {5, 6, 7}});
        case CellType::TETRA4: return whole(kTetra, 4);
        case CellType::TETRA10:
            return pieces(kTetra, {{1, 5, 7, 8},
                                   {2, 9, 6, 5},
                                   {3, 6, 7, 10},
                                   {4, 8, 9, 10},
                                   {6, 7, 9, 5},
                                   {7, 8, 9, 5},
                                   {7, 8, 9, 10},
                                   {6, 7, 9, 10}});
        case CellType::PENTA6:
            return v12 ? whole(kPrism, 6) : pieces(kTetra, {{1, 2, 3, 5}, {1, 3, 6, 5}, {1, 6, 4, 5}});
        case CellType::PYRA5: return v12 ? whole(kPyramid, 5) : pieces(kTetra, {{1, 2, 4, 5}, {2, 3, 4, 5}});
        case CellType::HEXA8:
            return v12 ? whole(kHexa, 8)
                       : pieces(kTetra,
                                {{1, 2, 3, 5}, {2, 3, 5, 7}, {6, 2, 5, 7}, {1, 4, 3, 7}, {1, 7, 4, 8}, {8, 5, 1, 7}});
        case CellType::PENTA15:
            return pieces(kTetra, {{4, 10, 13, 15},
                                   {1, 7, 9, 13},
                                   {1, 9, 15, 13},
                                   {1, 15, 10, 13},
                                   {5, 11, 13, 14},
                                   {2, 7, 8, 13},
                                   {2, 8, 14, 13},
                                   {2, 14, 11, 13},
                                   {6, 14, 15, 12},
                                   {14, 13, 15, 12},
                                   {3, 8, 14, 7},
                                   {3, 14, 13, 7},
                                   {3, 13, 9, 7},
                                   {3, 14, 12, 15},
                                   {3, 14, 13, 15},
                                   {2, 13, 15, 9}});
        case CellType::PENTA18:
            return pieces(kTetra,
                          {{1, 7, 9, 16},    {1, 9, 18, 16},   {1, 18, 10, 16},  {7, 8, 9, 17},    {7, 9, 18, 17},
                           {7, 18, 16, 17},  {9, 8, 3, 17},    {9, 3, 12, 17},   {9, 12, 18, 17},  {7, 2, 8, 11},
                           {7, 8, 17, 11},   {7, 17, 16, 11},  {10, 16, 18, 13}, {10, 18, 15, 13}, {10, 15, 4, 13},
                           {16, 17, 18, 14}, {16, 18, 15, 14}, {16, 15, 13, 14}, {18, 17, 12, 14}, {18, 12, 6, 14},
                           {18, 6, 15, 14},  {16, 11, 17, 5},  {16, 17, 14, 5},  {16, 14, 13, 5}});
        case CellType::HEXA20:
            return pieces(kTetra,
                          {{1, 9, 12, 13},   {2, 10, 14, 9},   {3, 15, 11, 10},  {4, 11, 12, 16},  {7, 19, 18, 15},
                           {6, 18, 17, 14},  {5, 20, 17, 13},  {9, 12, 13, 20},  {9, 17, 16, 20},  {17, 9, 13, 20},
                           {9, 11, 12, 16},  {9, 11, 16, 17},  {11, 19, 16, 17}, {16, 19, 20, 17}, {9, 14, 11, 17},
                           {14, 11, 17, 19}, {9, 10, 11, 14},  {10, 11, 14, 19}, {18, 10, 14, 19}, {18, 14, 17, 19},
                           {10, 15, 11, 19}, {15, 10, 18, 19}, {8, 19, 20, 16},  {12, 9, 16, 20}});
        case CellType::HEXA27:
            return pieces(kTetra,
                          {{9, 2, 14, 10},   {9, 14, 23, 10},  {9, 23, 21, 10},  {9, 14, 22, 23},  {9, 22, 27, 23},
                           {9, 27, 21, 23},  {1, 9, 22, 21},   {1, 22, 27, 21},  {1, 27, 12, 21},  {1, 22, 13, 27},
                           {1, 13, 25, 27},  {1, 25, 12, 27},  {22, 14, 6, 23},  {22, 6, 18, 23},  {22, 18, 27, 23},
                           {22, 6, 17, 18},  {22, 17, 26, 18}, {22, 26, 27, 18}, {13, 22, 17, 27}, {13, 17, 26, 27},
                           {13, 26, 25, 27}, {13, 17, 5, 26},  {13, 5, 20, 26},  {13, 20, 25, 26}, {21, 10, 23, 3},
                           {21, 23, 15, 3},  {21, 15, 11, 3},  {21, 23, 27, 15}, {21, 27, 24, 15}, {21, 24, 11, 15},
                           {12, 21, 27, 11}, {12, 27, 24, 11}, {12, 24, 4, 11},  {12, 27, 25, 24}, {12, 25, 16, 24},
                           {12, 16, 4, 24},  {27, 23, 18, 15}, {27, 18, 7, 15},  {27, 7, 24, 15},  {27, 18, 26, 7},
                           {27, 26, 19, 7},  {27, 19, 24, 7},  {25, 27, 26, 24}, {25, 26, 19, 24}, {25, 19, 16, 24},
                           {25, 26, 20, 19}, {25, 20, 8, 19},  {25, 8, 16, 19}});
        default: return {};  // PYRA13: not written by code_aster either
    }
}

// Tensor values of a node on a written cell: code_aster's irgnte, by position XX YY ZZ XY XZ YZ;
// cells of the plane kinds get [[1,4,0],[4,2,0],[0,0,3]]. (code_aster writes no tensor values on
// POI1 and TETRA4 cells, which makes its file unreadable; miniaster writes the volume layout there.)
std::array<double, 9> tensorOf(const double* t, Kind kind) {
    const bool plane = kind == kLine || kind == kTriangle || kind == kQuad;
    const double xz = plane ? 0.0 : t[4], yz = plane ? 0.0 : t[5];
    return {t[0], t[3], xz, t[3], t[1], yz, xz, yz, t[2]};
}

void appendRecord(std::string& out, const Mesh& mesh, const View& v, int cell, const Piece& piece) {
    const auto nodes = mesh.cellNodes(cell);
    std::vector<int> ids;
    for (int local : piece.nodes) ids.push_back(nodes[size_t(local)]);
    for (int axis = 0; axis < 3; ++axis) {  // x of every node, then y, then z; 4 numbers a line
        for (size_t i = 0; i < ids.size(); ++i) {
            out += fortranE(mesh.coords[size_t(ids[i])][size_t(axis)]);
            if (i % 4 == 3 || i + 1 == ids.size()) out += '\n';
        }
    }
    const int raw = v.rawComponents();
    for (const auto& step : v.steps) {
        for (int id : ids) {  // one node a line (a tensor: its 9 values)
            const double* t = step.data() + size_t(v.perCell ? cell : id) * size_t(raw);
            if (v.kind == ViewKind::Tensor) {
                for (double x : tensorOf(t, piece.kind)) out += fortranE(x);
            } else {
                for (int c = 0; c < raw; ++c) out += fortranE(t[c]);
            }
            out += '\n';
        }
    }
}

}  // namespace

std::string fortranE(double v) {
    if (!(std::abs(v) > 1e-99)) v = 0.0;  // NaN too: a missing value is 0 in code_aster's files
    int exponent = 0;
    double mantissa = 0.0;
    if (v != 0.0) {
        exponent = int(std::floor(std::log10(std::abs(v))));
        mantissa = v / std::pow(10.0, exponent);
        // Round to 7 decimals first: 9.99999999 becomes 10.0000000, i.e. 1.0000000E+(e+1).
        mantissa = std::round(mantissa * 1e7) / 1e7;
        if (std::abs(mantissa) >= 10.0) {
            mantissa /= 10.0;
            ++exponent;
        } else if (std::abs(mantissa) < 1.0) {
            mantissa *= 10.0;
            --exponent;
        }
    }
    return fmt::format("{:>10.7f}E{}{:03d}", mantissa, exponent < 0 ? '-' : '+', std::abs(exponent));
}

std::string header(int version) {
    return fmt::format("$PostFormat\n {} 0 8\n$EndPostFormat\n", version == 2 ? "1.2" : "1.0");
}

std::string view(const Mesh& mesh, const View& v, int version, std::vector<CellType>* skipped) {
    // Group the written pieces by kind, in the file's order.
    std::array<std::vector<std::pair<int, Piece>>, kKinds> byKind;
    for (int cell : v.cells) {
        const Split split = splitOf(mesh.cellTypes[size_t(cell)], version);
        if (split.empty() && skipped) skipped->push_back(mesh.cellTypes[size_t(cell)]);
        for (const auto& p : split) byKind[p.kind].emplace_back(cell, p);
    }
    const int column = v.kind == ViewKind::Scalar ? 0 : v.kind == ViewKind::Vector ? 1 : 2;
    std::string out = fmt::format("$View\n{} {:5d}\n", v.name, v.times.size());
    const int kinds = version == 2 ? kKinds : 4;
    for (int k = 0; k < kinds; ++k) {
        const int kind = version == 2 ? k : std::array<int, 4>{kPoint, kLine, kTriangle, kTetra}[size_t(k)];
        for (int c = 0; c < 3; ++c) out += fmt::format("{:8d} ", c == column ? byKind[size_t(kind)].size() : 0);
        out += '\n';
    }
    if (version == 2) out += "     0      0      0      0 \n";
    for (size_t i = 0; i < v.times.size(); ++i)
        out += fmt::format("{:15.8E}{}", v.times[i], i % 10 == 9 || i + 1 == v.times.size() ? "\n" : "");
    for (int k = 0; k < kinds; ++k) {
        const int kind = version == 2 ? k : std::array<int, 4>{kPoint, kLine, kTriangle, kTetra}[size_t(k)];
        for (const auto& [cell, piece] : byKind[size_t(kind)]) appendRecord(out, mesh, v, cell, piece);
    }
    return out + "$EndView\n";
}

namespace {

int meshFormat1Type(CellType t) {
    switch (t) {
        case CellType::POI1: return 15;
        case CellType::SEG2: return 1;
        case CellType::TRIA3: return 2;
        case CellType::QUAD4: return 3;
        case CellType::TETRA4: return 4;
        case CellType::HEXA8: return 5;
        case CellType::PENTA6: return 6;
        case CellType::PYRA5: return 7;
        default: return 0;
    }
}

// Region number of each cell (irmgms): groups in creation order, the last one wins.
std::vector<int> cellRegions(const Mesh& mesh) {
    int largest = 10000;
    auto numbered = [](const std::string& name, int& n) {
        if (name.size() < 3 || name.find_first_not_of("0123456789", 2) != std::string::npos) return false;
        n = std::stoi(name.substr(2));
        return true;
    };
    for (const auto& g : mesh.cellGroups.names())
        if (int n = 0; numbered(g, n)) largest = std::max(largest, n);
    std::vector<int> region(size_t(mesh.cellCount()), 10000);
    int k = 0;
    for (const auto& g : mesh.cellGroups.names()) {
        ++k;
        int n = 0;
        const int number = numbered(g, n) ? n : k + largest;
        for (int c : mesh.cellGroups.get(g)) region[size_t(c)] = number;
    }
    return region;
}

}  // namespace

std::string meshFormat1(const Mesh& mesh) {
    std::string out = fmt::format("$NOD\n{}\n", mesh.nodeCount());
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        const auto& x = mesh.coords[size_t(n)];
        out += fmt::format(" {:>7} {:23.16E} {:23.16E} {:23.16E}\n", n + 1, x[0], x[1], mesh.dim == 3 ? x[2] : 0.0);
    }
    out += "$ENDNOD\n$ELM\n" + std::to_string(mesh.cellCount()) + "\n";
    const auto region = cellRegions(mesh);
    for (int c = 0; c < mesh.cellCount(); ++c) {
        const int type = meshFormat1Type(mesh.cellTypes[size_t(c)]);
        if (type == 0)
            throw NotImplemented(
                fmt::format("FORMAT='GMSH' of the mesh {}: cell {} is a {}; miniaster writes linear "
                            "cells only (code_aster splits quadratic ones)",
                            mesh.name, mesh.cellNames[size_t(c)], cellTypeName(mesh.cellTypes[size_t(c)])));
        const auto nodes = mesh.cellNodes(c);
        out += fmt::format(" {:>7} {:2d} {:8d} {:8d} {:8d}", c + 1, type, region[size_t(c)], region[size_t(c)],
                           nodes.size());
        for (int n : nodes) out += fmt::format(" {:>7}", n + 1);
        out += "\n";
    }
    return out + "$ENDELM\n";
}

}  // namespace ma::gmsh
