#include "fracture/FrontSmoothing.hpp"

#include <Eigen/Dense>

#include "fracture/FrontTheta.hpp"
#include "xfem/TipEnrichment.hpp"

namespace ma::fracture {

namespace {

// gmatc3: the assembled mass matrix of the segments (linear shape functions, exact integration).
Eigen::MatrixXd frontMass(const std::vector<double>& s, bool closed) {
    const Eigen::Index n = Eigen::Index(s.size());
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index i = 0; i + 1 < n; ++i) {
        const double L = s[size_t(i + 1)] - s[size_t(i)];
        M(i, i) += L / 3, M(i, i + 1) += L / 6, M(i + 1, i) += L / 6, M(i + 1, i + 1) += L / 3;
        // A closed front: the first point's row also takes the last segment's, and the reverse.
        if (closed && i == 0) M(n - 1, n - 1) += L / 3, M(n - 1, 1) += L / 6;
        if (closed && i + 2 == n) M(0, n - 2) += L / 6, M(0, 0) += L / 3;
    }
    return M;
}

// gmatl3: the row sums, a closed front's ends added together.
Eigen::VectorXd lumpedMass(const std::vector<double>& s, bool closed) {
    const Eigen::Index n = Eigen::Index(s.size());
    Eigen::VectorXd m = Eigen::VectorXd::Zero(n);
    for (Eigen::Index i = 0; i + 1 < n; ++i) {
        const double L = s[size_t(i + 1)] - s[size_t(i)];
        m(i) += L / 2, m(i + 1) += L / 2;
    }
    if (closed) m(n - 1) += m(0), m(0) = m(n - 1);
    return m;
}

using Member = double FrontValues::*;
constexpr Member kMembers[] = {&FrontValues::G, &FrontValues::K1, &FrontValues::K2, &FrontValues::K3};

void solveLagrange(std::vector<FrontValues>& v, const std::vector<double>& s, bool closed, bool withK) {
    const size_t n = v.size();
    // The Irwin components take the system with their integrals as they are.
    std::vector<FrontValues> irwin = v;
    if (withK && !closed && n > 2) {
        for (Member m : kMembers) {
            v[0].*m = v[1].*m * (s[1] - s[0]) / (s[2] - s[0]);
            v[n - 1].*m = v[n - 2].*m * (s[n - 1] - s[n - 2]) / (s[n - 1] - s[n - 3]);
        }
    }
    const auto lu = frontMass(s, closed).partialPivLu();
    Eigen::VectorXd b(Eigen::Index(n), 1);
    for (Member m : kMembers) {
        for (size_t i = 0; i < n; ++i) b(Eigen::Index(i)) = v[i].*m;
        const Eigen::VectorXd g = lu.solve(b);
        for (size_t i = 0; i < n; ++i) v[i].*m = g(Eigen::Index(i));
    }
    for (size_t c = 0; c < 3; ++c) {
        for (size_t i = 0; i < n; ++i) b(Eigen::Index(i)) = irwin[i].irwin[c];
        const Eigen::VectorXd g = lu.solve(b);
        for (size_t i = 0; i < n; ++i) v[i].irwin[c] = g(Eigen::Index(i));
    }
    for (auto& p : v) p.gIrwin = p.irwin[0] * p.irwin[0] + p.irwin[1] * p.irwin[1] + p.irwin[2] * p.irwin[2];
}

void solveLumped(std::vector<FrontValues>& v, const std::vector<double>& s, bool closed, bool withK) {
    const size_t n = v.size();
    const Eigen::VectorXd m = lumpedMass(s, closed);
    for (size_t i = 0; i < n; ++i) {
        const double w = m(Eigen::Index(i));
        FrontValues& p = v[i];
        p.gIrwin = (p.irwin[0] * p.irwin[0] + p.irwin[1] * p.irwin[1] + p.irwin[2] * p.irwin[2]) / (w * w);
        for (Member k : kMembers) p.*k /= w;
        for (double& c : p.irwin) c /= w;
    }
    if (!withK || closed || n <= 2) return;
    auto extrapolate = [&](double FrontValues::*k) {
        v[0].*k = v[1].*k + (s[0] - s[1]) * (v[2].*k - v[1].*k) / (s[2] - s[1]);
        v[n - 1].*k = v[n - 2].*k + (s[n - 1] - s[n - 2]) * (v[n - 3].*k - v[n - 2].*k) / (s[n - 3] - s[n - 2]);
    };
    for (Member k : kMembers) extrapolate(k);
    extrapolate(&FrontValues::gIrwin);
}

// gmatr1: A_ij = int P_i P_j ds, the polynomials at 14 Gauss points of each segment.
Eigen::MatrixXd legendreGram(const std::vector<double>& s, int degree) {
    const Eigen::Index n = degree + 1;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
    const double length = s.back();
    std::vector<double> x, w;
    xfem::gaussLegendre01(14, x, w);
    for (size_t seg = 0; seg + 1 < s.size(); ++seg) {
        const double L = s[seg + 1] - s[seg];
        std::vector<double> at;
        for (double t : x) at.push_back(s[seg] + t * L);
        std::vector<std::vector<double>> P;
        for (int k = 0; k <= degree; ++k) P.push_back(legendrePolynomial(at, length, k));
        for (Eigen::Index i = 0; i < n; ++i)
            for (Eigen::Index j = 0; j < n; ++j)
                for (size_t g = 0; g < x.size(); ++g) A(i, j) += P[size_t(i)][g] * P[size_t(j)][g] * w[g] * L;
    }
    return A;
}

}  // namespace

std::vector<FrontValues> legendreAlongFront(const std::vector<FrontValues>& integrals,
                                            const std::vector<double>& abscissa) {
    const int degree = int(integrals.size()) - 1;
    const auto lu = legendreGram(abscissa, degree).partialPivLu();
    const Eigen::Index n = degree + 1;
    std::vector<FrontValues> out(abscissa.size());
    std::vector<std::vector<double>> P;
    for (int k = 0; k <= degree; ++k) P.push_back(legendrePolynomial(abscissa, abscissa.back(), k));
    Eigen::VectorXd b(n);
    auto project = [&](auto get, auto put) {
        for (Eigen::Index k = 0; k < n; ++k) b(k) = get(integrals[size_t(k)]);
        const Eigen::VectorXd c = lu.solve(b);
        for (size_t i = 0; i < out.size(); ++i) {
            double v = 0.0;
            for (Eigen::Index k = 0; k < n; ++k) v += c(k) * P[size_t(k)][i];
            put(out[i], v);
        }
    };
    for (Member m : kMembers)
        project([&](const FrontValues& f) { return f.*m; }, [&](FrontValues& f, double v) { f.*m = v; });
    for (size_t c = 0; c < 3; ++c)
        project([&](const FrontValues& f) { return f.irwin[c]; }, [&](FrontValues& f, double v) { f.irwin[c] = v; });
    for (auto& p : out) p.gIrwin = p.irwin[0] * p.irwin[0] + p.irwin[1] * p.irwin[1] + p.irwin[2] * p.irwin[2];
    return out;
}

std::vector<FrontValues> smoothAlongFront(std::vector<FrontValues> integrals, const std::vector<double>& abscissa,
                                          bool closed, GSmoothing smoothing, bool withK) {
    if (smoothing == GSmoothing::Lagrange) solveLagrange(integrals, abscissa, closed, withK);
    else solveLumped(integrals, abscissa, closed, withK);
    return integrals;
}

}  // namespace ma::fracture
