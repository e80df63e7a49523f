#include "fracture/LipTerm.hpp"

#include <cmath>
#include <numbers>

#include "core/Error.hpp"
#include "fe/ElasticityKernels.hpp"
#include "fe/ElementKinematics.hpp"
#include "fe/Enrichment.hpp"
#include "fe/MechanicalLoad.hpp"
#include "fracture/WilliamsFields.hpp"

namespace ma::fracture {

namespace {

// One pressure (or shear) on the lips: its value at the points and, for a function, its gradient
// from the values at the parent cell's nodes.
struct LipValue {
    std::vector<double> atPoints;
    std::vector<double> atNodes;
};

LipValue valuesOf(const LoadValue& v, const Mesh& mesh, int cell, const std::vector<std::array<double, 3>>& xyz,
                  double inst) {
    LipValue out;
    if (!v.function) return out;
    out.atPoints = evaluateAtPoints(*v.function, xyz, inst);
    std::vector<std::array<double, 3>> nodes;
    for (int n : mesh.cellNodes(cell)) nodes.push_back(mesh.coords[size_t(n)]);
    out.atNodes = evaluateAtPoints(*v.function, nodes, inst);
    return out;
}

double valueAt(const LipValue& v, const LoadValue& load, size_t p) {
    return v.atPoints.empty() ? load.value : v.atPoints[p];
}

Vec3 gradientAt(const LipValue& v, const LipPoint& q) {
    Vec3 g{};
    for (size_t a = 0; a < v.atNodes.size(); ++a)
        for (size_t j = 0; j < 3; ++j) g[j] += q.gradN[a * 3 + j] * v.atNodes[a];
    return g;
}

// The displacement of the lip at point p of its element: sum_a N_a (sum_k psi_ak U_ak + Phi K_a).
Vec3 lipDisplacement(const ElementIntegration& ei, size_t p, const std::vector<double>& N, const std::vector<int>& dofs,
                     const std::vector<double>& u, int dim) {
    Vec3 out{};
    size_t i = 0;
    for (int a = 0; a < ei.nodeCount; ++a) {
        const double Na = N[size_t(a)];
        for (int k = 0; k < ei.slots[size_t(a)]; ++k) {
            const double m = ei.multiplier(int(p), a, k);
            for (int c = 0; c < dim; ++c, ++i) out[size_t(c)] += m * Na * u[size_t(dofs[i])];
        }
        if (!ei.tipAt(a)) continue;
        const double* Phi = ei.tipValue(p, ei.tipGroupOf(a));
        for (int m = 0; m < dim; ++m, ++i)
            for (int c = 0; c < dim; ++c) out[size_t(c)] += Na * Phi[c * 3 + m] * u[size_t(dofs[i])];
    }
    return out;
}

// The points of one side of one cell for one PRES_REP FISSURE.
void addLipPoints(const Discretisation& space, const std::vector<double>& u, LipIntegration& lip, const LipPressure& lp,
                  double factor, double inst, LawCache& laws, std::vector<LipPoint>& out) {
    const Mesh& mesh = space.mesh();
    const int dim = space.dim();
    ElementIntegration& ei = lip.element;
    const int cell = ei.cell;
    const IsotropicLaw& law = laws.of(ModelElement{cell, space.model().modelisation});
    if (ei.hasTip()) space.model().enrichment->tipFields(cell, TipLaw(law.lambdaEff, law.mu), ei);
    ei.refWeights.assign(ei.refPoints.size(), 1.0);  // only N and grad N are read
    PointGeometry geo;
    computePointGeometry(mesh, cell, dim, false, ei, geo);
    std::vector<int> dofs;
    localDofs(mesh, space.numbering(), ei, dofs);
    const LipValue pres = valuesOf(lp.pressure, mesh, cell, lip.xyz, inst);
    const LipValue shear = valuesOf(lp.shear, mesh, cell, lip.xyz, inst);
    const Material& material = space.material().at(cell);
    const size_t n = size_t(ei.nodeCount);
    for (size_t p = 0; p < lip.xyz.size(); ++p) {
        LipPoint q;
        q.cell = cell;
        q.weight = lip.weight[p];
        q.xyz = lip.xyz[p];
        q.normal = lip.normal[p];
        q.E = material.E, q.nu = material.nu;
        q.N.assign(geo.N.begin() + std::ptrdiff_t(p * n), geo.N.begin() + std::ptrdiff_t((p + 1) * n));
        q.gradN.assign(geo.gradN.begin() + std::ptrdiff_t(p * n * 3),
                       geo.gradN.begin() + std::ptrdiff_t((p + 1) * n * 3));
        q.u = lipDisplacement(ei, p, q.N, dofs, u, dim);
        const Vec3& m = q.normal;
        const Vec3 tangent{-m[1], m[0], 0.0};  // CISA_2D's direction (plane models)
        const double pv = factor * valueAt(pres, lp.pressure, p), cv = factor * valueAt(shear, lp.shear, p);
        const Vec3 gp = gradientAt(pres, q), gc = gradientAt(shear, q);
        for (size_t c = 0; c < 3; ++c) {
            q.traction[c] = -pv * m[c] + cv * tangent[c];
            for (size_t j = 0; j < 3; ++j) q.tractionGrad[c][j] = factor * (-gp[j] * m[c] + gc[j] * tangent[c]);
        }
        out.push_back(std::move(q));
    }
}

// The auxiliary displacement of `mode` at a lip point, in global axes.
Vec3 auxiliaryDisplacement(Mode mode, const LipPoint& q, const FrontFrame& f, const ElasticConstants& c) {
    const Vec3 d = difference(q.xyz, f.origin);
    const double r = std::hypot(dot(d, f.e1), dot(d, f.e2));
    // The lip whose material lies on the e2 side has its outward normal along -e2: theta = +pi.
    const double angle = dot(q.normal, f.e2) < 0 ? std::numbers::pi : -std::numbers::pi;
    const LocalField local = williamsField(mode, r, angle, c.mu, c.kappa);
    const Vec3* e[3] = {&f.e1, &f.e2, &f.e3};
    Vec3 out{};
    for (size_t i = 0; i < 3; ++i)
        for (size_t a = 0; a < 3; ++a) out[i] += (*e[a])[i] * local.u[a];
    return out;
}

}  // namespace

bool thetaReaches(const Mesh& mesh, int cell, const std::vector<Vec3>& theta) {
    for (int n : mesh.cellNodes(cell))
        if (theta[size_t(n)] != Vec3{}) return true;
    return false;
}

std::vector<LipPoint> lipPoints(const Discretisation& space, const std::vector<double>& u,
                                const std::vector<LoadCase>& loads, const Concept& crack, double inst,
                                const std::function<bool(int)>& read) {
    std::vector<LipPoint> out;
    LawCache laws(space.material());
    for (const auto& lc : loads) {
        const double factor = lc.factor(inst);
        if (factor == 0.0) continue;
        for (const auto& lp : lc.load->lipPressures) {
            if (lp.crack.get() != &crack) continue;
            std::vector<LipIntegration> lips;
            const auto* enrichment = space.model().enrichment.get();
            if (!enrichment || !enrichment->lipIntegration(crack, lips))
                throw InternalError(lp.path + ": the crack is not one of the model's");
            for (auto& lip : lips) {
                const int cell = lip.element.cell;
                if (!read(cell) || (!lp.onlyCells.empty() && !lp.onlyCells[size_t(cell)])) continue;
                addLipPoints(space, u, lip, lp, factor, inst, laws, out);
                std::vector<double>().swap(lip.element.tipPhi);  // one lip's Phi at a time
            }
        }
    }
    return out;
}

FrontValues lipIntegrals(const Mesh& mesh, const std::vector<LipPoint>& points, const std::vector<Vec3>& theta,
                         std::span<const FrontFrame> frames, Modelisation modelisation, int dim, bool withK) {
    FrontValues out;
    for (size_t q = 0; q < points.size(); ++q) {
        const LipPoint& p = points[q];
        const auto nodes = mesh.cellNodes(p.cell);
        Vec3 th{};
        double div = 0.0;
        for (size_t a = 0; a < nodes.size(); ++a) {
            const Vec3& t = theta[size_t(nodes[a])];
            for (size_t k = 0; k < 3; ++k) th[k] += p.N[a] * t[k], div += p.gradN[a * 3 + k] * t[k];
        }
        Vec3 load{};  // t div(theta) + grad t . theta
        for (size_t c = 0; c < 3; ++c) {
            load[c] = p.traction[c] * div;
            for (size_t j = 0; j < 3; ++j) load[c] += p.tractionGrad[c][j] * th[j];
        }
        if (load == Vec3{}) continue;
        out.G += p.weight * dot(load, p.u);
        if (!withK) continue;
        const ElasticConstants c = ElasticConstants::of(p.E, p.nu, modelisation);
        const FrontFrame& frame = frames.size() == 1 ? frames[0] : frames[q];
        const double k1 = p.weight * c.eStar / 2 * dot(load, auxiliaryDisplacement(Mode::I, p, frame, c));
        const double k2 = p.weight * c.eStar / 2 * dot(load, auxiliaryDisplacement(Mode::II, p, frame, c));
        const double k3 = dim == 3 ? p.weight * c.mu * dot(load, auxiliaryDisplacement(Mode::III, p, frame, c)) : 0.0;
        out.K1 += k1, out.K2 += k2, out.K3 += k3;
        out.irwin[0] += k1 / std::sqrt(c.eStar), out.irwin[1] += k2 / std::sqrt(c.eStar);
        out.irwin[2] += k3 / std::sqrt(2 * c.mu);
    }
    return out;
}

void addLipTerm(FrontValues& total, const FrontValues& lip, const std::vector<LipPoint>& points,
                Modelisation modelisation) {
    total.G += lip.G, total.K1 += lip.K1, total.K2 += lip.K2, total.K3 += lip.K3;
    for (size_t c = 0; c < 3; ++c) total.irwin[c] += lip.irwin[c];
    if (points.empty()) return;
    const ElasticConstants c = ElasticConstants::of(points.back().E, points.back().nu, modelisation);
    total.gIrwin = (total.K1 * total.K1 + total.K2 * total.K2) / c.eStar + total.K3 * total.K3 / (2 * c.mu);
}

}  // namespace ma::fracture
