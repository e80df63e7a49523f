#include "fracture/FrontG.hpp"

#include <algorithm>

#include "fracture/DomainSampling.hpp"

namespace ma::fracture {

namespace {

// The nodes whose BASLOC the integrals read: those of the cells where some theta is not zero (the
// lip term reads the frames where theta is constant too), and one cell beyond, since the nodal
// divergence of the bases averages the cells around a node.
std::vector<char> baslocNodes(const Mesh& mesh, const FrontGSetup& setup) {
    std::vector<char> read(size_t(mesh.nodeCount()), 0), wide;
    for (int cell = 0; cell < mesh.cellCount(); ++cell)
        if (anyThetaReaches(mesh, cell, setup))
            for (int n : mesh.cellNodes(cell)) read[size_t(n)] = 1;
    wide = read;
    for (int cell = 0; cell < mesh.cellCount(); ++cell) {
        const auto nodes = mesh.cellNodes(cell);
        if (std::any_of(nodes.begin(), nodes.end(), [&](int n) { return read[size_t(n)] != 0; }))
            for (int n : nodes) wide[size_t(n)] = 1;
    }
    return wide;
}

}  // namespace

FrontGSetup frontGSetup(const Mesh& mesh, const xfem::Crack& crack, int numeFond,
                        std::optional<std::pair<double, double>> radii, GSmoothing smoothing, int degree,
                        size_t points) {
    FrontGSetup setup;
    setup.smoothing = smoothing;
    const auto gn = xfem::nodalLevelSetGradient(mesh, crack.lsn);
    const auto gt = xfem::nodalLevelSetGradient(mesh, crack.lst);
    setup.front = front3D(mesh, crack, gn, gt, numeFond);
    if (points > 0) setup.front = redistributed(setup.front, points);
    if (radii) {
        setup.rInf = radii->first, setup.rSup = radii->second;
    } else {
        const double size = *std::max_element(setup.front.cellSize.begin(), setup.front.cellSize.end());
        setup.rInf = 2 * size, setup.rSup = 4 * size;
    }
    std::vector<FrontProjection> nodes(size_t(mesh.nodeCount()));
    for (size_t n = 0; n < nodes.size(); ++n) nodes[n] = projectOnFront(setup.front, mesh.coords[n]);
    const auto& front = setup.front;
    if (smoothing == GSmoothing::Legendre) {
        for (int k = 0; k <= degree; ++k)
            setup.thetas.push_back(frontTheta(mesh, front, nodes, gt,
                                              legendrePolynomial(front.abscissa, front.abscissa.back(), k), setup.rInf,
                                              setup.rSup));
    } else {
        for (size_t k = 0; k < front.points.size(); ++k)
            setup.thetas.push_back(frontTheta(mesh, front, nodes, gt, lagrangeHat(front, k), setup.rInf, setup.rSup));
    }
    setup.basloc = xfem::frontBases(mesh, crack, baslocNodes(mesh, setup));
    setup.basisDivergence = basisDivergence(mesh, setup.basloc);
    return setup;
}

bool anyThetaVaries(const Mesh& mesh, int cell, const FrontGSetup& setup) {
    return std::any_of(setup.thetas.begin(), setup.thetas.end(),
                       [&](const std::vector<Vec3>& t) { return thetaVaries(mesh, cell, t); });
}

bool anyThetaReaches(const Mesh& mesh, int cell, const FrontGSetup& setup) {
    return std::any_of(setup.thetas.begin(), setup.thetas.end(),
                       [&](const std::vector<Vec3>& t) { return thetaReaches(mesh, cell, t); });
}

std::vector<FrontValues> frontValues(const Discretisation& space, const std::vector<double>& u,
                                     const xfem::Crack& crack, const FrontGSetup& setup, bool withK,
                                     const std::vector<LipPoint>& lips) {
    std::vector<FrontValues> integrals(setup.thetas.size());
    domainPoints3D(space, u, setup.thetas, crack.lsn, setup.basloc, setup.basisDivergence,
                   [&](size_t k, const std::vector<DomainPoint>& points, const std::vector<FrontFrame>& frames) {
                       const auto v = domainIntegrals(points, frames, space.model().modelisation, 3, withK);
                       FrontValues& sum = integrals[k];
                       sum.G += v.G, sum.K1 += v.K1, sum.K2 += v.K2, sum.K3 += v.K3;
                       for (size_t c = 0; c < 3; ++c) sum.irwin[c] += v.irwin[c];
                   });
    if (!lips.empty()) {
        std::vector<FrontFrame> frames;
        for (const auto& p : lips)
            frames.push_back(interpolatedFrame(setup.basloc, space.mesh().cellNodes(p.cell), p.N));
        for (size_t k = 0; k < integrals.size(); ++k)
            addLipTerm(integrals[k],
                       lipIntegrals(space.mesh(), lips, setup.thetas[k], frames, space.model().modelisation, 3, withK),
                       lips, space.model().modelisation);
    }
    if (setup.smoothing == GSmoothing::Legendre) return legendreAlongFront(integrals, setup.front.abscissa);
    return smoothAlongFront(std::move(integrals), setup.front.abscissa, setup.front.closed, setup.smoothing, withK);
}

}  // namespace ma::fracture
