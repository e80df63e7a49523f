#include "med_io/MedResultReader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "core/Error.hpp"
#include "med_io/MedFileHandle.hpp"
#include "med_io/MedReader.hpp"

namespace ma::med {

namespace {

[[noreturn]] void unreadable(const std::string& path, const std::string& what) {
    throw UserError("MED file '" + path + "' is damaged or truncated: cannot read " + what);
}

struct FieldHeader {
    std::string name, mesh;
    med_field_type type = MED_FLOAT64;
    std::vector<std::string> components;
    med_int steps = 0;
};

std::vector<FieldHeader> readFieldHeaders(const MedFile& file) {
    const med_int n = MEDnField(file.id());
    if (n < 0) unreadable(file.path(), "the list of fields");
    std::vector<FieldHeader> out;
    for (int i = 1; i <= int(n); ++i) {
        const med_int nc = MEDfieldnComponent(file.id(), i);
        if (nc < 0) unreadable(file.path(), fmt::format("the components of field number {}", i));
        char name[MED_NAME_SIZE + 1] = {}, mesh[MED_NAME_SIZE + 1] = {}, dtunit[MED_SNAME_SIZE + 1] = {};
        std::string cname(size_t(nc) * MED_SNAME_SIZE + 1, '\0'), cunit(cname.size(), '\0');
        med_bool local;
        FieldHeader h;
        if (MEDfieldInfo(file.id(), i, name, mesh, &local, &h.type, cname.data(), cunit.data(), dtunit, &h.steps) < 0)
            unreadable(file.path(), fmt::format("the header of field number {}", i));
        h.name = trimName(name, MED_NAME_SIZE);
        h.mesh = trimName(mesh, MED_NAME_SIZE);
        for (med_int c = 0; c < nc; ++c)
            h.components.push_back(trimName(cname.data() + c * MED_SNAME_SIZE, MED_SNAME_SIZE));
        out.push_back(std::move(h));
    }
    return out;
}

// Entities (1-based) of a profile; empty for "all entities".
std::vector<med_int> profileMembers(const MedFile& file, const std::string& profile) {
    if (profile.empty() || profile == MED_NO_PROFILE_INTERNAL) return {};
    const med_int size = MEDprofileSizeByName(file.id(), profile.c_str());
    std::vector<med_int> members(size_t(std::max<med_int>(size, 0)));
    if (size < 0 || MEDprofileRd(file.id(), profile.c_str(), members.data()) < 0)
        unreadable(file.path(), "profile " + profile);
    return members;
}

// Where one step of a field is read from.
struct StepPlace {
    const MedFile& file;
    const FieldHeader& field;
    med_int numdt, numit;
    std::string where() const { return fmt::format("field {} at step ({}, {})", field.name, numdt, numit); }
};

// Values of one (entity, geometry) block, every profile of it: calls back with the entity
// numbers (1-based; empty = all), the points per entity and the values (full interlace).
template <class Visit>
void readBlocks(const StepPlace& at, med_entity_type entity, med_geometry_type geo, Visit&& visit) {
    char defaultProfile[MED_NAME_SIZE + 1] = {}, defaultLoc[MED_NAME_SIZE + 1] = {};
    const med_int nprof = MEDfieldnProfile(at.file.id(), at.field.name.c_str(), at.numdt, at.numit, entity, geo,
                                           defaultProfile, defaultLoc);
    const size_t nc = at.field.components.size();
    for (int p = 1; p <= int(nprof); ++p) {
        char profile[MED_NAME_SIZE + 1] = {}, loc[MED_NAME_SIZE + 1] = {};
        med_int profileSize = 0, npoints = 1;
        const med_int n = MEDfieldnValueWithProfile(at.file.id(), at.field.name.c_str(), at.numdt, at.numit, entity,
                                                    geo, p, MED_COMPACT_STMODE, profile, &profileSize, loc, &npoints);
        if (n < 0) unreadable(at.file.path(), at.where());
        if (n == 0) continue;
        std::vector<double> values(size_t(n) * size_t(std::max<med_int>(npoints, 1)) * nc);
        if (MEDfieldValueWithProfileRd(at.file.id(), at.field.name.c_str(), at.numdt, at.numit, entity, geo,
                                       MED_COMPACT_STMODE, profile, MED_FULL_INTERLACE, MED_ALL_CONSTITUENT,
                                       reinterpret_cast<unsigned char*>(values.data())) < 0)
            unreadable(at.file.path(), at.where());
        auto members = profileMembers(at.file, trimName(profile, MED_NAME_SIZE));
        if (!members.empty() && members.size() != size_t(n)) unreadable(at.file.path(), at.where() + " (profile size)");
        visit(members, int(n), int(std::max<med_int>(npoints, 1)), values);
    }
}

std::shared_ptr<NodalField> readNodal(const StepPlace& at, const std::shared_ptr<Mesh>& mesh) {
    auto f = std::make_shared<NodalField>();
    bool any = false;
    readBlocks(at, MED_NODE, MED_NONE,
               [&](const std::vector<med_int>& members, int n, int, const std::vector<double>& v) {
                   if (!any) f->resize(mesh, at.field.components);
                   any = true;
                   const size_t nc = at.field.components.size();
                   for (int i = 0; i < n; ++i) {
                       const int node = members.empty() ? i : int(members[size_t(i)]) - 1;
                       if (node < 0 || node >= mesh->nodeCount())
                           unreadable(at.file.path(), at.where() + " (node number)");
                       for (size_t c = 0; c < nc; ++c) f->set(node, int(c), v[size_t(i) * nc + c]);
                   }
               });
    return any ? f : nullptr;
}

// ELGA (MED_CELL) or ELNO (MED_NODE_ELEMENT) values: one GaussField element per cell.
std::shared_ptr<GaussField> readCellPoints(const StepPlace& at, const std::shared_ptr<Mesh>& mesh,
                                           const std::map<CellType, int>& firstCell) {
    auto g = std::make_shared<GaussField>();
    g->mesh = mesh;
    g->components = at.field.components;
    const size_t nc = g->components.size();
    for (med_entity_type entity : {MED_CELL, MED_NODE_ELEMENT}) {
        for (const auto& [type, first] : firstCell) {
            readBlocks(at, entity, static_cast<med_geometry_type>(type),
                       [&](const std::vector<med_int>& members, int n, int npoints, const std::vector<double>& v) {
                           for (int i = 0; i < n; ++i) {
                               const int k = members.empty() ? i : int(members[size_t(i)]) - 1;
                               const int cell = first + k;
                               if (k < 0 || cell >= mesh->cellCount() || mesh->cellTypes[size_t(cell)] != type)
                                   unreadable(at.file.path(), at.where() + " (cell number)");
                               g->atNodes = entity == MED_NODE_ELEMENT;
                               g->cells.push_back(cell);
                               g->pointOffsets.push_back(g->pointOffsets.back() + npoints);
                               g->pointWeights.insert(g->pointWeights.end(), size_t(npoints), 1.0);
                               const auto* row = v.data() + size_t(i) * size_t(npoints) * nc;
                               g->values.insert(g->values.end(), row, row + size_t(npoints) * nc);
                           }
                       });
        }
    }
    return g->cells.empty() ? nullptr : g;
}

}  // namespace

std::vector<MedResultMesh> readResults(const std::string& path) {
    std::vector<MedResultMesh> out;
    for (const auto& name : meshNames(path)) out.push_back({name, readMesh(path, name), {}});
    MedFile file(path, MED_ACC_RDONLY);
    for (const auto& h : readFieldHeaders(file)) {
        auto target = std::find_if(out.begin(), out.end(), [&](const MedResultMesh& m) { return m.name == h.mesh; });
        if (target == out.end())
            throw UserError(fmt::format("MED file '{}': field {} is defined on mesh '{}', which is not in the file",
                                        path, h.name, h.mesh));
        if (h.type != MED_FLOAT64)
            throw NotImplemented(
                fmt::format("MED file '{}': field {} does not hold 64-bit reals (MED type {}); "
                            "only real fields are read",
                            path, h.name, int(h.type)));
        std::map<CellType, int> firstCell;  // cells are numbered type by type (readMesh)
        const auto& mesh = target->mesh;
        for (int c = mesh->cellCount() - 1; c >= 0; --c) firstCell[mesh->cellTypes[size_t(c)]] = c;
        MedField field{h.name, h.components, {}};
        for (int s = 1; s <= int(h.steps); ++s) {
            MedFieldStep step;
            med_int numdt = 0, numit = 0;
            if (MEDfieldComputingStepInfo(file.id(), h.name.c_str(), s, &numdt, &numit, &step.dt) < 0)
                unreadable(path, fmt::format("step {} of field {}", s, h.name));
            step.numdt = int(numdt);
            step.numit = int(numit);
            const StepPlace at{file, h, numdt, numit};
            step.nodal = readNodal(at, mesh);
            step.cellPoints = readCellPoints(at, mesh, firstCell);
            if (step.nodal || step.cellPoints) field.steps.push_back(std::move(step));
        }
        target->fields.push_back(std::move(field));
    }
    file.close();
    return out;
}

}  // namespace ma::med
