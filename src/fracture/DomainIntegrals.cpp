#include "fracture/DomainIntegrals.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fracture/WilliamsFields.hpp"

namespace ma::fracture {

ElasticConstants ElasticConstants::of(double E, double nu, Modelisation modelisation) {
    ElasticConstants c;
    c.mu = E / (2 * (1 + nu));
    if (modelisation == Modelisation::C_PLAN) {
        c.lambda = E * nu / (1 - nu * nu);
        c.kappa = (3 - nu) / (1 + nu);
        c.eStar = E;
    } else {
        c.lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
        c.kappa = 3 - 4 * nu;
        c.eStar = E / (1 - nu * nu);
    }
    return c;
}

namespace {

using Tensor = double[3][3];

void stress(const Tensor& g, const ElasticConstants& c, int dim, Tensor& s) {
    double tr = 0.0;
    for (int i = 0; i < dim; ++i) tr += g[i][i];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) s[i][j] = (i < dim && j < dim) ? c.mu * (g[i][j] + g[j][i]) : 0.0;
    for (int i = 0; i < dim; ++i) s[i][i] += c.lambda * tr;
}

// The auxiliary field of `mode` at a point, in global axes: G = P Gl P^T (P's columns e1 e2 e3).
void auxiliaryGradient(Mode mode, const DomainPoint& p, const FrontFrame& f, const ElasticConstants& c, Tensor& g) {
    const Vec3 d = difference(p.xyz, f.origin);
    const double x1 = dot(d, f.e1), x2 = dot(d, f.e2);
    const double r = std::hypot(x1, x2);
    double t = std::atan2(x2, x1);
    // Behind the front the side of the crack decides the sign of theta, not the point's x2 (a lip
    // that is not straight).
    if (p.side != 0.0 && x1 < 0) t = std::copysign(std::acos(std::clamp(x1 / r, -1.0, 1.0)), p.side);
    const LocalField local = williamsField(mode, r, t, c.mu, c.kappa);
    const Vec3* e[3] = {&f.e1, &f.e2, &f.e3};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double v = 0.0;
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b) v += (*e[a])[i] * local.grad[a][b] * (*e[b])[j];
            for (int k = 0; k < 3; ++k) v += local.u[size_t(k)] * f.basisGradient[k][i][j];
            g[i][j] = v;
        }
}

double divergence(const DomainPoint& p, int dim) {
    double v = 0.0;
    for (int k = 0; k < dim; ++k) v += p.gradTheta[k][k];
    return v;
}

// sigma_ij a_i,k theta_k,j
double contract(const Tensor& s, const Tensor& a, const DomainPoint& p, int dim) {
    double v = 0.0;
    for (int i = 0; i < dim; ++i)
        for (int j = 0; j < dim; ++j)
            for (int k = 0; k < dim; ++k) v += s[i][j] * a[i][k] * p.gradTheta[k][j];
    return v;
}

double doubleDot(const Tensor& s, const Tensor& g, int dim) {
    double v = 0.0;
    for (int i = 0; i < dim; ++i)
        for (int j = 0; j < dim; ++j) v += s[i][j] * g[i][j];
    return v;
}

double interaction(Mode mode, const DomainPoint& p, const FrontFrame& f, const ElasticConstants& c, const Tensor& s,
                   int dim) {
    Tensor ga, sa;
    auxiliaryGradient(mode, p, f, c, ga);
    stress(ga, c, dim, sa);
    return contract(s, ga, p, dim) + contract(sa, p.gradU, p, dim) - doubleDot(sa, p.gradU, dim) * divergence(p, dim);
}

}  // namespace

namespace {

template <class FrameOf>
FrontValues integrate(const std::vector<DomainPoint>& points, const FrameOf& frameOf, Modelisation modelisation,
                      int dim, bool withK) {
    FrontValues out;
    ElasticConstants c{};
    for (size_t q = 0; q < points.size(); ++q) {
        const DomainPoint& p = points[q];
        c = ElasticConstants::of(p.E, p.nu, modelisation);
        Tensor s;
        stress(p.gradU, c, dim, s);
        out.G += p.weight * (contract(s, p.gradU, p, dim) - 0.5 * doubleDot(s, p.gradU, dim) * divergence(p, dim));
        if (!withK) continue;
        const FrontFrame& frame = frameOf(q);
        const double k1 = p.weight * c.eStar / 2 * interaction(Mode::I, p, frame, c, s, dim);
        const double k2 = p.weight * c.eStar / 2 * interaction(Mode::II, p, frame, c, s, dim);
        const double k3 = dim == 3 ? p.weight * c.mu * interaction(Mode::III, p, frame, c, s, dim) : 0.0;
        out.K1 += k1, out.K2 += k2, out.K3 += k3;
        out.irwin[0] += k1 / std::sqrt(c.eStar), out.irwin[1] += k2 / std::sqrt(c.eStar);
        out.irwin[2] += k3 / std::sqrt(2 * c.mu);
    }
    if (c.eStar > 0) out.gIrwin = (out.K1 * out.K1 + out.K2 * out.K2) / c.eStar + out.K3 * out.K3 / (2 * c.mu);
    return out;
}

}  // namespace

FrontValues domainIntegrals(const std::vector<DomainPoint>& points, const FrontFrame& frame, Modelisation modelisation,
                            int dim, bool withK) {
    return integrate(
        points, [&](size_t) -> const FrontFrame& { return frame; }, modelisation, dim, withK);
}

FrontValues domainIntegrals(const std::vector<DomainPoint>& points, std::span<const FrontFrame> frames,
                            Modelisation modelisation, int dim, bool withK) {
    return integrate(
        points, [&](size_t q) -> const FrontFrame& { return frames[q]; }, modelisation, dim, withK);
}

}  // namespace ma::fracture
