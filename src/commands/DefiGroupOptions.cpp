#include "commands/DefiGroupOptions.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "mesh/GeometricSelection.hpp"
#include "mesh/GroupSelection.hpp"
#include "mesh/LineOrdering.hpp"
#include "mesh/MeshMessages.hpp"
#include "xfem/Crack.hpp"

namespace ma::defi_group {
namespace {

const char* dimensionWord(int dim) { return dim == 2 ? "a plane mesh (constant z)" : "a 3D mesh"; }

// A vector keyword that must have exactly `count` values (code_aster reads exactly that many).
Vec3 exactVector(const KeywordSet& occ, const std::string& keyword, size_t count, const char* why) {
    const auto v = occ.reals(keyword);
    if (v.size() != count)
        throw UserError(fmt::format("{} has {} values; it needs {} ({})", occ.pathOf(keyword), v.size(), count, why));
    return {v[0], v[1], count > 2 ? v[2] : 0.0};
}

double positive(const KeywordSet& occ, const std::string& keyword) {
    const double x = occ.real(keyword);
    if (!(x > 0)) throw UserError(fmt::format("{} must be strictly positive (got {:g})", occ.pathOf(keyword), x));
    return x;
}

int namedNode(const Mesh& mesh, const KeywordSet& occ, const std::string& keyword) {
    const std::string name = occ.text(keyword);
    const int node = mesh.findNode(name);
    if (node < 0) throw UserError(fmt::format("{}: the mesh has no node '{}'", occ.pathOf(keyword), name));
    return node;
}

// The first node of a group meant to hold one; `alarm` when it holds several.
template <class Alarm>
int groupNode(const Mesh& mesh, const KeywordSet& occ, const std::string& keyword, const Alarm& alarm) {
    const std::string name = occ.text(keyword);
    const auto& nodes = namedGroup(mesh, GroupKind::Nodes, name, occ.pathOf(keyword));
    if (nodes.size() > 1) msg().alarm(alarm, occ.pathOf(keyword), name, nodes.size(), mesh.nodeNames[size_t(nodes[0])]);
    return nodes.front();
}

// POINT, NOEUD_CENTRE or GROUP_NO_CENTRE (code_aster's utcono): dim coordinates, z = 0 in a plane mesh.
Vec3 centre(const Mesh& mesh, const KeywordSet& occ, int dim) {
    if (occ.has("POINT")) return exactVector(occ, "POINT", size_t(dim), dimensionWord(dim));
    const int node = occ.has("NOEUD_CENTRE") ? namedNode(mesh, occ, "NOEUD_CENTRE")
                                             : groupNode(mesh, occ, "GROUP_NO_CENTRE", MODELISA9_29);
    Vec3 x = mesh.coords[size_t(node)];
    if (dim == 2) x[2] = 0;
    return x;
}

// 2 or 3 values, z = 0 when 2 (FACE_NORMALE's VECT_NORMALE, BANDE's POINT and VECT_NORMALE).
Vec3 flexibleVector(const KeywordSet& occ, const std::string& keyword) {
    auto v = occ.reals(keyword);
    if (v.size() < 2 || v.size() > 3)
        throw UserError(fmt::format("{} expects 2 or 3 values, got {}", occ.pathOf(keyword), v.size()));
    return {v[0], v[1], v.size() > 2 ? v[2] : 0.0};
}

// VECT_NORMALE or ANGL_NAUT. PLAN takes dim components, the cylinders 3; ANGL_NAUT takes dim - 1
// angles (PLAN, BANDE, FACE_NORMALE) or 2 (the cylinders).
Vec3 direction(const KeywordSet& occ, int dim) {
    const std::string option = occ.text("OPTION");
    const bool plan = option == "PLAN" || option == "BANDE" || option == "FACE_NORMALE";
    if (occ.has("VECT_NORMALE"))
        return exactVector(occ, "VECT_NORMALE", size_t(plan ? dim : 3),
                           plan ? dimensionWord(dim) : "the cylinder's axis");
    const auto angles = occ.reals("ANGL_NAUT");
    const size_t needed = plan ? size_t(dim - 1) : 2;
    if (angles.size() < needed || (!plan && angles.size() != needed))
        throw UserError(
            fmt::format("{} has {} values; it needs {} here", occ.pathOf("ANGL_NAUT"), angles.size(), needed));
    return nauticalDirection(angles[0], needed > 1 ? angles[1] : 0.0, plan ? dim : 3);
}

std::vector<int> nodesOnPlaneOption(const Mesh& mesh, const KeywordSet& occ, int dim) {
    const Vec3 point = centre(mesh, occ, dim), normal = direction(occ, dim);
    if (!(norm(normal) > 0)) throw UserError(occ.pathOf("VECT_NORMALE") + ": the normal vector is zero");
    return nodesOnPlane(mesh, point, normal, positive(occ, "PRECISION"));
}

// The nodes of NOEUD and GROUP_NO, in increasing node number (code_aster's reliem).
std::vector<int> listedNodes(const Mesh& mesh, const KeywordSet& occ) {
    std::vector<char> mark(size_t(mesh.nodeCount()), 0);
    if (occ.has("GROUP_NO"))
        for (const auto& g : occ.texts("GROUP_NO"))
            for (int n : namedGroup(mesh, GroupKind::Nodes, g, occ.pathOf("GROUP_NO"))) mark[size_t(n)] = 1;
    if (occ.has("NOEUD"))
        for (const auto& name : occ.texts("NOEUD")) {
            const int n = mesh.findNode(name);
            if (n < 0) throw UserError(fmt::format("{}: the mesh has no node '{}'", occ.pathOf("NOEUD"), name));
            mark[size_t(n)] = 1;
        }
    std::vector<int> nodes;
    for (int i = 0; i < mesh.nodeCount(); ++i)
        if (mark[size_t(i)]) nodes.push_back(i);
    return nodes;
}

// NOEUD_xxx or GROUP_NO_xxx (xxx = ORIG or EXTR); -1 when neither is given.
int lineEnd(const Mesh& mesh, const KeywordSet& occ, const std::string& which) {
    if (occ.has("NOEUD_" + which)) return namedNode(mesh, occ, "NOEUD_" + which);
    if (occ.has("GROUP_NO_" + which)) return groupNode(mesh, occ, "GROUP_NO_" + which, SOUSTRUC_87);
    return -1;
}

std::vector<int> segmentOption(const Mesh& mesh, const KeywordSet& occ) {
    const int origin = lineEnd(mesh, occ, "ORIG"), extremity = lineEnd(mesh, occ, "EXTR");
    auto nodes = listedNodes(mesh, occ);
    if (nodes.empty()) throw UserError(occ.path() + ": NOEUD and GROUP_NO hold no node");
    return orderAlongSegment(mesh, std::move(nodes), origin, extremity, occ.real("PRECISION"),
                             occ.text("CRITERE") == "RELATIF");
}

std::vector<int> lineOption(const Mesh& mesh, const KeywordSet& occ) {
    std::vector<char> mark(size_t(mesh.cellCount()), 0);
    for (const auto& g : occ.texts("GROUP_MA"))
        for (int c : namedGroup(mesh, GroupKind::Cells, g, occ.pathOf("GROUP_MA"))) mark[size_t(c)] = 1;
    std::vector<int> cells;
    for (int c = 0; c < mesh.cellCount(); ++c)
        if (mark[size_t(c)]) cells.push_back(c);
    LineEnds ends;
    ends.origin = lineEnd(mesh, occ, "ORIG");
    ends.extremity = lineEnd(mesh, occ, "EXTR");
    if (occ.has("VECT_ORIE")) ends.orientation = exactVector(occ, "VECT_ORIE", 3, "a direction in space");
    ends.anyOrigin = occ.has("ORIGINE");
    return nodesAlongLine(mesh, std::move(cells), ends);
}

std::vector<std::shared_ptr<xfem::Crack>> cracksOf(const Mesh& mesh, const KeywordSet& occ) {
    auto cracks = occ.objects<xfem::Crack>("FISSURE");
    for (const auto& c : cracks)
        if (c->mesh.get() != &mesh)
            throw UserError(fmt::format("{}: interface {} is defined on another mesh", occ.pathOf("FISSURE"), c->name));
    return cracks;
}

// FISS_XFEM nodes, interface after interface as code_aster lists them (a node enriched by two
// interfaces is listed twice). Interfaces have Heaviside nodes only (STNO 1): CRACKTIP and MIXTE are empty.
std::vector<int> xfemNodes(const Mesh& mesh, const KeywordSet& occ) {
    const std::string type = occ.text("TYPE_GROUP");
    std::vector<int> nodes;
    if (type == "CRACKTIP" || type == "MIXTE") return nodes;
    for (const auto& crack : cracksOf(mesh, occ))
        for (int i = 0; i < mesh.nodeCount(); ++i)
            if (crack->nodeStatus[size_t(i)] != 0) nodes.push_back(i);
    return nodes;
}

// FISS_XFEM cells: HEAVISIDE and XFEM are the enriched cells interface after interface (a cell
// enriched by two interfaces is listed twice); FISSUREE keeps those whose nodes are all enriched.
std::vector<int> xfemCells(const Mesh& mesh, const KeywordSet& occ) {
    const std::string type = occ.text("TYPE_GROUP");
    std::vector<int> cells;
    if (type == "CRACKTIP" || type == "MIXTE") return cells;
    for (const auto& crack : cracksOf(mesh, occ))
        for (int c : crack->heavisideCells) {
            bool allEnriched = true;
            for (int n : mesh.cellNodes(c)) allEnriched = allEnriched && crack->nodeStatus[size_t(n)] != 0;
            if (type != "FISSUREE" || allEnriched) cells.push_back(c);
        }
    return cells;
}

}  // namespace

std::vector<int> cellOption(const Mesh& mesh, const KeywordSet& occ) {
    const std::string option = occ.text("OPTION");
    const int dim = effectiveDimension(mesh);
    if (option == "FACE_NORMALE") {
        const Vec3 v = occ.has("VECT_NORMALE") ? flexibleVector(occ, "VECT_NORMALE") : direction(occ, dim);
        return cellsWithNormal(mesh, v, occ.real("ANGL_PREC"), occ.text("VERI_SIGNE") == "OUI");
    }
    if (option == "BANDE") {
        const Vec3 point = occ.has("POINT") ? flexibleVector(occ, "POINT") : centre(mesh, occ, dim);
        const Vec3 n = occ.has("VECT_NORMALE") ? flexibleVector(occ, "VECT_NORMALE") : direction(occ, dim);
        return cellsInBand(mesh, point, n, occ.real("DIST"), occ.text("CRIT_NOEUD"));
    }
    if (option == "SPHERE")
        return cellsInSphere(mesh, centre(mesh, occ, dim), positive(occ, "RAYON"),
                             cellCriterion(occ.text("CRIT_NOEUD")));
    if (option == "CYLINDRE") {
        if (dim != 3) throw UserError(occ.pathOf("OPTION") + "='CYLINDRE' needs a 3D mesh");
        return cellsInCylinder(mesh, centre(mesh, occ, dim), direction(occ, dim), positive(occ, "RAYON"),
                               cellCriterion(occ.text("CRIT_NOEUD")));
    }
    if (option == "FISS_XFEM") return xfemCells(mesh, occ);
    throw NotImplemented(occ.pathOf("OPTION") + "='" + option + "' is not supported");
}

std::vector<int> nodeOption(const Mesh& mesh, const KeywordSet& occ) {
    const std::string option = occ.text("OPTION");
    const int dim = effectiveDimension(mesh);
    if (option == "PLAN") return nodesOnPlaneOption(mesh, occ, dim);
    if (option == "ENV_SPHERE")
        return nodesOnSphere(mesh, centre(mesh, occ, dim), positive(occ, "RAYON"), positive(occ, "PRECISION"));
    if (option == "ENV_CYLINDRE") {
        if (dim != 3) throw UserError(occ.pathOf("OPTION") + "='ENV_CYLINDRE' needs a 3D mesh");
        return nodesOnCylinder(mesh, centre(mesh, occ, dim), direction(occ, dim), positive(occ, "RAYON"),
                               positive(occ, "PRECISION"));
    }
    if (option == "SEGM_DROI_ORDO") return segmentOption(mesh, occ);
    if (option == "NOEUD_ORDO") return lineOption(mesh, occ);
    if (option == "FISS_XFEM") return xfemNodes(mesh, occ);
    throw NotImplemented(occ.pathOf("OPTION") + "='" + option + "' is not supported");
}

}  // namespace ma::defi_group
