#include "post/NodeValues.hpp"

#include <cmath>
#include <functional>

#include "core/Error.hpp"
#include "mesh/ShapeFunctions.hpp"

namespace ma::post {
namespace {

using Basis = std::function<void(const std::array<double, 3>&, std::vector<double>&)>;

// The element of the vertices of `type` (QUAD8 -> QUAD4 ...): its shape functions are the fitting
// basis, as code_aster's GANO matrices extrapolate to the vertices.
CellType vertexType(CellType type) {
    switch (type) {
        case CellType::TRIA6:
        case CellType::TRIA7: return CellType::TRIA3;
        case CellType::QUAD8:
        case CellType::QUAD9: return CellType::QUAD4;
        case CellType::TETRA10: return CellType::TETRA4;
        case CellType::PYRA13: return CellType::PYRA5;
        case CellType::PENTA15:
        case CellType::PENTA18: return CellType::PENTA6;
        case CellType::HEXA20:
        case CellType::HEXA27: return CellType::HEXA8;
        default: return type;
    }
}

// Solves the n x n system a x = b (b: n x nc, overwritten by x); false when singular.
bool solveDense(std::vector<double>& a, std::vector<double>& b, int n, int nc) {
    double scale = 0;
    for (double v : a) scale = std::max(scale, std::abs(v));
    for (int k = 0; k < n; ++k) {
        int pivot = k;
        for (int i = k + 1; i < n; ++i)
            if (std::abs(a[size_t(i * n + k)]) > std::abs(a[size_t(pivot * n + k)])) pivot = i;
        if (std::abs(a[size_t(pivot * n + k)]) <= 1e-12 * scale) return false;
        for (int j = 0; j < n; ++j) std::swap(a[size_t(k * n + j)], a[size_t(pivot * n + j)]);
        for (int c = 0; c < nc; ++c) std::swap(b[size_t(k * nc + c)], b[size_t(pivot * nc + c)]);
        for (int i = k + 1; i < n; ++i) {
            const double f = a[size_t(i * n + k)] / a[size_t(k * n + k)];
            for (int j = k; j < n; ++j) a[size_t(i * n + j)] -= f * a[size_t(k * n + j)];
            for (int c = 0; c < nc; ++c) b[size_t(i * nc + c)] -= f * b[size_t(k * nc + c)];
        }
    }
    for (int k = n - 1; k >= 0; --k)
        for (int c = 0; c < nc; ++c) {
            double s = b[size_t(k * nc + c)];
            for (int j = k + 1; j < n; ++j) s -= a[size_t(k * n + j)] * b[size_t(j * nc + c)];
            b[size_t(k * nc + c)] = s / a[size_t(k * n + k)];
        }
    return true;
}

// A fit of the values at `points` of `field` in `basis` (nb functions): coefficients nb x nc, the
// mean (a constant) when the points do not determine the basis.
struct Fit {
    Basis basis;
    std::vector<double> coef;
    int nc = 0;

