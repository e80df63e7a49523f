#include "mesh/GmshMeshReader.hpp"

#include <array>
#include <fstream>
#include <map>
#include <sstream>
#include <unordered_map>
#include <vector>

#include <fmt/format.h>

#include "core/Error.hpp"

namespace ma {

namespace {

// gmsh element types 1..19 as PRE_GMSH converts them: the code_aster cell, the node count of the
// gmsh element, and for each code_aster node the (1-based) gmsh node it takes where the two
// orders differ (code_aster's inigms; QUAD9 and PYRAM14 lose their centre node).
struct GmshType {
    CellType cell;
    int gmshNodes;
    std::vector<std::pair<int, int>> moved;  // (code_aster node, gmsh node), 1-based
};

const std::vector<std::pair<int, int>> kHexaMoves{{10, 12}, {11, 14}, {12, 10}, {13, 11},
                                                  {14, 13}, {18, 19}, {19, 20}, {20, 18}};
const std::vector<std::pair<int, int>> kPentaMoves{{8, 10}, {9, 8}, {10, 9}, {14, 15}, {15, 14}};
const std::vector<std::pair<int, int>> kPyramMoves{{7, 9}, {8, 11}, {9, 7}, {10, 8}, {11, 10}};

const GmshType& gmshType(int type) {
    static const std::array<GmshType, 19> types{{
        {CellType::SEG2, 2, {}},
        {CellType::TRIA3, 3, {}},
        {CellType::QUAD4, 4, {}},
        {CellType::TETRA4, 4, {}},
        {CellType::HEXA8, 8, {}},
        {CellType::PENTA6, 6, {}},
        {CellType::PYRA5, 5, {}},
        {CellType::SEG3, 3, {}},
        {CellType::TRIA6, 6, {}},
        {CellType::QUAD8, 9, {}},
        {CellType::TETRA10, 10, {{9, 10}, {10, 9}}},
        {CellType::HEXA27, 27,
         [] {
             auto m = kHexaMoves;
             m.insert(m.end(), {{23, 24}, {24, 25}, {25, 23}});
             return m;
         }()},
        {CellType::PENTA18, 18,
         [] {
             auto m = kPentaMoves;
             m.insert(m.end(), {{17, 18}, {18, 17}});
             return m;
         }()},
        {CellType::PYRA13, 14, kPyramMoves},
        {CellType::POI1, 1, {}},
        {CellType::QUAD8, 8, {}},
        {CellType::HEXA20, 20, kHexaMoves},
        {CellType::PENTA15, 15, kPentaMoves},
        {CellType::PYRA13, 13, kPyramMoves},
    }};
    return types[size_t(type - 1)];
}

// Numbers become names of at most 8 characters ("N1234567"), as PRE_GMSH writes them.
constexpr long long kMaxNumber = 9'999'999;

class Parser {
public:
    Parser(std::istream& in, std::string source) : in_(in), source_(std::move(source)) {}

    std::shared_ptr<Mesh> parse() {
        header();
        nodes();
        expect("$Elements", "the $Elements section must follow $EndNodes");
        elements();
        expect("$EndElements", "the element list must end with $EndElements");
        return build();
    }

private:
    struct Element {
        long long number;
        int type;
        long long tag;
        std::vector<long long> nodes;  // gmsh order
        int line;
    };

    [[noreturn]] void fail(int line, const std::string& what) const {
        throw UserError(fmt::format("mesh file '{}', line {}: {}", source_, line, what));
    }

    bool next(std::string& line) {
        while (std::getline(in_, line)) {
            ++line_;
            if (!line.empty() && line.back() == '\r') line.pop_back();
            if (line.find_first_not_of(" \t") != std::string::npos) return true;
        }
        return false;
    }

    std::string need(const char* what) {
        std::string line;
        if (!next(line)) fail(line_, fmt::format("the file ends before {}", what));
        return line;
    }

    void expect(const char* keyword, const char* why) {
        std::istringstream s(need(keyword));
        std::string word;
        s >> word;
        if (word != keyword) fail(line_, fmt::format("'{}' found: {}", word, why));
    }

    long long count(const char* what) {
        std::istringstream s(need(what));
        long long n = -1;
        std::string extra;
        if (!(s >> n) || n < 0 || (s >> extra)) fail(line_, fmt::format("expected the number of {}", what));
        return n;
    }

    void header() {
        std::istringstream first(need("$MeshFormat"));
        std::string word;
        first >> word;
        if (word == "$NOD")
            fail(line_,
                 "MSH version 1 file: miniaster reads MSH 2 text files (gmsh -format msh2, or "
                 "Mesh.MshFileVersion = 2.2)");
        if (word != "$MeshFormat") fail(line_, "a gmsh mesh file starts with $MeshFormat");
        std::istringstream format(need("the format line"));
        std::string version;
        int fileType = -1;
        format >> version >> fileType;
        if (version.empty() || version[0] != '2' || (version.size() > 1 && version[1] != '.'))
            fail(line_, fmt::format("MSH version {}: miniaster reads MSH 2 text files (gmsh -format msh2, or "
                                    "Mesh.MshFileVersion = 2.2)",
                                    version));
        if (fileType != 0) fail(line_, "a binary MSH file: save the mesh as text (Mesh.Binary = 0)");
        expect("$EndMeshFormat", "the format line is one line");
        // Sections before $Nodes ($PhysicalNames...) are skipped, as PRE_GMSH does: groups are named
        // after their physical number.
        std::string line;
        while (true) {
            line = need("$Nodes");
            if (line.rfind("$Nodes", 0) == 0) break;
        }
    }

