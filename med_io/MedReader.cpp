#include "med_io/MedReader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "med_io/MedCellOrder.hpp"
#include "med_io/MedFileHandle.hpp"
#include "med_io/MedMessages.hpp"

namespace ma::med {

namespace {

constexpr size_t kMaxGroupName = 24;  // code_aster's limit on GROUP_MA / GROUP_NO names

[[noreturn]] void damaged(const std::string& path, const std::string& what) {
    throwMedError("MED file '" + path + "' is damaged or truncated: cannot read " + what);
}

struct MeshHeader {
    std::string name;
    med_int spaceDim = 0, meshDim = 0;
    med_mesh_type type = MED_UNSTRUCTURED_MESH;
};

std::vector<MeshHeader> readHeaders(const MedFile& file) {
    med_int n = MEDnMesh(file.id());
    if (n < 0) damaged(file.path(), "the list of meshes");
    std::vector<MeshHeader> out;
    for (med_int i = 1; i <= n; ++i) {
        med_int naxis = MEDmeshnAxis(file.id(), i);
        if (naxis < 0) damaged(file.path(), fmt::format("the header of mesh number {}", i));
        char name[MED_NAME_SIZE + 1] = {}, desc[MED_COMMENT_SIZE + 1] = {}, dtunit[MED_SNAME_SIZE + 1] = {};
        std::string axisName(size_t(std::max<med_int>(naxis, 3)) * MED_SNAME_SIZE + 1, '\0');
        std::string axisUnit(axisName.size(), '\0');
        MeshHeader h;
        med_sorting_type sort;
        med_int nstep = 0;
        med_axis_type axisType;
        if (MEDmeshInfo(file.id(), i, name, &h.spaceDim, &h.meshDim, &h.type, desc, dtunit, &sort, &nstep, &axisType,
                        axisName.data(), axisUnit.data()) < 0)
            damaged(file.path(), fmt::format("the header of mesh number {}", i));
        h.name = trimName(name, MED_NAME_SIZE);
        out.push_back(h);
    }
    return out;
}

// Names of `n` entities (16 characters each in the file), first 8 characters kept as code_aster.
std::vector<std::string> splitNames(const std::vector<char>& buf, med_int n) {
    std::vector<std::string> names(static_cast<size_t>(n));
    for (med_int i = 0; i < n; ++i) {
        // trimName's rule (up to the first NUL, trailing blanks off), cut at 8, blanks off again;
        // the string is built once (millions of names in a refined mesh).
        const char* p = buf.data() + size_t(i) * MED_SNAME_SIZE;
        size_t len = 0;
        while (len < MED_SNAME_SIZE && p[len] != '\0') ++len;
        while (len > 0 && p[len - 1] == ' ') --len;
        if (len > 8) len = 8;
        while (len > 0 && p[len - 1] == ' ') --len;
        names[size_t(i)].assign(p, len);
    }
    return names;
}

struct Family {
    std::vector<int> groups;  // indices into the group name table
};

// The mesh `header` of a MED file, read step by step into a Mesh.
class MeshReader {
public:
    MeshReader(const std::string& path, const MedFile& file, const MeshHeader& header, MeshReadReport* report)
        : path_(path),
          fid_(file.id()),
          header_(header),
          mname_(header.name.c_str()),
          where_("mesh '" + header.name + "'"),
          report_(report),
          mesh_(std::make_shared<Mesh>()) {
        med_float dt = 0;
        if (MEDmeshComputationStepInfo(fid_, mname_, 1, &numdt_, &numit_, &dt) < 0)
            damaged(path_, "the computation step of " + where_);
        mesh_->dim = int(header.spaceDim);
    }

    std::shared_ptr<Mesh> read() {
        readNodes();
        const auto types = cellTypes();
        reserveCells(types);
        for (med_geometry_type geo : types) readCells(geo);
        readFamilies();
        buildGroups(nodeFamily_, mesh_->nodeGroups);
        buildGroups(cellFamily_, mesh_->cellGroups);
        return mesh_;
    }

private:
    med_int count(med_entity_type ent, med_geometry_type geo, med_data_type data, med_connectivity_mode mode) {
        med_bool changed, transformed;
        return MEDmeshnEntity(fid_, mname_, numdt_, numit_, ent, geo, data, mode, &changed, &transformed);
    }

