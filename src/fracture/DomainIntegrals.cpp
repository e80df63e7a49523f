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

// The auxiliary field of `mode` at a point, in global axes: G = P Gl P^T (P's columns e1 e2 e3),
// plus u_k d(e_k)/dx (the basis turning with the point); `local` gets the field in the frame.
void auxiliaryGradient(Mode mode, const DomainPoint& p, const FrontFrame& f, const ElasticConstants& c, Tensor& g,
                       LocalField& local) {
    const Vec3 d = difference(p.xyz, f.origin);
    const double x1 = dot(d, f.e1), x2 = dot(d, f.e2);
    const double r = std::hypot(x1, x2);
    double t = std::atan2(x2, x1);
    // Behind the front the side of the crack decides the sign of theta, not the point's x2 (a lip
    // that is not straight).
    if (p.side != 0.0 && x1 < 0) t = std::copysign(std::acos(std::clamp(x1 / r, -1.0, 1.0)), p.side);
    local = williamsField(mode, r, t, c.mu, c.kappa);
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

bool turns(const FrontFrame& f) {
    for (const auto& k : f.basisGradient)
        for (const auto& i : k)
            for (double v : i)
                if (v != 0.0) return true;
    return false;
}

// dG_mn/dx_j of the auxiliary gradient above, the terms that carry the basis gradient D: with
// G_mn = u_k,a (e_a)_n (e_k)_m + u_k (D_k)_mn,
//   dG_mn/dx_j = u_k,ab (e_b)_j (e_a)_n (e_k)_m + u_k,a [(D_a)_nj (e_k)_m + (e_a)_n (D_k)_mj + (e_a)_j (D_k)_mn]
// + u_k dD_k/dx. The first term is left out: Williams' plane fields solve Navier's equations in
// their plane (it adds nothing to div sigma^a) and it is symmetric in j, n (nothing to the curl).
// The last is symmetric in j, n too; in div sigma^a it gives u_k (lambda + 2 mu) grad(div e_k) for a
// basis vector that is a gradient (e1, e2: of LST, LSN), added in curvedFrontTerm; e3's (mode III)
// is left out.
using Tensor3 = double[3][3][3];

void auxiliaryGradientDerivative(const LocalField& local, const FrontFrame& f, Tensor3& t) {
    const Vec3* e[3] = {&f.e1, &f.e2, &f.e3};
    const auto& D = f.basisGradient;
    // h_a = u_k,a e_k and q_k = u_k,a e_a: the three terms are sums over a or k of these times D.
    double h[2][3] = {}, q[3][3] = {};
    for (size_t k = 0; k < 3; ++k)
        for (size_t a = 0; a < 2; ++a) {
            const double g = local.grad[k][a];
            for (size_t m = 0; m < 3; ++m) h[a][m] += g * (*e[k])[m], q[k][m] += g * (*e[a])[m];
        }
    for (size_t m = 0; m < 3; ++m)
        for (size_t n = 0; n < 3; ++n)
            for (size_t j = 0; j < 3; ++j) {
                double v = 0.0;
                for (size_t a = 0; a < 2; ++a) v += h[a][m] * D[a][n][j];
                for (size_t k = 0; k < 3; ++k) v += q[k][n] * D[k][m][j] + q[k][j] * D[k][m][n];
                t[m][n][j] = v;
            }
}

// The volume term of the interaction integral on a curved front (docs/cracks.md, the penny section):
// the divergence of the interaction's energy-momentum tensor, which vanishes for the straight
// front's fields, is here
//   [div sigma^a . (grad u theta)] + sigma_ij (G_ik,j - G_ij,k) theta_k
// (the auxiliary stress out of equilibrium, and the curl of G where it is not a true gradient).
double curvedFrontTerm(const LocalField& local, const FrontFrame& f, const ElasticConstants& c, const Tensor& s,
                       const DomainPoint& p) {
    Tensor3 t;
    auxiliaryGradientDerivative(local, f, t);
    double v = 0.0;
    for (size_t i = 0; i < 3; ++i) {
        double divSigma = 0.0, gradUTheta = 0.0;
        for (size_t j = 0; j < 3; ++j) {
            divSigma += c.mu * (t[i][j][j] + t[j][i][j]) + c.lambda * t[j][j][i];
            gradUTheta += p.gradU[i][j] * p.theta[j];
        }
        for (size_t k = 0; k < 2; ++k) divSigma += (c.lambda + 2 * c.mu) * local.u[k] * f.divergenceGradient[k][i];
        v += divSigma * gradUTheta;
        for (size_t j = 0; j < 3; ++j)
            for (size_t k = 0; k < 3; ++k) v += s[i][j] * (t[i][k][j] - t[i][j][k]) * p.theta[k];
    }
    return v;
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
    LocalField local;
    auxiliaryGradient(mode, p, f, c, ga, local);
    stress(ga, c, dim, sa);
    const double v =
        contract(s, ga, p, dim) + contract(sa, p.gradU, p, dim) - doubleDot(sa, p.gradU, dim) * divergence(p, dim);
    return dim == 3 && turns(f) ? v + curvedFrontTerm(local, f, c, s, p) : v;
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