    void at(const std::array<double, 3>& xi, double* out) const {
        std::vector<double> N;
        basis(xi, N);
        for (int c = 0; c < nc; ++c) {
            out[c] = 0;
            for (size_t b = 0; b < N.size(); ++b) out[c] += N[b] * coef[b * size_t(nc) + size_t(c)];
        }
    }
};

Fit leastSquares(const GaussField& field, const std::vector<int>& points, int nb, const Basis& basis) {
    const int nc = field.componentCount();
    Fit fit{basis, {}, nc};
    if (int(points.size()) >= nb) {
        std::vector<double> ata(size_t(nb * nb), 0.0), atv(size_t(nb * nc), 0.0), N;
        for (int p : points) {
            basis(field.pointRefCoords[size_t(p)], N);
            for (int i = 0; i < nb; ++i) {
                for (int j = 0; j < nb; ++j) ata[size_t(i * nb + j)] += N[size_t(i)] * N[size_t(j)];
                for (int c = 0; c < nc; ++c) atv[size_t(i * nc + c)] += N[size_t(i)] * field.values[size_t(p * nc + c)];
            }
        }
        if (solveDense(ata, atv, nb, nc)) {
            fit.coef = std::move(atv);
            return fit;
        }
    }
    fit.basis = [](const std::array<double, 3>&, std::vector<double>& N) { N.assign(1, 1.0); };
    fit.coef.assign(size_t(nc), 0.0);
    for (int p : points)
        for (int c = 0; c < nc; ++c) fit.coef[size_t(c)] += field.values[size_t(p * nc + c)] / double(points.size());
    return fit;
}

Basis shapeBasis(CellType type) {
    return [type](const std::array<double, 3>& xi, std::vector<double>& N) {
        N.resize(size_t(nodeCount(type)));
        shapeValues(type, xi, N);
    };
}

Basis linearBasis(int dim) {
    return [dim](const std::array<double, 3>& xi, std::vector<double>& N) {
        N.assign(1, 1.0);
        for (int d = 0; d < dim; ++d) N.push_back(xi[size_t(d)]);
    };
}

}  // namespace

std::shared_ptr<GaussField> restrictToCells(const GaussField& field, const std::vector<char>& keepCell) {
    auto out = std::make_shared<GaussField>();
    out->mesh = field.mesh;
    out->quantity = field.quantity;
    out->components = field.components;
    out->atNodes = field.atNodes;
    const size_t nc = field.components.size();
    for (size_t e = 0; e < field.cells.size(); ++e) {
        const int cell = field.cells[e];
        if (size_t(cell) >= keepCell.size() || !keepCell[size_t(cell)]) continue;
        const size_t first = size_t(field.pointOffsets[e]), last = size_t(field.pointOffsets[e + 1]);
        out->cells.push_back(cell);
        out->pointOffsets.push_back(out->pointOffsets.back() + int(last - first));
        auto copy = [&](auto& to, const auto& from, size_t width) {
            if (from.size() >= last * width)
                to.insert(to.end(), from.begin() + first * width, from.begin() + last * width);
        };
        copy(out->pointCoords, field.pointCoords, 1);
        copy(out->pointWeights, field.pointWeights, 1);
        copy(out->pointSubcell, field.pointSubcell, 1);
        copy(out->pointRefCoords, field.pointRefCoords, 1);
        copy(out->values, field.values, nc);
    }
    return out;
}

namespace {

// The values at the nodes of element e (nodes x nc into `out`).
void elementNodeValues(const GaussField& field, size_t e, const Enrichment* enrichment, double* out) {
    const int cell = field.cells[e];
    const CellType type = field.mesh->cellTypes[size_t(cell)];
    const auto refNodes = referenceNodes(type);
    const int nn = nodeCount(type), nc = field.componentCount();
    std::vector<int> points;
    for (int p = field.pointOffsets[e]; p < field.pointOffsets[e + 1]; ++p) points.push_back(p);
    const auto subcells = enrichment ? enrichment->subcellParentNodes(cell) : std::vector<std::vector<int>>{};
    if (subcells.empty() || field.pointSubcell.size() != field.pointWeights.size()) {
        const CellType vertices = vertexType(type);
        const Fit fit = leastSquares(field, points, nodeCount(vertices), shapeBasis(vertices));
        for (int a = 0; a < nn; ++a) fit.at(refNodes[size_t(a)], out + size_t(a * nc));
        return;
    }
    std::vector<int> around(size_t(nn), 0);
    std::fill(out, out + size_t(nn * nc), 0.0);
    std::vector<double> value(static_cast<size_t>(nc));
    for (size_t s = 0; s < subcells.size(); ++s) {
        std::vector<int> own;
        for (int p : points)
            if (field.pointSubcell[size_t(p)] == int(s)) own.push_back(p);
        if (own.empty() || subcells[s].empty()) continue;
        const int dim = referenceDimension(type);
        const Fit fit = leastSquares(field, own, dim + 1, linearBasis(dim));
        for (int a : subcells[s]) {
            fit.at(refNodes[size_t(a)], value.data());
            for (int c = 0; c < nc; ++c) out[size_t(a * nc + c)] += value[size_t(c)];
            ++around[size_t(a)];
        }
    }
    const Fit mean = leastSquares(field, points, 1, linearBasis(0));
    for (int a = 0; a < nn; ++a) {
        if (around[size_t(a)] == 0) mean.at(refNodes[size_t(a)], out + size_t(a * nc));
        else
            for (int c = 0; c < nc; ++c) out[size_t(a * nc + c)] /= around[size_t(a)];
    }
}

}  // namespace

std::shared_ptr<GaussField> nodeValues(const GaussField& field, const Enrichment* enrichment) {
    if (!field.mesh || field.atNodes || field.pointRefCoords.size() != field.pointWeights.size())
        throw InternalError("nodeValues needs a field at integration points with their reference coordinates");
    auto out = std::make_shared<GaussField>();
    out->mesh = field.mesh;
    out->quantity = field.quantity;
    out->components = field.components;
    out->atNodes = true;
    out->cells = field.cells;
    const Mesh& mesh = *field.mesh;
    const size_t nc = field.components.size();
    for (size_t e = 0; e < field.cells.size(); ++e) {
        const int cell = field.cells[e];
        const CellType type = mesh.cellTypes[size_t(cell)];
        const auto nodes = mesh.cellNodes(cell);
        const auto refNodes = referenceNodes(type);
        out->pointOffsets.push_back(out->pointOffsets.back() + int(nodes.size()));
        for (size_t a = 0; a < nodes.size(); ++a) {
            out->pointCoords.push_back(mesh.coords[size_t(nodes[a])]);
            out->pointRefCoords.push_back(refNodes[a]);
        }
        out->values.resize(size_t(out->pointOffsets.back()) * nc);
        elementNodeValues(field, e, enrichment, out->values.data() + size_t(out->pointOffsets[e]) * nc);
    }
    out->pointWeights.assign(out->pointCoords.size(), 0.0);
    out->pointSubcell.assign(out->pointCoords.size(), 0);
    return out;
}

std::shared_ptr<NodalField> nodalAverage(const GaussField& elno) {
    if (!elno.mesh || !elno.atNodes) throw InternalError("nodalAverage needs an ELNO field");
    const Mesh& mesh = *elno.mesh;
    auto out = std::make_shared<NodalField>();
    out->resize(elno.mesh, elno.components);
    out->quantity = elno.quantity;
    const int nc = elno.componentCount();
    std::vector<int> count(size_t(mesh.nodeCount()), 0);
    for (size_t e = 0; e < elno.cells.size(); ++e) {
        const auto nodes = mesh.cellNodes(elno.cells[e]);
        for (size_t a = 0; a < nodes.size(); ++a) {
            ++count[size_t(nodes[a])];
            const size_t row = (size_t(elno.pointOffsets[e]) + a) * size_t(nc);
            for (int c = 0; c < nc; ++c) out->at(nodes[a], c) += elno.values[row + size_t(c)];
        }
    }
    for (int n = 0; n < mesh.nodeCount(); ++n)
        if (count[size_t(n)] > 0)
            for (int c = 0; c < nc; ++c) out->set(n, c, out->at(n, c) / count[size_t(n)]);
    return out;
}

}  // namespace ma::post