    // An optional dataset (family numbers, names) of `n` entities: absent, or present with one value
    // per entity; anything else is a damaged file (and would overflow the read buffer).
    bool present(med_entity_type ent, med_geometry_type geo, med_data_type data, med_int n, const std::string& what) {
        const med_int m = count(ent, geo, data, MED_NODAL);
        if (m < 0) damaged(path_, what);
        if (m > 0 && m != n) damaged(path_, fmt::format("{} ({} values for {} entities)", what, m, n));
        return m > 0;
    }

    void readNodes() {
        const med_int spaceDim = header_.spaceDim;
        nnode_ = count(MED_NODE, MED_NONE, MED_COORDINATE, MED_NO_CMODE);
        if (nnode_ < 0) damaged(path_, "the number of nodes of " + where_);
        std::vector<med_float> xyz(size_t(nnode_) * size_t(spaceDim));
        if (nnode_ > 0 && MEDmeshNodeCoordinateRd(fid_, mname_, numdt_, numit_, MED_FULL_INTERLACE, xyz.data()) < 0)
            damaged(path_, "the node coordinates of " + where_);
        mesh_->coords.resize(size_t(nnode_));
        for (med_int i = 0; i < nnode_; ++i)
            for (int d = 0; d < 3; ++d)
                mesh_->coords[size_t(i)][size_t(d)] = d < spaceDim ? xyz[size_t(i) * spaceDim + d] : 0.0;
        xyz = {};
        nodeFamily_.assign(size_t(nnode_), 0);
        if (present(MED_NODE, MED_NONE, MED_FAMILY_NUMBER, nnode_, "the node family numbers of " + where_) &&
            MEDmeshEntityFamilyNumberRd(fid_, mname_, numdt_, numit_, MED_NODE, MED_NONE, nodeFamily_.data()) < 0)
            damaged(path_, "the node family numbers of " + where_);
        if (present(MED_NODE, MED_NONE, MED_NAME, nnode_, "the node names of " + where_)) {
            std::vector<char> buf(size_t(nnode_) * MED_SNAME_SIZE + 1);
            if (MEDmeshEntityNameRd(fid_, mname_, numdt_, numit_, MED_NODE, MED_NONE, buf.data()) < 0)
                damaged(path_, "the node names of " + where_);
            mesh_->nodeNames = splitNames(buf, nnode_);
            for (med_int i = 0; i < nnode_; ++i)
                if (mesh_->nodeNames[size_t(i)].empty()) mesh_->nodeNames[size_t(i)] = fmt::format("N{}", i + 1);
        } else {
            mesh_->nodeNames.resize(size_t(nnode_));
            for (med_int i = 0; i < nnode_; ++i) mesh_->nodeNames[size_t(i)] = fmt::format("N{}", i + 1);
        }
    }

    // Cell types present, in increasing MED type code (code_aster numbering). Every fixed type is
    // probed by number (as mdump does) rather than enumerated with MEDmeshEntityInfo, which needs a
    // GEO attribute that some writers (meshio) omit.
    std::vector<med_geometry_type> cellTypes() {
        const med_int ntype = count(MED_CELL, MED_GEO_ALL, MED_CONNECTIVITY, MED_NODAL);
        if (ntype < 0) damaged(path_, "the cell types of " + where_);
        std::vector<med_geometry_type> types;
        for (CellType t :
             {CellType::POI1,   CellType::SEG2,    CellType::SEG3,    CellType::SEG4,   CellType::TRIA3,
              CellType::QUAD4,  CellType::TRIA6,   CellType::TRIA7,   CellType::QUAD8,  CellType::QUAD9,
              CellType::TETRA4, CellType::PYRA5,   CellType::PENTA6,  CellType::HEXA8,  CellType::TETRA10,
              CellType::PYRA13, CellType::PENTA15, CellType::PENTA18, CellType::HEXA20, CellType::HEXA27}) {
            const med_int n = count(MED_CELL, med_geometry_type(t), MED_CONNECTIVITY, MED_NODAL);
            if (n < 0) damaged(path_, "the " + cellTypeName(t) + " cells of " + where_);
            if (n > 0) types.push_back(med_geometry_type(t));
        }
        if (med_int(types.size()) < ntype) refuseUnreadTypes(ntype, types);
        return types;
    }

