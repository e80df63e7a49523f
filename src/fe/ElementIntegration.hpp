#pragma once
// How one element is integrated, and which functions multiply each node's shape function.
//
//   u(x) = sum_a sum_k N_a(x) * psi_{a,k}(x) * U_{a,k}
//
// k = 0 is the standard slot (psi = 1, components DX, DY[, DZ]); k >= 1 are the X-FEM Heaviside
// slots (components HkX, HkY[, HkZ]), psi constant on each integration sub-cell. A classical
// element has the cell's Gauss rule and only slot 0. An X-FEM element (src/xfem) lists the
// Gauss points of its sub-cells and the psi values. Stiffness, stresses (SIEF_ELGA), loads and
// POST_ERREUR sampling are all written once against this description.
//
// Crack-tip slot (components K1, K2[, K3], after the node's Heaviside slots, on the nodes flagged
// in `tip`): a vector enrichment
//
//   u(x) += N_a(x) * Phi(x) * K_a,   Phi[c][m] = component c of the asymptotic field of mode m
//
// a dim x dim matrix per group of tip nodes (the Williams fields in a local front basis minus their
// interpolation at the element's nodes, code_aster's xcalfev): 3D, one group (the nodal bases
// interpolated); 2D, one per front point of the element's tip nodes (each tip node's own tip: two
// where both tips of a short crack reach the element). Phi depends on the material through kappa
// and mu only, linearly: Phi = (kappa * A + B) / (2 mu); the enrichment gives A and B with their
// gradients, applyTipLaw the material's Phi.
#include <array>
#include <cstddef>
#include <vector>

#include "core/SharedVector.hpp"

namespace ma {

struct ElementIntegration {
    int cell = -1;
    int nodeCount = 0;  // nodes of the parent cell
    // Integration points in the parent reference element; the physical weight of point p is
    // refWeights[p] * |det J(refPoints[p])| (sub-cell volume ratio already in refWeights).
    // The point arrays and psi are shared by the copies describeAs makes (core/SharedVector.hpp).
    SharedVector<std::array<double, 3>> refPoints;
    SharedVector<double> refWeights;
    SharedVector<int> pointSubcell;  // sub-cell of each point (0 for a classical element)

    // slots[a] = number of slots of local node a in this element (1 = standard only).
    std::vector<int> slots;
    // psi[(s * nodeCount + a) * maxSlots + k] on sub-cell s = pointSubcell[p] (psi is constant on a
    // sub-cell: stored once per sub-cell, not per point, for the ~10^4 points of a 3D tip element);
    // only read for k < slots[a]. Empty means psi = 1 for k = 0 (a classical element).
    int maxSlots = 1;
    SharedVector<double> psi;

    // Per local node: 1 when it carries the tip slot in this element; empty when none does.
    std::vector<char> tip;
    // Per local node: the group whose Phi its tip slot takes (0 for other nodes); the groups' count.
    std::vector<unsigned char> tipGroup;
    int tipGroups = 1;
    // Per point and group, kTipStride values: the 3x3 matrix [c][m] (9) then its gradient [c][m][j] (27).
    static constexpr int kTipStride = 36;
    std::vector<double> tipA, tipB;  // from the enrichment (material-free parts)
    std::vector<double> tipPhi;      // (kappa * A + B) / (2 mu), set by applyTipLaw

    // This element as `other` without its tip fields (to fill: Enrichment::tipFields), sharing
    // its points and psi instead of copying them: a crack-tip element holds ~10^4 points.
    void describeAs(const ElementIntegration& other) {
        cell = other.cell, nodeCount = other.nodeCount;
        refPoints = other.refPoints, refWeights = other.refWeights, pointSubcell = other.pointSubcell;
        slots = other.slots, maxSlots = other.maxSlots, psi = other.psi;
        tip = other.tip, tipGroup = other.tipGroup, tipGroups = other.tipGroups;
        tipA.clear(), tipB.clear();  // tipPhi is overwritten whole (its capacity kept)
    }

    bool hasTip() const { return !tip.empty(); }
    bool tipAt(int a) const { return !tip.empty() && tip[std::size_t(a)] != 0; }
    int tipGroupOf(int a) const { return tipGroup.empty() ? 0 : tipGroup[std::size_t(a)]; }
    // Phi[c][m] and dPhi[c][m][j] of group g at point p (applyTipLaw must have run).
    const double* tipValue(std::size_t p, int g = 0) const {
        return &tipPhi[(p * std::size_t(tipGroups) + std::size_t(g)) * kTipStride];
    }
    const double* tipGradient(std::size_t p, int g = 0) const { return tipValue(p, g) + 9; }

    double multiplier(int p, int a, int k) const {
        if (psi.empty()) return k == 0 ? 1.0 : 0.0;
        return psi[(std::size_t(pointSubcell[std::size_t(p)]) * nodeCount + a) * maxSlots + k];
    }
};

// What makes Phi of A and B for an isotropic material given by its Hooke coefficients in the
// element's formulation (lambdaEff: lambda, or the plane-stress lambda*): kappa = (lambdaEff + 3 mu)
// / (lambdaEff + mu), which is 3 - 4 nu (3D, D_PLAN) or (3 - nu) / (1 + nu) (C_PLAN).
struct TipLaw {
    double kappa, scale;  // Phi = scale * (kappa * A + B)
    TipLaw(double lambdaEff, double mu) : kappa((lambdaEff + 3.0 * mu) / (lambdaEff + mu)), scale(1.0 / (2.0 * mu)) {}
};

// Fills ei.tipPhi from ei.tipA and ei.tipB.
inline void applyTipLaw(ElementIntegration& ei, double lambdaEff, double mu) {
    if (!ei.hasTip()) return;
    const auto [kappa, scale] = TipLaw(lambdaEff, mu);
    ei.tipPhi.resize(ei.tipA.size());
    for (std::size_t i = 0; i < ei.tipA.size(); ++i) ei.tipPhi[i] = scale * (kappa * ei.tipA[i] + ei.tipB[i]);
}

}  // namespace ma
