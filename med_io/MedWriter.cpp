#include "med_io/MedWriter.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "med_io/MedCellOrder.hpp"
#include "med_io/MedFileHandle.hpp"
#include "med_io/MedMessages.hpp"
#include "mesh/ElementGeometry.hpp"
#include "mesh/ShapeFunctions.hpp"

namespace ma::med {

std::string resultFieldName(const std::string& resultName, const std::string& fieldName) {
    std::string base = resultName;
    if (base.size() < 8) base.resize(8, '_');
    return base + fieldName;
}

namespace {

// Cell types in increasing MED code: the order code_aster writes and numbers them in.
std::vector<CellType> typesInOrder(const Mesh& mesh) {
    std::set<int> codes;
    for (auto t : mesh.cellTypes) codes.insert(int(t));
    std::vector<CellType> out;
    for (int c : codes) out.push_back(CellType(c));
    return out;
}

// One family per distinct set of groups, numbered sign*1, sign*2 ... in order of first
// appearance of the entities; 0 for entities in no group.
struct Families {
    std::vector<med_int> number;                                     // per entity
    std::vector<std::pair<med_int, std::vector<std::string>>> list;  // (number, group names)
};

Families buildFamilies(int entityCount, const GroupSet& groups, int sign) {
    std::vector<std::vector<int>> of(static_cast<size_t>(entityCount));
    const auto& names = groups.names();
    for (size_t g = 0; g < names.size(); ++g)
        for (int e : groups.get(names[g]))
            if (of[size_t(e)].empty() || of[size_t(e)].back() != int(g)) of[size_t(e)].push_back(int(g));
    Families fam;
    fam.number.assign(size_t(entityCount), 0);
    std::map<std::vector<int>, med_int> index;
    for (int e = 0; e < entityCount; ++e) {
        auto& set = of[size_t(e)];
        if (set.empty()) continue;
        std::sort(set.begin(), set.end());
        set.erase(std::unique(set.begin(), set.end()), set.end());
        auto it = index.find(set);
        if (it == index.end()) {
            med_int num = sign * med_int(index.size() + 1);
            it = index.emplace(set, num).first;
            std::vector<std::string> g;
            for (int k : set) g.push_back(names[size_t(k)]);
            fam.list.emplace_back(num, std::move(g));
        }
        fam.number[size_t(e)] = it->second;
    }
    return fam;
}

std::string joinedFamilyName(const std::vector<std::string>& groups) {
    std::string s;
    for (const auto& g : groups) s += (s.empty() ? "" : "_") + g;
    return s;
}

std::string padded16(const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += padName(n, MED_SNAME_SIZE);
    return s;
}

// Reference-element measure at xi: |det J| for a cell of the space dimension, the area/length
// element sqrt(det(J^T J)) for faces and edges.
double measureAt(CellType type, std::span<const std::array<double, 3>> nodes, const std::array<double, 3>& xi) {
    std::vector<double> dN(nodes.size() * 3);
    shapeDerivatives(type, xi, dN);
    double J[3][3];
    jacobian(nodes, dN, referenceDimension(type), J);
    return jacobianMeasure(J, referenceDimension(type));
}

// Cells, type by type in increasing MED code: connectivity, names, numbers, families.
template <class Fail>
void writeCells(med_idt fid, const Mesh& mesh, const std::string& meshName, const Families& cellFam, const Fail& fail) {
    for (CellType type : typesInOrder(mesh)) {
        const int nper = nodeCount(type);
        std::vector<med_int> conn, fam, num;
        std::string names;
        std::vector<int> med(static_cast<size_t>(nper));
        for (int c = 0; c < mesh.cellCount(); ++c) {
            if (mesh.cellTypes[size_t(c)] != type) continue;
            internalToMed(type, mesh.cellNodes(c), med);
            for (int v : med) conn.push_back(v + 1);
            fam.push_back(cellFam.number[size_t(c)]);
            num.push_back(c + 1);
            names += padName(mesh.cellNames[size_t(c)], MED_SNAME_SIZE);
        }
        const med_int n = med_int(fam.size());
        const auto geo = med_geometry_type(type);
        const std::string what = "the " + cellTypeName(type) + " cells";
        if (MEDmeshElementConnectivityWr(fid, meshName.c_str(), MED_NO_DT, MED_NO_IT, 0.0, MED_CELL, geo, MED_NODAL,
                                         MED_FULL_INTERLACE, n, conn.data()) < 0 ||
            MEDmeshEntityNameWr(fid, meshName.c_str(), MED_NO_DT, MED_NO_IT, MED_CELL, geo, n, names.c_str()) < 0 ||
            MEDmeshEntityNumberWr(fid, meshName.c_str(), MED_NO_DT, MED_NO_IT, MED_CELL, geo, n, num.data()) < 0 ||
            MEDmeshEntityFamilyNumberWr(fid, meshName.c_str(), MED_NO_DT, MED_NO_IT, MED_CELL, geo, n, fam.data()) < 0)
            fail(what);
    }
}

// Families: names are the joined group names (<= 64 characters) or FAMILLE_<n>.
template <class Fail>
void writeFamilies(med_idt fid, const std::string& meshName, const Families& fams, const Fail& fail) {
    std::set<std::string> used;
    for (const auto& [num, groups] : fams.list) {
        std::string name = joinedFamilyName(groups);
        if (name.size() > MED_NAME_SIZE || used.count(name)) name = fmt::format("FAMILLE_{}", std::abs(num));
        for (int k = 2; used.count(name); ++k) name = fmt::format("FAMILLE_{}_{}", std::abs(num), k);
        used.insert(name);
        std::string g;
        for (const auto& s : groups) g += padName(s, MED_LNAME_SIZE);
        if (MEDfamilyCr(fid, meshName.c_str(), name.c_str(), num, med_int(groups.size()), g.c_str()) < 0)
            fail("family " + name);
    }
}

// Index of each cell among the cells of its type, as written by writeMesh.
std::vector<int> ranksInType(const Mesh& mesh) {
    std::vector<int> rankInType(size_t(mesh.cellCount()));
    std::map<CellType, int> seen;
    for (int c = 0; c < mesh.cellCount(); ++c) rankInType[size_t(c)] = seen[mesh.cellTypes[size_t(c)]]++;
    return rankInType;
}

// Elements of a Gauss field grouped by cell type, then by their exact set of reference points
// (one MED localisation each). Elements of a type without a reference element are counted in
// `skipped` and left out, with an alarm.
std::map<CellType, std::map<std::vector<double>, std::vector<int>>> elementsByLocalisation(const std::string& fieldName,
                                                                                           const GaussField& field,
                                                                                           int& skipped) {
    const Mesh& mesh = *field.mesh;
    std::map<CellType, std::map<std::vector<double>, std::vector<int>>> groups;
    std::set<std::string> skippedTypes;
    for (int e = 0; e < int(field.cells.size()); ++e) {
        const CellType type = mesh.cellTypes[size_t(field.cells[size_t(e)])];
        if (!hasShapeFunctions(type)) {
            ++skipped;
            skippedTypes.insert(cellTypeName(type));
            continue;
        }
        std::vector<double> key;
        for (int p = field.pointOffsets[size_t(e)]; p < field.pointOffsets[size_t(e) + 1]; ++p)
            key.insert(key.end(), field.pointRefCoords[size_t(p)].begin(), field.pointRefCoords[size_t(p)].end());
        groups[type][key].push_back(e);
    }
    if (skipped > 0) msg().alarm(MED_ELGA, fieldName, skipped, fmt::format("{}", fmt::join(skippedTypes, " ")));
    return groups;
}

}  // namespace

struct MedWriter::Impl {
    AtomicPath target;
    std::unique_ptr<MedFile> file;
    std::map<std::string, std::string> profiles;  // content key -> profile name
    std::set<std::string> usedProfileNames, usedLocalizationNames;
    std::map<std::string, std::string> localizations;  // content key -> localisation name