    // Some cell block was not found by number: either a kind we do not read, or a block whose
    // connectivity is missing (damaged file).
    void refuseUnreadTypes(med_int ntype, const std::vector<med_geometry_type>& types) {
        for (med_int i = 1; i <= ntype; ++i) {
            char tname[MED_NAME_SIZE + 1] = {};
            med_geometry_type geo;
            if (MEDmeshEntityInfo(fid_, mname_, numdt_, numit_, MED_CELL, int(i), tname, &geo) < 0)
                damaged(path_, "the cell types of " + where_);
            if (std::find(types.begin(), types.end(), geo) != types.end()) continue;
            const std::string name = cellTypeName(CellType(geo));
            if (name.rfind("UNKNOWN", 0) != 0)
                damaged(path_, "the connectivity of the " + name + " cells of " + where_);
            throw NotImplemented(
                fmt::format("MED file '{}', {}: cells of MED type {} ({}) are not supported; "
                            "miniaster reads POI1, SEG2/3/4, TRIA3/6/7, QUAD4/8/9, TETRA4/10, "
                            "PYRA5/13, PENTA6/15/18, HEXA8/20/27",
                            path_, where_, trimName(tname, MED_NAME_SIZE), int(geo)));
        }
    }

    // Room for every cell at once (a refined mesh has millions).
    void reserveCells(const std::vector<med_geometry_type>& types) {
        size_t cells = 0, entries = 0;
        for (med_geometry_type geo : types) {
            const med_int n = count(MED_CELL, geo, MED_CONNECTIVITY, MED_NODAL);
            if (n > 0) cells += size_t(n), entries += size_t(n) * nodeCount(static_cast<CellType>(geo));
        }
        mesh_->cellTypes.reserve(cells);
        mesh_->cellOffsets.reserve(cells + 1);
        mesh_->cellNames.reserve(cells);
        mesh_->connectivity.reserve(entries);
        cellFamily_.reserve(cells);
    }

    void readCells(med_geometry_type geo) {
        CellType type = static_cast<CellType>(geo);
        const med_int n = count(MED_CELL, geo, MED_CONNECTIVITY, MED_NODAL);
        if (n < 0) damaged(path_, "the " + cellTypeName(type) + " cells of " + where_);
        if (n == 0) return;
        const int nn = nodeCount(type);
        std::vector<med_int> conn(size_t(n) * nn);
        if (MEDmeshElementConnectivityRd(fid_, mname_, numdt_, numit_, MED_CELL, geo, MED_NODAL, MED_FULL_INTERLACE,
                                         conn.data()) < 0)
            damaged(path_, "the connectivity of the " + cellTypeName(type) + " cells of " + where_);
        std::vector<med_int> fam(size_t(n), 0);
        if (present(MED_CELL, geo, MED_FAMILY_NUMBER, n,
                    "the family numbers of the " + cellTypeName(type) + " cells of " + where_) &&
            MEDmeshEntityFamilyNumberRd(fid_, mname_, numdt_, numit_, MED_CELL, geo, fam.data()) < 0)
            damaged(path_, "the family numbers of the " + cellTypeName(type) + " cells of " + where_);
        std::vector<std::string> names;
        if (present(MED_CELL, geo, MED_NAME, n, "the names of the " + cellTypeName(type) + " cells of " + where_)) {
            std::vector<char> buf(size_t(n) * MED_SNAME_SIZE + 1);
            if (MEDmeshEntityNameRd(fid_, mname_, numdt_, numit_, MED_CELL, geo, buf.data()) < 0)
                damaged(path_, "the names of the " + cellTypeName(type) + " cells of " + where_);
            names = splitNames(buf, n);
        }
        std::vector<int> med(nn), internal(nn);
        for (med_int c = 0; c < n; ++c) {
            for (int j = 0; j < nn; ++j) {
                med_int node = conn[size_t(c) * nn + j];
                if (node < 1 || node > nnode_)
                    throw UserError(
                        fmt::format("MED file '{}', {}: {} cell {} refers to node {} "
                                    "(the mesh has {} nodes)",
                                    path_, where_, cellTypeName(type), c + 1, node, nnode_));
                med[j] = int(node - 1);
            }
            medToInternal(type, med, internal);
            mesh_->addCell(type, internal, names.empty() ? std::string() : std::move(names[size_t(c)]));
        }
        cellFamily_.insert(cellFamily_.end(), fam.begin(), fam.end());
    }

