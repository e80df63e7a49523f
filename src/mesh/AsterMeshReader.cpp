#include "mesh/AsterMeshReader.hpp"

#include <cstring>
#include <fstream>
#include <unordered_map>

#include "core/Error.hpp"
#include "mesh/AsterMeshLexer.hpp"
#include "mesh/MeshMessages.hpp"

namespace ma {

namespace {

constexpr size_t kEntityNameLength = 8;  // node and cell names (code_aster K8)
constexpr size_t kGroupNameLength = 24;  // GROUP_NO / GROUP_MA names (K24)

struct NodeRecord {
    std::string name;
    std::array<double, 3> xyz{};
    int line;
};
struct CellRecord {
    CellType type;
    std::string name;
    std::vector<std::string> nodes;
    int line;
};
struct GroupRecord {
    std::string name;
    std::vector<std::pair<std::string, int>> members;  // (name, line)
    int line;
};
struct BlockHeader {
    std::string name;  // NOM=
    int line = 0;
};

// The text as read, names not yet resolved (groups and cells may come before what they name).
class AsterMeshParser {
public:
    AsterMeshParser(std::istream& in, const std::string& source, AsterMeshReport& report)
        : lex_(in, source), source_(source), report_(report) {}

    std::shared_ptr<Mesh> parse();

private:
    void readTitle(const AsterToken& keyword);
    void readCoordinates(const AsterToken& keyword, int dim);
    void readCells(const AsterToken& keyword, CellType type);
    void readGroup(const AsterToken& keyword, std::vector<GroupRecord>& groups);
    BlockHeader readHeader(const AsterToken& keyword);
    bool atBlockEnd(const AsterToken& keyword);
    AsterToken recordName(const char* what, const AsterToken& keyword);
    // `what` names the item in an error message; called only when there is one.
    template <class What>
    AsterToken recordItem(const AsterToken& record, const What& what);
    std::string groupName(const AsterToken& tok, const std::string& name);

    std::shared_ptr<Mesh> build(int finLine);
    void addGroups(const std::vector<GroupRecord>& records, const std::unordered_map<std::string, int>& index,
                   const char* kind, GroupSet& out);

