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
#include <array>
#include <vector>

namespace ma {

struct ElementIntegration {
    int cell = -1;
    int nodeCount = 0;  // nodes of the parent cell
    // Integration points in the parent reference element; the physical weight of point p is
    // refWeights[p] * |det J(refPoints[p])| (sub-cell volume ratio already in refWeights).
    std::vector<std::array<double, 3>> refPoints;
    std::vector<double> refWeights;
    std::vector<int> pointSubcell;  // sub-cell of each point (0 for a classical element)

    // slots[a] = number of slots of local node a in this element (1 = standard only).
    std::vector<int> slots;
    // psi[(p * nodeCount + a) * maxSlots + k]; only read for k < slots[a]. Empty means psi = 1
    // for k = 0 (a classical element).
    int maxSlots = 1;
    std::vector<double> psi;

    double multiplier(int p, int a, int k) const {
        if (psi.empty()) return k == 0 ? 1.0 : 0.0;
        return psi[(size_t(p) * nodeCount + a) * maxSlots + k];
    }
};

}  // namespace ma