    // A family of a MED 2.3 file (gmsh writes them; MEDfamilyInfo has no 2.3 implementation): its
    // attributes are read and ignored.
    bool family23Info(int f, char* famName, med_int& famNum, std::vector<char>& groups) {
        const med_int na = MEDnFamily23Attribute(fid_, mname_, f);
        if (na < 0) return false;
        const size_t n = size_t(std::max<med_int>(na, 1));
        std::vector<med_int> numbers(n), values(n);
        std::vector<char> descriptions(n * MED_COMMENT_SIZE + 1, '\0');
        return MEDfamily23Info(fid_, mname_, f, famName, numbers.data(), values.data(), descriptions.data(), &famNum,
                               groups.data()) >= 0;
    }

    // Families -> group indices.
    void readFamilies() {
        const med_int nfam = MEDnFamily(fid_, mname_);
        if (nfam < 0) damaged(path_, "the families of " + where_);
        for (med_int f = 1; f <= nfam; ++f) {
            med_int ng = MEDnFamilyGroup(fid_, mname_, int(f));
            if (ng < 0) damaged(path_, "the families of " + where_);
            char famName[MED_NAME_SIZE + 1] = {};
            med_int famNum = 0;
            std::vector<char> groups(size_t(std::max<med_int>(ng, 1)) * MED_LNAME_SIZE + 1, '\0');
            if (MEDfamilyInfo(fid_, mname_, int(f), famName, &famNum, groups.data()) < 0 &&
                !family23Info(int(f), famName, famNum, groups))
                damaged(path_, "the families of " + where_);
            Family& fam = families_[famNum];
            for (med_int g = 0; g < ng; ++g) {
                std::string name = trimName(groups.data() + size_t(g) * MED_LNAME_SIZE, MED_LNAME_SIZE);
                if (name.empty()) continue;
                const std::string kept = keptGroupName(name);
                auto [it, added] = groupIndex_.emplace(kept, int(groupNames_.size()));
                if (added) groupNames_.push_back(kept);
                fam.groups.push_back(it->second);
            }
        }
    }

    // The group name as kept: cut to 24 characters, a second long name cut to the same prefix
    // made unique (alarm MED_7 once per name).
    std::string keptGroupName(const std::string& name) {
        std::string kept = name;
        if (kept.size() <= kMaxGroupName) return kept;
        kept.resize(kMaxGroupName);
        auto clash = renamedFrom_.find(kept);
        for (int k = 1; clash != renamedFrom_.end() && clash->second != name; ++k) {
            std::string suffix = std::to_string(k);
            kept = name.substr(0, kMaxGroupName - suffix.size()) + suffix;
            clash = renamedFrom_.find(kept);
        }
        if (!renamedFrom_.count(kept)) {
            renamedFrom_[kept] = name;
            msg().alarm(MED_7, name, path_, kept);
            if (report_) report_->renamedGroups.emplace_back(name, kept);
        }
        return kept;
    }