    AsterLexer lex_;
    std::string source_;
    AsterMeshReport& report_;
    int dim_ = 0, dimLine_ = 0;
    std::vector<NodeRecord> nodes_;
    std::vector<CellRecord> cells_;
    std::vector<GroupRecord> nodeGroups_, cellGroups_;
};

std::shared_ptr<Mesh> AsterMeshParser::parse() {
    if (lex_.lineCount() == 0) lex_.fail(1, "the file is empty");
    for (;;) {
        const AsterToken tok = lex_.next();
        if (tok.kind == AsterToken::Kind::End)
            lex_.fail(tok.line, "end of file before the FIN line: the file is truncated");
        if (!tok.first) lex_.fail(tok.line, "'" + tok.text + "' follows a complete record (one record per line)");
        if (tok.is("FIN")) return build(tok.line);
        if (tok.is("FINSF")) continue;
        CellType type{};
        if (tok.is("TITRE")) {
            readTitle(tok);
        } else if (tok.is("COOR_1D")) {
            lex_.fail(tok.line, "COOR_1D: 1D meshes are outside miniaster's models (COOR_2D or COOR_3D only)");
        } else if (tok.is("COOR_2D") || tok.is("COOR_3D")) {
            readCoordinates(tok, tok.text == "COOR_2D" ? 2 : 3);
        } else if (tok.kind == AsterToken::Kind::Name && cellTypeFromName(tok.text, type) &&
                   cellTypeName(type) == tok.text) {
            readCells(tok, type);
        } else if (tok.is("GROUP_NO") || tok.is("GROUP_MA")) {
            readGroup(tok, tok.text == "GROUP_NO" ? nodeGroups_ : cellGroups_);
        } else {
            lex_.fail(tok.line,
                      "'" + tok.text +
                          "' is not a block keyword of a code_aster mesh file (TITRE, COOR_2D, COOR_3D, a "
                          "cell type such as QUAD4 or HEXA20, GROUP_NO, GROUP_MA, FINSF, FIN; in upper case)");
        }
    }
}

// Items after the keyword on its line: NOM= (a group's name), NBLIGE= (header lines to skip);
// the others (NBOBJ=, DATE=, AUTEUR= ...) are ignored, as code_aster does.
BlockHeader AsterMeshParser::readHeader(const AsterToken& keyword) {
    BlockHeader header;
    int headerLines = 1;
    while (lex_.moreOnLine()) {
        const AsterToken item = lex_.next();
        if (item.kind != AsterToken::Kind::Name) continue;
        const bool isName = item.text.compare(0, 3, "NOM") == 0, isLines = item.text == "NBLIGE";
        if (!isName && !isLines) continue;
        const AsterToken value = lex_.moreOnLine() ? lex_.next() : AsterToken{};
        if ((isName && value.kind != AsterToken::Kind::Name) || (isLines && value.kind != AsterToken::Kind::Integer))
            lex_.fail(item.line,
                      item.text + "= must be followed by " + (isName ? "a name" : "an integer") + " on the same line");
        if (isName) header.name = value.text, header.line = value.line;
        if (isLines) headerLines = int(value.value);
    }
    if (headerLines > 1) lex_.restartAt(keyword.line + headerLines);
    return header;
}

bool AsterMeshParser::atBlockEnd(const AsterToken& keyword) {
    const AsterToken& tok = lex_.peek();
    if (tok.kind == AsterToken::Kind::End)
        lex_.fail(tok.line, "end of file inside the " + keyword.text + " block begun at line " +
                                std::to_string(keyword.line) + " (no FINSF, no FIN): the file is truncated");
    if (tok.is("FIN")) return true;
    if (tok.is("FINSF")) {
        lex_.next();
        return true;
    }
    return false;
}

AsterToken AsterMeshParser::recordName(const char* what, const AsterToken& keyword) {
    AsterToken tok = lex_.next();
    if (!tok.first)
        lex_.fail(tok.line, "'" + tok.text + "' follows a complete record of the " + keyword.text +
                                " block (one record per line, each one starting its line)");
    if (tok.kind != AsterToken::Kind::Name)
        lex_.fail(tok.line, "'" + tok.text + "' where a " + what +
                                " name is expected (a letter, then letters, "
                                "digits or '_')");
    if (tok.text.size() > kEntityNameLength)
        lex_.fail(tok.line, std::string(what) + " name '" + tok.text + "' has " + std::to_string(tok.text.size()) +
                                " characters: code_aster's node and cell names have at most 8");
    return tok;
}

// The next item of the record begun by `record`; records may wrap onto the following lines.
template <class What>
AsterToken AsterMeshParser::recordItem(const AsterToken& record, const What& what) {
    AsterToken tok = lex_.next();
    if (tok.kind == AsterToken::Kind::End || tok.is("FINSF") || tok.is("FIN"))
        lex_.fail(tok.line, "the record of '" + record.text + "' begun at line " + std::to_string(record.line) +
                                " ends before its " + what() + " (" +
                                (tok.kind == AsterToken::Kind::End ? "end of file" : tok.text) + " found)");
    return tok;
}

void AsterMeshParser::readTitle(const AsterToken& keyword) {
    for (int line = keyword.line + 1; line <= lex_.lineCount(); ++line) {
        std::string text = lex_.rawLine(line);
        const size_t start = text.find_first_not_of(" \t");
        const std::string word =
            start == std::string::npos ? "" : text.substr(start, text.find_first_of(" \t%", start) - start);
        if (word == "FINSF" || word == "FIN") {
            lex_.restartAt(line);
            return;
        }
        report_.title.push_back(std::move(text));
    }
    lex_.fail(lex_.lineCount(), "end of file inside the TITRE block begun at line " + std::to_string(keyword.line) +
                                    " (no FINSF): the file is truncated");
}

void AsterMeshParser::readCoordinates(const AsterToken& keyword, int dim) {
    if (dim_ != 0 && dim_ != dim)
        lex_.fail(keyword.line, keyword.text + " after a COOR_" + std::to_string(dim_) + "D block (line " +
                                    std::to_string(dimLine_) + "): a mesh has one space dimension");
    if (dim_ == 0) dim_ = dim, dimLine_ = keyword.line;
    readHeader(keyword);
    while (!atBlockEnd(keyword)) {
        const AsterToken name = recordName("node", keyword);
        NodeRecord node{name.text, {}, name.line};
        for (int k = 0; k < dim; ++k) {
            auto what = [k] { return "coordinate " + std::string(1, "XYZ"[k]); };
            const AsterToken value = recordItem(name, what);
            if (!value.isNumber())
                lex_.fail(value.line, "'" + value.text + "' where the " + what() + " of node " + name.text +
                                          " is expected (" + keyword.text + ": " + std::to_string(dim) +
                                          " numbers per node)");
            node.xyz[size_t(k)] = value.value;
        }
        nodes_.push_back(std::move(node));
    }
}

void AsterMeshParser::readCells(const AsterToken& keyword, CellType type) {
    readHeader(keyword);
    const int count = nodeCount(type);
    while (!atBlockEnd(keyword)) {
        const AsterToken name = recordName("cell", keyword);
        CellRecord cell{type, name.text, {}, name.line};
        for (int k = 1; k <= count; ++k) {
            auto what = [&, k] {
                return "node " + std::to_string(k) + " of " + std::to_string(count) + " (" + keyword.text + ")";
            };
            AsterToken node = recordItem(name, what);
            if (node.kind != AsterToken::Kind::Name)
                lex_.fail(node.line, "'" + node.text + "' where " + what() + " of cell " + name.text +
                                         " is expected (a node name)");
            cell.nodes.push_back(std::move(node.text));
        }
        cells_.push_back(std::move(cell));
    }
}

std::string AsterMeshParser::groupName(const AsterToken& tok, const std::string& name) {
    if (name.size() <= kGroupNameLength) return name;
    const std::string cut = name.substr(0, kGroupNameLength);
    report_.alarms.push_back(formatted(MODELISA4_97, source_, tok.line, name, cut));
    return cut;
}

// GROUP_xx NOM=G then members from the next line on, or GROUP_xx then "G m1 m2 ..." (one group
// per block; members on any number of lines).
void AsterMeshParser::readGroup(const AsterToken& keyword, std::vector<GroupRecord>& groups) {
    const BlockHeader header = readHeader(keyword);
    GroupRecord group;
    if (!header.name.empty()) {
        group.line = header.line;
        group.name = groupName(keyword, header.name);
    } else {
        if (atBlockEnd(keyword)) lex_.fail(keyword.line, keyword.text + " block without a group name");
        const AsterToken name = lex_.next();
        if (name.kind != AsterToken::Kind::Name)
            lex_.fail(name.line, "'" + name.text + "' where the name of the group is expected");
        group.line = name.line;
        group.name = groupName(name, name.text);
    }
    while (!atBlockEnd(keyword)) {
        const AsterToken member = lex_.next();
        if (member.kind != AsterToken::Kind::Name)
            lex_.fail(member.line, "'" + member.text + "' in group " + group.name + ": members are " +
                                       (keyword.text == "GROUP_NO" ? "node" : "cell") + " names");
        group.members.emplace_back(member.text, member.line);
    }
    groups.push_back(std::move(group));
}

template <class Record>
std::unordered_map<std::string, int> nameIndex(const std::vector<Record>& records, const char* what,
                                               const AsterLexer& lex) {
    std::unordered_map<std::string, int> index;
    for (size_t i = 0; i < records.size(); ++i) {
        auto [it, fresh] = index.emplace(records[i].name, int(i));
        if (!fresh)
            lex.fail(records[i].line, std::string(what) + " name '" + records[i].name + "' is already used at line " +
                                          std::to_string(records[size_t(it->second)].line));
    }
    return index;
}

void AsterMeshParser::addGroups(const std::vector<GroupRecord>& records,
                                const std::unordered_map<std::string, int>& index, const char* kind, GroupSet& out) {
    const bool ofNodes = std::string(kind) == "GROUP_NO";
    for (const auto& group : records) {
        if (out.has(group.name)) lex_.fail(group.line, kind + std::string(" '") + group.name + "' is defined twice");
        std::vector<int> members;
        std::vector<char> seen(index.size(), 0);
        for (const auto& [name, line] : group.members) {
            auto it = index.find(name);
            if (it == index.end())
                lex_.fail(line, kind + std::string(" '") + group.name + "' names " + (ofNodes ? "node" : "cell") +
                                    " '" + name + "', which the file does not define");
            if (!seen[size_t(it->second)]++) members.push_back(it->second);
            else
                report_.alarms.push_back(
                    formatted(ofNodes ? MODELISA5_6 : MODELISA5_8, source_, line, name, group.name));
        }
        if (members.empty()) report_.alarms.push_back(formatted(MODELISA4_80, source_, group.line, kind, group.name));
        else out.set(group.name, std::move(members));
    }
}

std::shared_ptr<Mesh> AsterMeshParser::build(int finLine) {
    if (nodes_.empty()) lex_.fail(finLine, "the file defines no node (no COOR_2D or COOR_3D block)");
    if (cells_.empty()) lex_.fail(finLine, "the file defines no cell (no cell block such as QUAD4)");
    const auto nodeIndex = nameIndex(nodes_, "node", lex_);
    const auto cellIndex = nameIndex(cells_, "cell", lex_);
    auto mesh = std::make_shared<Mesh>();
    mesh->dim = dim_;
    mesh->coords.reserve(nodes_.size());
    for (auto& node : nodes_) mesh->addNode(node.xyz, node.name);
    std::vector<int> connectivity;
    for (const auto& cell : cells_) {
        connectivity.clear();
        for (const auto& node : cell.nodes) {
            auto it = nodeIndex.find(node);
            if (it == nodeIndex.end())
                lex_.fail(cell.line, "cell " + cell.name + " names node '" + node + "', which no COOR block defines");
            connectivity.push_back(it->second);
        }
        mesh->addCell(cell.type, connectivity, cell.name);
    }
    addGroups(nodeGroups_, nodeIndex, "GROUP_NO", mesh->nodeGroups);
    addGroups(cellGroups_, cellIndex, "GROUP_MA", mesh->cellGroups);
    return mesh;
}

}  // namespace

std::shared_ptr<Mesh> parseAsterMesh(std::istream& in, const std::string& source, AsterMeshReport* report) {
    AsterMeshReport local;
    AsterMeshParser parser(in, source, report ? *report : local);
    return parser.parse();
}

std::shared_ptr<Mesh> readAsterMesh(const std::string& path, AsterMeshReport* report) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw UserError("mesh file '" + path + "' cannot be opened");
    // A MED file is HDF5: its signature, not text, on the first line.
    char head[8] = {};
    in.read(head, sizeof(head));
    if (in.gcount() == sizeof(head) && std::memcmp(head, "\x89HDF\r\n\x1a\n", sizeof(head)) == 0)
        throw UserError("mesh file '" + path +
                        "' is a MED (HDF5) file, not a code_aster text mesh: read it with "
                        "LIRE_MAILLAGE(FORMAT='MED')");
    in.clear();
    in.seekg(0);
    return parseAsterMesh(in, path, report);
}

}  // namespace ma