    void nodes() {
        const long long n = count("nodes");
        for (long long k = 0; k < n; ++k) {
            std::istringstream s(need("the end of the node list"));
            long long number = 0;
            std::array<double, 3> x{};
            std::string extra;
            if (!(s >> number >> x[0] >> x[1] >> x[2]) || (s >> extra)) fail(line_, "a node line is: number x y z");
            if (number < 1 || number > kMaxNumber)
                fail(line_, fmt::format("node number {} out of 1..{}", number, kMaxNumber));
            if (!nodeIndex_.emplace(number, nodeNumbers_.size()).second)
                fail(line_, fmt::format("node {} is defined twice", number));
            nodeNumbers_.push_back(number);
            coords_.push_back(x);
        }
        expect("$EndNodes", fmt::format("$Nodes announces {} nodes", n).c_str());
    }

    void elements() {
        const long long n = count("elements");
        std::unordered_map<long long, int> seen;
        for (long long k = 0; k < n; ++k) {
            std::istringstream s(need("the end of the element list"));
            Element e{0, 0, 0, {}, 0};
            int tags = -1;
            if (!(s >> e.number >> e.type >> tags) || tags < 0)
                fail(line_, "an element line is: number type number-of-tags tags... nodes...");
            e.line = line_;
            if (e.number < 1 || e.number > kMaxNumber)
                fail(line_, fmt::format("element number {} out of 1..{}", e.number, kMaxNumber));
            if (!seen.emplace(e.number, line_).second)
                fail(line_, fmt::format("element {} is defined twice (line {})", e.number, seen[e.number]));
            if (e.type < 1 || e.type > 19)
                fail(line_,
                     fmt::format("element {}: gmsh type {} is not one PRE_GMSH reads (1 to 19)", e.number, e.type));
            std::vector<long long> tagValues(static_cast<size_t>(tags));
            for (auto& t : tagValues)
                if (!(s >> t)) fail(line_, fmt::format("element {}: {} tags announced", e.number, tags));
            if (tags == 0 || tagValues[0] <= 0)
                fail(line_, fmt::format("element {} has no physical group (first tag 0 or absent): give every element "
                                        "a physical group, as code_aster's PRE_GMSH needs",
                                        e.number));
            if (tagValues[0] >= 1'000'000)
                fail(line_, fmt::format("element {}: physical tag {} has more than 6 digits", e.number, tagValues[0]));
            e.tag = tagValues[0];
            e.nodes.resize(size_t(gmshType(e.type).gmshNodes));
            for (auto& v : e.nodes) {
                if (!(s >> v))
                    fail(line_, fmt::format("element {}: gmsh type {} has {} nodes", e.number, e.type, e.nodes.size()));
                if (!nodeIndex_.count(v))
                    fail(line_, fmt::format("element {} names node {}, which $Nodes does not define", e.number, v));
            }
            std::string extra;
            if (s >> extra) fail(line_, fmt::format("element {}: more values than its type and tags take", e.number));
            elements_.push_back(std::move(e));
        }
    }

    std::shared_ptr<Mesh> build() const;

    std::istream& in_;
    std::string source_;
    int line_ = 0;
    std::vector<long long> nodeNumbers_;
    std::vector<std::array<double, 3>> coords_;
    std::unordered_map<long long, size_t> nodeIndex_;
    std::vector<Element> elements_;
};

std::shared_ptr<Mesh> Parser::build() const {
    auto mesh = std::make_shared<Mesh>();
    mesh->dim = 3;  // PRE_GMSH writes COOR_3D
    std::vector<char> used(nodeNumbers_.size(), 0);
    for (const auto& e : elements_)
        for (long long v : e.nodes) used[nodeIndex_.at(v)] = 1;
    std::vector<int> meshNode(nodeNumbers_.size(), -1);
    for (size_t k = 0; k < nodeNumbers_.size(); ++k)
        if (used[k]) meshNode[k] = mesh->addNode(coords_[k], fmt::format("N{}", nodeNumbers_[k]));
    // Cells by gmsh type, then file order; groups by first appearance of their tag, members in file order.
    std::map<const Element*, int> cellOf;
    for (int type = 1; type <= 19; ++type)
        for (const auto& e : elements_) {
            if (e.type != type) continue;
            const GmshType& t = gmshType(type);
            std::vector<int> nodes(size_t(nodeCount(t.cell)));
            for (size_t k = 0; k < nodes.size(); ++k) nodes[k] = meshNode[nodeIndex_.at(e.nodes[k])];
            for (const auto& [aster, gmsh] : t.moved)
                nodes[size_t(aster - 1)] = meshNode[nodeIndex_.at(e.nodes[size_t(gmsh - 1)])];
            cellOf[&e] = mesh->addCell(t.cell, nodes, fmt::format("M{}", e.number));
        }
    std::vector<long long> tagOrder;
    std::map<long long, std::vector<int>> members;
    for (const auto& e : elements_) {
        if (!members.count(e.tag)) tagOrder.push_back(e.tag);
        members[e.tag].push_back(cellOf.at(&e));
    }
    for (long long tag : tagOrder) {
        const std::string name = fmt::format("GM{}", tag);
        const auto& cells = members.at(tag);
        if (cells.size() == 1 && mesh->cellTypes[size_t(cells[0])] == CellType::POI1)
            mesh->nodeGroups.set(name, {mesh->cellNodes(cells[0])[0]});
        mesh->cellGroups.set(name, cells);
    }
    return mesh;
}

}  // namespace

std::shared_ptr<Mesh> parseGmshMesh(std::istream& in, const std::string& source) { return Parser(in, source).parse(); }

std::shared_ptr<Mesh> readGmshMesh(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw UserError(fmt::format("cannot open the gmsh mesh file '{}'", path));
    return parseGmshMesh(in, path);
}

}  // namespace ma