    // Members of each group, in entity order; groups are created in order of first appearance in
    // the families (code_aster's order), empty groups are not created.
    void buildGroups(const std::vector<med_int>& familyOf, GroupSet& target) {
        std::vector<std::vector<int>> members(groupNames_.size());
        std::set<med_int> unknown;
        for (size_t e = 0; e < familyOf.size(); ++e) {
            if (familyOf[e] == 0) continue;
            auto it = families_.find(familyOf[e]);
            if (it == families_.end()) {
                unknown.insert(familyOf[e]);
                continue;
            }
            for (int g : it->second.groups) members[size_t(g)].push_back(int(e));
        }
        if (!unknown.empty())
            throw UserError(
                fmt::format("MED file '{}' is damaged or inconsistent, {}: family number {} is used "
                            "but not defined",
                            path_, where_, *unknown.begin()));
        for (size_t g = 0; g < groupNames_.size(); ++g)
            if (!members[g].empty()) target.set(groupNames_[g], std::move(members[g]));
    }

    const std::string& path_;
    const med_idt fid_;
    const MeshHeader& header_;
    const char* mname_;
    const std::string where_;
    MeshReadReport* report_;
    std::shared_ptr<Mesh> mesh_;
    med_int numdt_ = MED_NO_DT, numit_ = MED_NO_IT;
    med_int nnode_ = 0;
    std::vector<med_int> nodeFamily_, cellFamily_;
    std::vector<std::string> groupNames_;  // as kept (cut to 24 characters)
    std::map<std::string, int> groupIndex_;
    std::map<med_int, Family> families_;
    std::map<std::string, std::string> renamedFrom_;  // kept name -> name in file
};

// The mesh named meshName (the first one when empty); refuses grids and space dimensions but 2, 3.
const MeshHeader& chooseMesh(const std::vector<MeshHeader>& headers, const std::string& path,
                             const std::string& meshName) {
    if (headers.empty()) throw UserError("MED file '" + path + "' contains no mesh");
    const MeshHeader* chosen = nullptr;
    if (meshName.empty()) {
        chosen = &headers.front();
    } else {
        for (const auto& h : headers)
            if (h.name == meshName) chosen = &h;
        if (!chosen) {
            std::string list;
            for (const auto& h : headers) list += (list.empty() ? "'" : ", '") + h.name + "'";
            throw UserError("NOM_MED='" + meshName + "': MED file '" + path +
                            "' has no mesh of that name; meshes in the file: " + list);
        }
    }
    if (chosen->type != MED_UNSTRUCTURED_MESH)
        throw NotImplemented("mesh '" + chosen->name + "' of MED file '" + path +
                             "' is a structured (grid) mesh; only unstructured meshes are read");
    if (chosen->spaceDim < 2 || chosen->spaceDim > 3)
        throw NotImplemented(
            fmt::format("mesh '{}' of MED file '{}' has space dimension {}; "
                        "only 2 and 3 are supported",
                        chosen->name, path, chosen->spaceDim));
    return *chosen;
}

}  // namespace

std::vector<std::string> meshNames(const std::string& path) {
    checkReadableMedFile(path);
    MedFile file(path, MED_ACC_RDONLY);
    std::vector<std::string> names;
    for (const auto& h : readHeaders(file)) names.push_back(h.name);
    return names;
}

std::shared_ptr<Mesh> readMesh(const std::string& path, const std::string& meshName, MeshReadReport* report) {
    checkReadableMedFile(path);
    checkMedStructure(path);
    MedFile file(path, MED_ACC_RDONLY);
    const auto headers = readHeaders(file);
    const MeshHeader& chosen = chooseMesh(headers, path, meshName);
    auto mesh = MeshReader(path, file, chosen, report).read();
    file.close();
    if (report) {
        report->meshName = chosen.name;
        report->spaceDim = int(chosen.spaceDim);
        report->meshDim = int(chosen.meshDim);
        for (const auto& h : headers) report->meshesInFile.push_back(h.name);
    }
    mesh->name = chosen.name;
    return mesh;
}

}  // namespace ma::med