    explicit Impl(const std::string& path) : target(path) {}
    med_idt fid() const { return file->id(); }
    const std::string& path() const { return file->path(); }

    std::string profile(const std::vector<med_int>& members) {
        std::string key(reinterpret_cast<const char*>(members.data()), members.size() * sizeof(med_int));
        auto it = profiles.find(key);
        if (it != profiles.end()) return it->second;
        std::string name;
        for (int k = int(usedProfileNames.size()) + 1;; ++k) {
            name = fmt::format("PROFIL_{}", k);
            if (!usedProfileNames.count(name)) break;
        }
        if (MEDprofileWr(fid(), name.c_str(), med_int(members.size()), members.data()) < 0)
            throwMedError("MED file '" + target.finalPath() + "': cannot write profile " + name);
        usedProfileNames.insert(name);
        profiles.emplace(key, name);
        return name;
    }

    void loadExistingNames() {
        med_int np = MEDnProfile(fid());
        for (med_int i = 1; i <= np; ++i) {
            char name[MED_NAME_SIZE + 1] = {};
            med_int size = 0;
            if (MEDprofileInfo(fid(), int(i), name, &size) >= 0) usedProfileNames.insert(trimName(name, MED_NAME_SIZE));
        }
        med_int nl = MEDnLocalization(fid());
        for (med_int i = 1; i <= nl; ++i) {
            char name[MED_NAME_SIZE + 1] = {}, interp[MED_NAME_SIZE + 1] = {}, sect[MED_NAME_SIZE + 1] = {};
            med_geometry_type geo, sgeo;
            med_int sdim = 0, npt = 0, nsect = 0;
            if (MEDlocalizationInfo(fid(), int(i), name, &geo, &sdim, &npt, interp, sect, &nsect, &sgeo) >= 0)
                usedLocalizationNames.insert(trimName(name, MED_NAME_SIZE));
        }
    }

