#include "xfem/Crack.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

#include "core/Error.hpp"
#include "mesh/ElementGeometry.hpp"
#include "mesh/PointLocation.hpp"
#include "mesh/ShapeFunctions.hpp"
#include "xfem/CellGeometry.hpp"

namespace ma::xfem {

namespace {

constexpr double kMachineEpsilon = DBL_EPSILON;  // code_aster's r8prem
constexpr double kSnapTolerance = 1e-6;          // xajuls

// Nodal average of the level-set gradient computed at the nodes of every volume cell (§1.3), for
// the nodes of the cut cells (the only ones the contact normals use; 0 elsewhere), or of all
// cells when cutCells is null.
std::vector<std::array<double, 3>> nodalGradient(const Mesh& mesh, const std::vector<double>& lsn,
                                                 const std::vector<int>* cutCells) {
    const int dim = mesh.maxCellDimension();
    std::vector<std::array<double, 3>> grad(mesh.nodeCount(), {0, 0, 0});
    std::vector<int> count(mesh.nodeCount(), 0);
    std::vector<char> wanted(mesh.nodeCount(), cutCells ? 0 : 1);
    if (cutCells)
        for (int c : *cutCells)
            for (int n : mesh.cellNodes(c)) wanted[n] = 1;
    std::array<double, 24> dN{};
    for (int c = 0; c < mesh.cellCount(); ++c) {
        const CellType type = mesh.cellTypes[c];
        if (cellDimension(type) != dim || dim < 2 || !hasShapeFunctions(type)) continue;
        const auto nodes = mesh.cellNodes(c);
        if (std::none_of(nodes.begin(), nodes.end(), [&](int n) { return wanted[n] != 0; })) continue;
        const auto ref = referenceNodes(type);
        for (size_t a = 0; a < nodes.size(); ++a) {
            shapeDerivatives(type, ref[a], dN);
            auto d = [&](int b, int j) { return dN[3 * b + j]; };
            double J[3][3] = {}, inv[3][3] = {};  // J[i][j] = dx_i / dxi_j
            jacobian(
                dim, dim, int(nodes.size()), [&](int b) -> const Vec3& { return mesh.coords[nodes[b]]; }, d, J);
            if (invertJacobian(dim, J, inv) == 0.0) continue;
            Vec3 g{}, gx{};  // dLSN / dxi_j, dLSN / dx_j
            for (size_t b = 0; b < nodes.size(); ++b)
                for (int j = 0; j < dim; ++j) g[j] += lsn[nodes[b]] * dN[3 * b + j];
            physicalGradient(
                dim, inv, [&](int j) { return g[j]; }, gx);
            for (int j = 0; j < 3; ++j) grad[nodes[a]][j] += gx[j];
            ++count[nodes[a]];
        }
    }
    for (int n = 0; n < mesh.nodeCount(); ++n)
        if (count[n] > 0)
            for (int j = 0; j < 3; ++j) grad[n][j] /= count[n];
    return grad;
}

std::string pointText(const JunctionInput& in, int dim) {
    return dim == 3 ? fmt::format("({:g}, {:g}, {:g})", in.point[0], in.point[1], in.point[2])
                    : fmt::format("({:g}, {:g})", in.point[0], in.point[1]);
}

std::string boxText(const Mesh& mesh) {
    std::string s;
    for (int j = 0; j < mesh.dim; ++j) {
        double lo = INFINITY, hi = -INFINITY;
        for (const auto& x : mesh.coords) lo = std::min(lo, x[size_t(j)]), hi = std::max(hi, x[size_t(j)]);
        s += fmt::format("{}[{:g}, {:g}]", j ? " x " : "", lo, hi);
    }
    return s;
}

// The side of POINT (§2.1): the sign of the master's level set interpolated at the point, in the
// cell containing it. code_aster takes the sign at the mesh node nearest to POINT (xinlsj), which
// is the other side, or on the interface, for a point within half a cell of it; the interpolated
// value is the point's own side. A value within kSnapTolerance of the level set's variation
// across that cell (its size in level-set units) is on the interface: no side.
double sideAtPoint(const Mesh& mesh, const PointInCell& at, const Crack& master, const JunctionInput& in) {
    const double value = interpolateAt(mesh, at, master.lsn);
    double lo = INFINITY, hi = -INFINITY;
    for (int n : mesh.cellNodes(at.cell))
        lo = std::min(lo, master.lsn[size_t(n)]), hi = std::max(hi, master.lsn[size_t(n)]);
    const double tolerance = kSnapTolerance * (hi - lo);
    if (!(std::abs(value) > tolerance))
        throw UserError(fmt::format(
            "{}/POINT={}: the level set of the master interface {} is {:g} at that point (interpolated in cell {} "
            "({}) containing it): the point lies on that interface. POINT must lie strictly on one side of {}, "
            "the side where this interface exists: |LSN| above {:g} there ({:g} times the level set's variation "
            "across the cell)",
            in.keywordPath, pointText(in, mesh.dim), master.name, value, mesh.cellNames[size_t(at.cell)],
            cellTypeName(mesh.cellTypes[size_t(at.cell)]), master.name, tolerance, kSnapTolerance));
    return value > 0 ? -1.0 : 1.0;
}

// JONFISS/JONCOEF of a branch (§2.1, §2.2).
std::vector<JunctionMaster> junctionMasters(const Mesh& mesh, const JunctionInput& in) {
    const PointInCell at = locatePoint(mesh, in.point);
    if (at.cell < 0)
        throw UserError(
            fmt::format("{}/POINT={}: the point lies in no cell of mesh {} (bounding box {}); POINT must "
                        "lie inside the mesh, strictly on the side of each master interface where this "
                        "interface exists",
                        in.keywordPath, pointText(in, mesh.dim), mesh.name, boxText(mesh)));
    std::vector<JunctionMaster> out;
    auto contains = [&](const Crack* c) {
        return std::any_of(out.begin(), out.end(), [&](const JunctionMaster& m) { return m.crack.get() == c; });
    };
    for (const auto& master : in.masters) {
        if (master->mesh.get() != &mesh)
            throw UserError(fmt::format("{}: crack {} is defined on another mesh", in.keywordPath, master->name));
        // A listed crack that is a master of another listed one comes through the chain.
        bool inherited = false;
        for (const auto& other : in.masters)
            if (other != master && other->hasMaster(master.get())) inherited = true;
        if (inherited) continue;
        const double coef = sideAtPoint(mesh, at, *master, in);
        if (!contains(master.get())) out.push_back({master, coef, true});
        for (const auto& chained : master->masters)
            if (!contains(chained.crack.get())) out.push_back({chained.crack, chained.coef, false});
    }
    if (out.size() > 10) throw UserError(in.keywordPath + ": a branch interface may depend on at most 10 masters");
    return out;
}

}  // namespace

int Crack::enrichedNodeCount() const { return nodeCountWithStatus(1); }

int Crack::nodeCountWithStatus(int status) const {
    return static_cast<int>(std::count(nodeStatus.begin(), nodeStatus.end(), status));
}

std::vector<std::array<double, 3>> nodalLevelSetGradient(const Mesh& mesh, const std::vector<double>& values) {
    return nodalGradient(mesh, values, nullptr);
}

bool Crack::hasMaster(const Crack* crack) const {
    return std::any_of(masters.begin(), masters.end(), [&](const JunctionMaster& m) { return m.crack.get() == crack; });
}

int snapLevelSet(const Mesh& mesh, std::vector<double>& lsn) {
    const int dim = mesh.maxCellDimension();
    int changes = 0;
    for (int c = 0; c < mesh.cellCount(); ++c) {
        const CellType type = mesh.cellTypes[c];
        if (cellDimension(type) != dim) continue;
        if (!xfemSupports(type)) continue;  // other cells cannot be X-FEM elements anyway
        const auto nodes = mesh.cellNodes(c);
        for (const auto& e : cellEdges(type)) {
            double& a = lsn[nodes[e[0]]];
            double& b = lsn[nodes[e[1]]];
            if (std::abs(a - b) <= kMachineEpsilon) continue;
            const double d = a / (a - b);
            if (std::abs(d) <= kSnapTolerance && a != 0.0) a = 0.0, ++changes;
            if (std::abs(d - 1.0) <= kSnapTolerance && b != 0.0) b = 0.0, ++changes;
        }
    }
    return changes;
}

namespace {

// Cut cells (§1.4): some vertex has LSN * LSN(first vertex) <= 0; only cells of the enrichment zone
// (GROUP_MA_ENRI, code_aster's xmafis) when there is one.
std::vector<int> cutCellsOf(const Mesh& mesh, const std::vector<double>& ls, const std::vector<char>* zone) {
    std::vector<int> cells;
    for (int c = 0; c < mesh.cellCount(); ++c) {
        if (mesh.cellTypes[c] == CellType::POI1) continue;
        if (zone && !(*zone)[size_t(c)]) continue;
        const auto nodes = mesh.cellNodes(c);
        const double pivot = ls[nodes[0]];
        for (size_t k = 1; k < nodes.size(); ++k)
            if (ls[nodes[k]] * pivot <= 0.0) {
                cells.push_back(c);
                break;
            }
    }
    return cells;
}

std::string noCutCellText(const Mesh& mesh, const char* what) {
    return fmt::format(
        "DEFI_FISS: the {} (LSN = 0) does not cut any cell of the mesh {}: it lies outside the structure or on "
        "its boundary; code_aster stops with XFEM_57",
        what, mesh.name);
}

// Heaviside cells (§1.6): every cell but POI1 with an enriched node.
std::vector<int> heavisideCellsOf(const Mesh& mesh, const std::vector<unsigned char>& nodeStatus) {
    std::vector<int> cells;
    for (int c = 0; c < mesh.cellCount(); ++c) {
        if (mesh.cellTypes[c] == CellType::POI1) continue;
        for (int n : mesh.cellNodes(c))
            if (nodeStatus[n]) {
                cells.push_back(c);
                break;
            }
    }
    return cells;
}

}  // namespace

std::shared_ptr<Crack> buildCrack(const std::shared_ptr<const Mesh>& meshPtr, std::vector<double> lsn,
                                  const JunctionInput* junction, const std::vector<char>* zone) {
    const Mesh& mesh = *meshPtr;
    auto crack = std::make_shared<Crack>();
    crack->mesh = meshPtr;
    for (double v : lsn)
        if (!std::isfinite(v)) throw NumericalError("FONC_LN gives a non-finite value at a node");
    crack->adjustedLevelSets = snapLevelSet(mesh, lsn);
    crack->lsn = std::move(lsn);
    crack->lst.assign(crack->lsn.size(), -1.0);
    const auto& ls = crack->lsn;
    if (junction && !junction->masters.empty()) crack->masters = junctionMasters(mesh, *junction);

    crack->cutCells = cutCellsOf(mesh, ls, zone);
    if (crack->cutCells.empty())
        throw UserError(noCutCellText(mesh, zone ? "interface (in GROUP_MA_ENRI)" : "interface"));
    crack->lsnGradient = nodalGradient(mesh, ls, &crack->cutCells);

    // Node status (§1.5): min * max of LSN over the vertices of the cut cells around the node < 0.
    const int nn = mesh.nodeCount();
    std::vector<double> lo(nn, std::numeric_limits<double>::infinity());
    std::vector<double> hi(nn, -std::numeric_limits<double>::infinity());
    const size_t nm = crack->masters.size();
    // Junction correction (§2.4): minimum over the branch zero points of coef * LSN_master.
    std::vector<double> minJunction(nm * nn, std::numeric_limits<double>::infinity());
    std::vector<double> cellJunction(nm);
    for (int c : crack->cutCells) {
        const auto nodes = mesh.cellNodes(c);
        double cmin = std::numeric_limits<double>::infinity(), cmax = -cmin;
        for (int n : nodes) cmin = std::min(cmin, ls[n]), cmax = std::max(cmax, ls[n]);
        for (int n : nodes) lo[n] = std::min(lo[n], cmin), hi[n] = std::max(hi[n], cmax);
        if (nm == 0) continue;
        std::fill(cellJunction.begin(), cellJunction.end(), std::numeric_limits<double>::infinity());
        auto addPoint = [&](int a, int b, double t) {  // point a + t (b - a) on an edge
            for (size_t k = 0; k < nm; ++k) {
                const auto& m = crack->masters[k];
                const double va = m.coef * m.crack->lsn[a], vb = m.coef * m.crack->lsn[b];
                cellJunction[k] = std::min(cellJunction[k], va + t * (vb - va));
            }
        };
        const CellType type = mesh.cellTypes[c];
        if (type == CellType::POI1 || !xfemSupports(type)) continue;
        for (const auto& e : cellEdges(type)) {
            const int a = nodes[e[0]], b = nodes[e[1]];
            if (ls[a] == 0.0) addPoint(a, b, 0.0);
            if (ls[b] == 0.0) addPoint(a, b, 1.0);
            if (ls[a] * ls[b] < 0.0) addPoint(a, b, ls[a] / (ls[a] - ls[b]));
        }
        for (int n : nodes)
            for (size_t k = 0; k < nm; ++k)
                minJunction[k * nn + n] = std::min(minJunction[k * nn + n], cellJunction[k]);
    }
    crack->nodeStatus.assign(nn, 0);
    for (int n = 0; n < nn; ++n) {
        if (lo[n] > hi[n] || !(lo[n] * hi[n] < 0.0)) continue;  // no cut cell around, or one side
        bool forbidden = false;
        // For interfaces the master's tangential level set is -1 everywhere: only LSJ decides.
        for (size_t k = 0; k < nm; ++k)
            if (minJunction[k * nn + n] >= 0.0) forbidden = true;
        if (!forbidden) crack->nodeStatus[n] = 1;
    }

    crack->heavisideCells = heavisideCellsOf(mesh, crack->nodeStatus);
    return crack;
}

namespace {

// Node status of a crack (code_aster's xstano, linear cells, no junction): over the cut cells
// around the node, LSN's extremes at their vertices and LST's at the points of their edges where
// LSN = 0. Heaviside (1) when LSN changes sign there and that part of the surface is behind the
// front (LST <= 0); crack tip (2) when the front crosses the support (LST changes sign on
// LSN = 0); both (3). code_aster marks tip-only nodes -2 until NB_COUCHES is applied: 2 here.
std::vector<unsigned char> crackNodeStatus(const Mesh& mesh, const std::vector<double>& lsn,
                                           const std::vector<double>& lst, const std::vector<int>& cutCells) {
    const size_t nn = lsn.size();
    constexpr double inf = std::numeric_limits<double>::infinity();
    std::vector<double> nLo(nn, inf), nHi(nn, -inf), tLo(nn, inf), tHi(nn, -inf);
    for (int c : cutCells) {
        const CellType type = mesh.cellTypes[size_t(c)];
        if (!xfemSupports(type))  // a status left at 0 there would pass for a front outside the mesh
            throw NotImplemented(fmt::format(
                "DEFI_FISS_XFEM: the crack cuts cell {} ({}): the node status and the front of a crack are found "
                "on SEG2, TRIA3, QUAD4, TETRA4 and HEXA8 cells only",
                mesh.cellNames[size_t(c)], cellTypeName(type)));
        const auto nodes = mesh.cellNodes(c);
        double cnLo = inf, cnHi = -inf, ctLo = inf, ctHi = -inf;
        auto zeroAt = [&](double v) { ctLo = std::min(ctLo, v), ctHi = std::max(ctHi, v); };
        for (int n : nodes) cnLo = std::min(cnLo, lsn[size_t(n)]), cnHi = std::max(cnHi, lsn[size_t(n)]);
        for (const auto& e : cellEdges(type)) {
            const size_t a = size_t(nodes[size_t(e[0])]), b = size_t(nodes[size_t(e[1])]);
            if (lsn[a] == 0.0 && lsn[b] == 0.0) {
                zeroAt(lst[a]), zeroAt(lst[b]);
            } else if (lsn[a] * lsn[b] <= 0.0) {
                zeroAt(lst[a] + lsn[a] / (lsn[a] - lsn[b]) * (lst[b] - lst[a]));
            }
        }
        for (int n : nodes) {
            const size_t k = size_t(n);
            nLo[k] = std::min(nLo[k], cnLo), nHi[k] = std::max(nHi[k], cnHi);
            tLo[k] = std::min(tLo[k], ctLo), tHi[k] = std::max(tHi[k], ctHi);
        }
    }
    std::vector<unsigned char> status(nn, 0);
    for (size_t n = 0; n < nn; ++n) {
        if (nLo[n] > nHi[n]) continue;  // no cut cell around the node
        const bool heaviside = nLo[n] * nHi[n] < 0.0 && tHi[n] <= kMachineEpsilon;
        const bool tip = nLo[n] * nHi[n] <= kMachineEpsilon && tLo[n] * tHi[n] <= kMachineEpsilon;
        status[n] = static_cast<unsigned char>(tip ? (heaviside ? 3 : 2) : (heaviside ? 1 : 0));
    }
    return status;
}

// MAFOND (xstam1): cut cells of the mesh's dimension whose nodes all have status 2 or 3.
std::vector<int> tipCellsOf(const Mesh& mesh, const Crack& crack) {
    const int dim = mesh.maxCellDimension();
    std::vector<int> cells;
    for (int c : crack.cutCells) {
        if (cellDimension(mesh.cellTypes[size_t(c)]) != dim) continue;
        const auto nodes = mesh.cellNodes(c);
        if (std::all_of(nodes.begin(), nodes.end(), [&](int n) { return crack.nodeStatus[size_t(n)] >= 2; }))
            cells.push_back(c);
    }
    return cells;
}

}  // namespace

std::shared_ptr<Crack> buildCrackWithFront(const std::shared_ptr<const Mesh>& meshPtr, std::vector<double> lsn,
                                           std::vector<double> lst) {
    const Mesh& mesh = *meshPtr;
    auto crack = std::make_shared<Crack>();
    crack->mesh = meshPtr;
    crack->isCrack = true;
    for (size_t n = 0; n < lsn.size(); ++n)
        if (!std::isfinite(lsn[n]) || !std::isfinite(lst[n]))
            throw NumericalError(fmt::format("DEFI_FISS: the level sets are not finite at node {} (LSN {}, LST {})",
                                             mesh.nodeNames[n], lsn[n], lst[n]));
    crack->adjustedLevelSets = snapLevelSet(mesh, lsn) + snapLevelSet(mesh, lst);
    crack->lsn = std::move(lsn);
    crack->lst = std::move(lst);
    crack->cutCells = cutCellsOf(mesh, crack->lsn, nullptr);
    if (crack->cutCells.empty()) throw UserError(noCutCellText(mesh, "crack"));
    crack->lsnGradient = nodalGradient(mesh, crack->lsn, &crack->cutCells);
    crack->nodeStatus = crackNodeStatus(mesh, crack->lsn, crack->lst, crack->cutCells);
    crack->heavisideCells = heavisideCellsOf(mesh, crack->nodeStatus);
    crack->tipCells = tipCellsOf(mesh, *crack);
    crack->fronts = crackFronts(mesh, crack->lsn, crack->lst, crack->tipCells);
    return crack;
}

double enrichCrackTipZone(Crack& crack, double radius, int layers) {
    const Mesh& mesh = *crack.mesh;
    if (crack.tipCells.empty()) return 0.0;
    if (radius <= 0.0 && layers > 0) {
        double h = std::numeric_limits<double>::infinity();
        for (int c : crack.tipCells) h = std::min(h, characteristicLength(mesh, c));
        radius = h * layers;
    }
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        auto& st = crack.nodeStatus[size_t(n)];
        if (st <= 1 && std::hypot(crack.lsn[size_t(n)], crack.lst[size_t(n)]) <= radius)
            st = static_cast<unsigned char>(st + 2);
    }
    crack.heavisideCells = heavisideCellsOf(mesh, crack.nodeStatus);
    return radius;
}

}  // namespace ma::xfem
