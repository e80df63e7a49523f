#include "post/VtuWriter.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <cstring>

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"

namespace ma::vtu {

namespace {

// VTK's cell type numbers (vtkCellType.h).
enum : int {
    kVertex = 1,
    kLine = 3,
    kTriangle = 5,
    kQuad = 9,
    kTetra = 10,
    kHexahedron = 12,
    kWedge = 13,
    kPyramid = 14,
    kQuadraticEdge = 21,
    kQuadraticTriangle = 22,
    kQuadraticQuad = 23,
    kQuadraticTetra = 24,
    kQuadraticHexahedron = 25,
    kQuadraticWedge = 26,
    kQuadraticPyramid = 27,
    kBiquadraticQuad = 28,
    kBiquadraticTriangle = 34,
    kCubicLine = 35,
};

// code_aster lists the mid-edge nodes of prisms and hexahedra bottom, vertical, top; VTK bottom,
// top, vertical.
const std::vector<int> kHexa20{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 16, 17, 18, 19, 12, 13, 14, 15};
const std::vector<int> kPenta15{0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 13, 14, 9, 10, 11};

// base64 of `bytes` (RFC 4648, padded), appended to `out`.
void appendBase64(std::string& out, const unsigned char* bytes, size_t n) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (size_t i = 0; i < n; i += 3) {
        const uint32_t b0 = bytes[i], b1 = i + 1 < n ? bytes[i + 1] : 0, b2 = i + 2 < n ? bytes[i + 2] : 0;
        const uint32_t v = (b0 << 16) | (b1 << 8) | b2;
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += i + 1 < n ? table[(v >> 6) & 63] : '=';
        out += i + 2 < n ? table[v & 63] : '=';
    }
}

// A binary DataArray body: VTK's UInt64 byte count, then the raw values, all in base64.
template <class T>
std::string encoded(const std::vector<T>& values) {
    std::vector<unsigned char> block(sizeof(uint64_t) + values.size() * sizeof(T));
    const uint64_t bytes = values.size() * sizeof(T);
    std::memcpy(block.data(), &bytes, sizeof bytes);
    if (!values.empty()) std::memcpy(block.data() + sizeof bytes, values.data(), bytes);
    std::string out;
    out.reserve(block.size() * 4 / 3 + 4);
    appendBase64(out, block.data(), block.size());
    return out;
}

std::string xmlEscaped(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '&') out += "&amp;";
        else if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '"') out += "&quot;";
        else out += c;
    }
    return out;
}

std::string dataArray(const DataArray& a, size_t tuples) {
    const int nc = std::max(a.componentCount(), 1);
    if (a.values.size() != tuples * size_t(nc))
        throw InternalError(
            fmt::format("VTU array {}: {} values for {} tuples of {}", a.name, a.values.size(), tuples, nc));
    std::string head = fmt::format(R"(        <DataArray type="{}" Name="{}" NumberOfComponents="{}")",
                                   a.flag ? "UInt8" : "Float64", xmlEscaped(a.name), nc);
    for (int c = 0; c < a.componentCount() && nc > 1; ++c)
        head += fmt::format(R"( ComponentName{}="{}")", c, xmlEscaped(a.componentNames[size_t(c)]));
    head += " format=\"binary\">\n          ";
    if (a.flag) {
        std::vector<uint8_t> bytes(a.values.size());
        for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = a.values[i] != 0.0 ? 1 : 0;
        head += encoded(bytes);
    } else {
        head += encoded(a.values);
    }
    return head + "\n        </DataArray>\n";
}

}  // namespace

VtkCell vtkCellOf(CellType t) {
    switch (t) {
        case CellType::POI1: return {kVertex, {}, 1};
        case CellType::SEG2: return {kLine, {}, 2};
        case CellType::SEG3: return {kQuadraticEdge, {}, 3};
        case CellType::SEG4: return {kCubicLine, {}, 4};
        case CellType::TRIA3: return {kTriangle, {}, 3};
        case CellType::TRIA6: return {kQuadraticTriangle, {}, 6};
        case CellType::TRIA7: return {kBiquadraticTriangle, {}, 7};
        case CellType::QUAD4: return {kQuad, {}, 4};
        case CellType::QUAD8: return {kQuadraticQuad, {}, 8};
        case CellType::QUAD9: return {kBiquadraticQuad, {}, 9};
        case CellType::TETRA4: return {kTetra, {}, 4};
        case CellType::TETRA10: return {kQuadraticTetra, {}, 10};
        case CellType::PYRA5: return {kPyramid, {}, 5};
        case CellType::PYRA13: return {kQuadraticPyramid, {}, 13};
        case CellType::PENTA6: return {kWedge, {}, 6};
        case CellType::PENTA15:
        case CellType::PENTA18: return {kQuadraticWedge, kPenta15, 15};
        case CellType::HEXA8: return {kHexahedron, {}, 8};
        case CellType::HEXA20:
        case CellType::HEXA27: return {kQuadraticHexahedron, kHexa20, 20};
    }
    throw NotImplemented("VTU: cell type " + cellTypeName(t) + " has no VTK equivalent");
}

void write(const std::string& path, const Mesh& mesh, const std::vector<DataArray>& pointData,
           const std::vector<DataArray>& cellData, const std::string& activeVectors) {
    std::vector<double> points;
    points.reserve(size_t(mesh.nodeCount()) * 3);
    for (const auto& xyz : mesh.coords) points.insert(points.end(), xyz.begin(), xyz.end());
    std::vector<int64_t> connectivity, offsets;
    std::vector<uint8_t> types;
    for (int c = 0; c < mesh.cellCount(); ++c) {
        const VtkCell v = vtkCellOf(mesh.cellTypes[size_t(c)]);
        const auto nodes = mesh.cellNodes(c);
        for (int j = 0; j < v.nodes; ++j)
            connectivity.push_back(nodes[size_t(v.internalNode.empty() ? j : v.internalNode[size_t(j)])]);
        offsets.push_back(int64_t(connectivity.size()));
        types.push_back(uint8_t(v.type));
    }
    std::string xml =
        "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
        "header_type=\"UInt64\">\n  <UnstructuredGrid>\n";
    xml += fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", mesh.nodeCount(), mesh.cellCount());
    xml += activeVectors.empty() ? "      <PointData>\n"
                                 : fmt::format("      <PointData Vectors=\"{}\">\n", xmlEscaped(activeVectors));
    for (const auto& a : pointData) xml += dataArray(a, size_t(mesh.nodeCount()));
    xml += "      </PointData>\n      <CellData>\n";
    for (const auto& a : cellData) xml += dataArray(a, size_t(mesh.cellCount()));
    xml +=
        "      </CellData>\n      <Points>\n"
        "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"binary\">\n          " +
        encoded(points) + "\n        </DataArray>\n      </Points>\n      <Cells>\n" +
        "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"binary\">\n          " +
        encoded(connectivity) +
        "\n        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"binary\">\n          " +
        encoded(offsets) +
        "\n        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"binary\">\n          " +
        encoded(types) + "\n        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
    writeFileAtomically(path, xml);
}

void writeCollection(const std::string& path, const std::vector<CollectionStep>& steps) {
    std::string xml =
        "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n";
    for (const auto& s : steps)
        xml += fmt::format("    <DataSet timestep=\"{:.17g}\" group=\"\" part=\"0\" file=\"{}\"/>\n", s.time,
                           xmlEscaped(s.file));
    xml += "  </Collection>\n</VTKFile>\n";
    writeFileAtomically(path, xml);
}

}  // namespace ma::vtu