    // Existing mesh of that name: -1 when absent, else its node count.
    med_int existingMeshNodes(const std::string& meshName) {
        med_int n = MEDnMesh(fid());
        for (med_int i = 1; i <= n; ++i) {
            med_int naxis = MEDmeshnAxis(fid(), i);
            char name[MED_NAME_SIZE + 1] = {}, desc[MED_COMMENT_SIZE + 1] = {}, dtunit[MED_SNAME_SIZE + 1] = {};
            std::string axes(size_t(std::max<med_int>(naxis, 3)) * MED_SNAME_SIZE + 1, '\0'), units = axes;
            med_int sdim, mdim, nstep;
            med_mesh_type mtype;
            med_sorting_type sort;
            med_axis_type atype;
            if (MEDmeshInfo(fid(), i, name, &sdim, &mdim, &mtype, desc, dtunit, &sort, &nstep, &atype, axes.data(),
                            units.data()) < 0)
                continue;
            if (trimName(name, MED_NAME_SIZE) != meshName) continue;
            med_bool chg, trsf;
            return MEDmeshnEntity(fid(), name, MED_NO_DT, MED_NO_IT, MED_NODE, MED_NONE, MED_COORDINATE, MED_NO_CMODE,
                                  &chg, &trsf);
        }
        return -1;
    }

    // Creates the field unless it exists; an existing field must have the same components.
    void ensureField(const std::string& fieldName, const std::string& meshName, const std::vector<std::string>& comps) {
        med_int nf = MEDnField(fid());
        for (med_int i = 1; i <= nf; ++i) {
            med_int nc = MEDfieldnComponent(fid(), int(i));
            if (nc < 0) continue;
            char name[MED_NAME_SIZE + 1] = {}, mesh[MED_NAME_SIZE + 1] = {}, dtunit[MED_SNAME_SIZE + 1] = {};
            std::string cname(size_t(nc) * MED_SNAME_SIZE + 1, '\0'), cunit = cname;
            med_bool local;
            med_field_type type;
            med_int nstep;
            if (MEDfieldInfo(fid(), int(i), name, mesh, &local, &type, cname.data(), cunit.data(), dtunit, &nstep) < 0)
                continue;
            if (trimName(name, MED_NAME_SIZE) != fieldName) continue;
            if (cname.substr(0, size_t(nc) * MED_SNAME_SIZE) != padded16(comps))
                throwMedError(
                    fmt::format("MED file '{}' already holds a field '{}' with other "
                                "components; choose another result name or unit",
                                target.finalPath(), fieldName));
            return;
        }
        const std::string units(comps.size() * MED_SNAME_SIZE, ' ');
        if (MEDfieldCr(fid(), fieldName.c_str(), MED_FLOAT64, med_int(comps.size()), padded16(comps).c_str(),
                       units.c_str(), "", meshName.c_str()) < 0)
            throwMedError("MED file '" + target.finalPath() + "': cannot create field " + fieldName);
    }
    // The localisation of `npt` points of a `type` cell (lkey: type, points and weights), written
    // the first time it is met.
    std::string localisation(CellType type, int npt, const std::string& lkey, const std::vector<med_float>& refNodes,
                             const std::vector<med_float>& pts, const std::vector<med_float>& weights) {
        if (auto found = localizations.find(lkey); found != localizations.end()) return found->second;
        std::string loc;
        for (int k = int(usedLocalizationNames.size()) + 1;; ++k) {
            loc = fmt::format("LOC_{}_{}PG_{}", cellTypeName(type), npt, k);
            if (!usedLocalizationNames.count(loc)) break;
        }
        if (MEDlocalizationWr(fid(), loc.c_str(), med_geometry_type(type), referenceDimension(type), refNodes.data(),
                              MED_FULL_INTERLACE, npt, pts.data(), weights.data(), MED_NO_INTERPOLATION,
                              MED_NO_MESH_SUPPORT) < 0)
            throwMedError("MED file '" + target.finalPath() + "': cannot write localisation " + loc);
        usedLocalizationNames.insert(loc);
        localizations.emplace(lkey, loc);
        return loc;
    }
};

MedWriter::MedWriter(const std::string& path, bool append) : impl_(std::make_unique<Impl>(path)) {
    silenceHdf5Errors();
    namespace fs = std::filesystem;
    std::error_code ec;
    if (append && fs::exists(path, ec)) {
        checkReadableMedFile(path);
        fs::copy_file(path, impl_->target.tempPath(), fs::copy_options::overwrite_existing, ec);
        if (ec) throw UserError("cannot copy '" + path + "' to add results to it: " + ec.message());
        impl_->file = std::make_unique<MedFile>(impl_->target.tempPath(), MED_ACC_RDWR);
        impl_->loadExistingNames();
    } else {
        impl_->file = std::make_unique<MedFile>(impl_->target.tempPath(), MED_ACC_CREAT);
        MEDfileCommentWr(impl_->fid(), "CREE PAR MINIASTER");
    }
}

MedWriter::~MedWriter() = default;

void MedWriter::commit() {
    impl_->file->close();
    impl_->target.commit();
}

bool MedWriter::writeMesh(const Mesh& mesh, const std::string& meshName) {
    const med_idt fid = impl_->fid();
    const std::string& tmp = impl_->target.finalPath();
    auto fail = [&](const std::string& what) {
        throwMedError("MED file '" + tmp + "': cannot write " + what + " of mesh '" + meshName + "'");
    };
    const med_int existing = impl_->existingMeshNodes(meshName);
    if (existing >= 0) {
        if (existing != mesh.nodeCount())
            throw UserError(
                fmt::format("the MED file already holds a mesh named '{}' with {} nodes, "
                            "not the {} nodes of the mesh to print",
                            meshName, existing, mesh.nodeCount()));
        return false;
    }
    const int dim = mesh.dim;
    const char* axes3 = "X               Y               Z               ";
    const std::string axisNames(axes3, size_t(dim) * MED_SNAME_SIZE);
    std::string axisUnits;
    for (int d = 0; d < dim; ++d) axisUnits += padName("INCONNU", MED_SNAME_SIZE);
    if (MEDmeshCr(fid, meshName.c_str(), dim, dim, MED_UNSTRUCTURED_MESH, "CREE PAR MINIASTER", "SANS UNITES",
                  MED_SORT_ITDT, MED_CARTESIAN, axisNames.c_str(), axisUnits.c_str()) < 0)
        fail("the header");

    // Nodes: coordinates, names, families.
    const int nn = mesh.nodeCount();
    std::vector<med_float> xyz(size_t(nn) * size_t(dim));
    for (int i = 0; i < nn; ++i)
        for (int d = 0; d < dim; ++d) xyz[size_t(i) * dim + d] = mesh.coords[size_t(i)][size_t(d)];
    if (MEDmeshNodeCoordinateWr(fid, meshName.c_str(), MED_NO_DT, MED_NO_IT, 0.0, MED_FULL_INTERLACE, nn, xyz.data()) <
        0)
        fail("the node coordinates");
    xyz = {};
    {
        std::string names;
        names.reserve(size_t(nn) * MED_SNAME_SIZE + 1);
        for (const auto& n : mesh.nodeNames) names += padName(n, MED_SNAME_SIZE);
        if (MEDmeshEntityNameWr(fid, meshName.c_str(), MED_NO_DT, MED_NO_IT, MED_NODE, MED_NONE, nn, names.c_str()) < 0)
            fail("the node names");
    }
    const Families nodeFam = buildFamilies(nn, mesh.nodeGroups, +1);
    if (MEDmeshEntityFamilyNumberWr(fid, meshName.c_str(), MED_NO_DT, MED_NO_IT, MED_NODE, MED_NONE, nn,
                                    nodeFam.number.data()) < 0)
        fail("the node families");

    // Cells, type by type in increasing MED code.
    const Families cellFam = buildFamilies(mesh.cellCount(), mesh.cellGroups, -1);
    writeCells(fid, mesh, meshName, cellFam, fail);

    writeFamilies(fid, meshName, nodeFam, fail);
    writeFamilies(fid, meshName, cellFam, fail);
    if (MEDfamilyCr(fid, meshName.c_str(), "FAMILLE_ZERO", 0, 0, "") < 0) fail("family 0");
    return true;
}

void MedWriter::writeNodalField(const std::string& fieldName, const std::string& meshName, const NodalField& field,
                                int numdt, int numit, double dt) {
    const int nc = field.componentCount();
    const int nn = field.mesh ? field.mesh->nodeCount() : 0;
    if (!field.mesh || field.values.size() != size_t(nn) * size_t(nc) || field.present.size() != field.values.size())
        throw UserError("field " + fieldName +
                        " is inconsistent with its mesh (value array size); it cannot be printed");
    std::vector<int> comps;
    std::vector<med_int> nodes;
    std::vector<char> anyNode(size_t(nn), 0);
    std::vector<char> anyComp(size_t(nc), 0);
    for (int i = 0; i < nn; ++i)
        for (int k = 0; k < nc; ++k)
            if (field.has(i, k)) anyNode[size_t(i)] = anyComp[size_t(k)] = 1;
    for (int k = 0; k < nc; ++k)
        if (anyComp[size_t(k)]) comps.push_back(k);
    for (int i = 0; i < nn; ++i)
        if (anyNode[size_t(i)]) nodes.push_back(i + 1);
    if (comps.empty()) {
        msg().alarm(MED_NO_VALUE, fieldName);
        return;
    }
    std::vector<std::string> names;
    for (int k : comps) names.push_back(field.components[size_t(k)]);
    impl_->ensureField(fieldName, meshName, names);

    std::vector<med_float> values;
    values.reserve(nodes.size() * comps.size());
    for (med_int node : nodes)
        for (int k : comps) values.push_back(field.has(int(node - 1), k) ? field.at(int(node - 1), k) : 0.0);
    const std::string profile = int(nodes.size()) == nn ? std::string(MED_NO_PROFILE) : impl_->profile(nodes);
    if (MEDfieldValueWithProfileWr(impl_->fid(), fieldName.c_str(), numdt, numit, dt, MED_NODE, MED_NONE,
                                   MED_COMPACT_STMODE, profile.c_str(), MED_NO_LOCALIZATION, MED_FULL_INTERLACE,
                                   MED_ALL_CONSTITUENT, med_int(nodes.size()),
                                   reinterpret_cast<const unsigned char*>(values.data())) < 0)
        throwMedError(fmt::format("MED file '{}': cannot write field {} at step ({}, {})", impl_->target.finalPath(),
                                  fieldName, numdt, numit));
}

int MedWriter::writeGaussField(const std::string& fieldName, const std::string& meshName, const GaussField& field,
                               int numdt, int numit, double dt) {
    if (!field.mesh) throw UserError("field " + fieldName + " has no mesh");
    if (field.atNodes) {
        writeNodeElementField(fieldName, meshName, field, numdt, numit, dt);
        return 0;
    }
    const Mesh& mesh = *field.mesh;
    const int nc = int(field.components.size());
    const size_t npoints = field.pointWeights.size();
    if (field.pointOffsets.size() != field.cells.size() + 1 || size_t(field.pointOffsets.back()) != npoints ||
        field.pointRefCoords.size() != npoints || field.values.size() != npoints * size_t(nc))
        throw UserError("field " + fieldName +
                        " is incomplete (integration points without reference coordinates or "
                        "values); it cannot be printed with its MED localisations");
    const std::vector<int> rankInType = ranksInType(mesh);
    int skipped = 0;
    const auto groups = elementsByLocalisation(fieldName, field, skipped);
    if (groups.empty()) return skipped;
    impl_->ensureField(fieldName, meshName, field.components);

    for (const auto& [type, bySet] : groups) {
        const auto geo = med_geometry_type(type);
        const int rdim = referenceDimension(type);
        const int nper = nodeCount(type);
        int typeCount = 0;
        for (auto t : mesh.cellTypes) typeCount += t == type;
        // Reference element nodes in MED order.
        auto ref = referenceNodes(type);
        std::vector<med_float> refNodes(size_t(nper) * rdim);
        auto order = medNodeOf(type);
        for (int j = 0; j < nper; ++j) {
            const int medIndex = order.empty() ? j : order[size_t(j)];
            for (int d = 0; d < rdim; ++d) refNodes[size_t(medIndex) * rdim + d] = ref[size_t(j)][size_t(d)];
        }
        for (const auto& [key, elems] : bySet) {
            const int e0 = elems.front();
            const int p0 = field.pointOffsets[size_t(e0)];
            const int npt = field.pointOffsets[size_t(e0) + 1] - p0;
            // Reference weights of the first element: physical weight / Jacobian measure.
            auto cellNodes = mesh.cellNodes(field.cells[size_t(e0)]);
            std::vector<std::array<double, 3>> X;
            for (int v : cellNodes) X.push_back(mesh.coords[size_t(v)]);
            std::vector<med_float> pts(static_cast<size_t>(npt * rdim)), weights(static_cast<size_t>(npt));
            for (int p = 0; p < npt; ++p) {
                const auto& xi = field.pointRefCoords[size_t(p0 + p)];
                for (int d = 0; d < rdim; ++d) pts[size_t(p) * rdim + d] = xi[size_t(d)];
                const double m = measureAt(type, X, xi);
                weights[size_t(p)] = m > 0 ? field.pointWeights[size_t(p0 + p)] / m : 0.0;
            }
            std::string lkey = fmt::format("{}|{}|", int(type), fmt::join(key, ","));
            lkey += fmt::format("{}", fmt::join(weights, ","));
            const std::string loc = impl_->localisation(type, npt, lkey, refNodes, pts, weights);
            // Values: elements in MED order within the type.
            std::vector<int> sorted = elems;
            std::sort(sorted.begin(), sorted.end(), [&](int a, int b) {
                return rankInType[size_t(field.cells[size_t(a)])] < rankInType[size_t(field.cells[size_t(b)])];
            });
            std::vector<med_int> members;
            std::vector<med_float> values;
            values.reserve(sorted.size() * size_t(npt) * nc);
            for (int e : sorted) {
                members.push_back(rankInType[size_t(field.cells[size_t(e)])] + 1);
                const int p = field.pointOffsets[size_t(e)];
                values.insert(values.end(), field.values.begin() + size_t(p) * nc,
                              field.values.begin() + size_t(p + npt) * nc);
            }
            const std::string profile =
                int(members.size()) == typeCount ? std::string(MED_NO_PROFILE) : impl_->profile(members);
            if (MEDfieldValueWithProfileWr(impl_->fid(), fieldName.c_str(), numdt, numit, dt, MED_CELL, geo,
                                           MED_COMPACT_STMODE, profile.c_str(), loc.c_str(), MED_FULL_INTERLACE,
                                           MED_ALL_CONSTITUENT, med_int(members.size()),
                                           reinterpret_cast<const unsigned char*>(values.data())) < 0)
                throwMedError(fmt::format("MED file '{}': cannot write field {} on {} cells at step ({}, {})",
                                          impl_->target.finalPath(), fieldName, cellTypeName(type), numdt, numit));
        }
    }
    return skipped;
}

void MedWriter::writeNodeElementField(const std::string& fieldName, const std::string& meshName,
                                      const GaussField& field, int numdt, int numit, double dt) {
    const Mesh& mesh = *field.mesh;
    const size_t nc = field.components.size();
    const std::vector<int> rankInType = ranksInType(mesh);
    std::map<CellType, std::vector<int>> byType;  // elements, in MED order within their type
    for (size_t e = 0; e < field.cells.size(); ++e) byType[mesh.cellTypes[size_t(field.cells[e])]].push_back(int(e));
    impl_->ensureField(fieldName, meshName, field.components);
    for (auto& [type, elems] : byType) {
        std::sort(elems.begin(), elems.end(), [&](int a, int b) {
            return rankInType[size_t(field.cells[size_t(a)])] < rankInType[size_t(field.cells[size_t(b)])];
        });
        const int nper = nodeCount(type);
        const auto order = medNodeOf(type);
        int typeCount = 0;
        for (auto t : mesh.cellTypes) typeCount += t == type;
        std::vector<med_int> members;
        std::vector<med_float> values(elems.size() * size_t(nper) * nc);
        for (size_t i = 0; i < elems.size(); ++i) {
            const int e = elems[i];
            members.push_back(rankInType[size_t(field.cells[size_t(e)])] + 1);
            for (int j = 0; j < nper; ++j) {
                const size_t medIndex = order.empty() ? size_t(j) : size_t(order[size_t(j)]);
                const size_t from = (size_t(field.pointOffsets[size_t(e)]) + size_t(j)) * nc;
                for (size_t c = 0; c < nc; ++c) values[(i * size_t(nper) + medIndex) * nc + c] = field.values[from + c];
            }
        }
        const std::string profile =
            int(members.size()) == typeCount ? std::string(MED_NO_PROFILE) : impl_->profile(members);
        if (MEDfieldValueWithProfileWr(impl_->fid(), fieldName.c_str(), numdt, numit, dt, MED_NODE_ELEMENT,
                                       med_geometry_type(type), MED_COMPACT_STMODE, profile.c_str(),
                                       MED_NO_LOCALIZATION, MED_FULL_INTERLACE, MED_ALL_CONSTITUENT,
                                       med_int(members.size()),
                                       reinterpret_cast<const unsigned char*>(values.data())) < 0)
            throwMedError(fmt::format("MED file '{}': cannot write ELNO field {} on {} cells at step ({}, {})",
                                      impl_->target.finalPath(), fieldName, cellTypeName(type), numdt, numit));
    }
}

}  // namespace ma::med
