#pragma once
// The interface through which an X-FEM model (src/xfem) changes what the classical engine does:
// more unknowns per node, and sub-cell integration of cut elements. The engine (src/fe) knows
// only this interface, so fe does not depend on xfem.
#include <string>
#include <vector>

#include "fe/ElementIntegration.hpp"

namespace ma {

class Enrichment {
public:
    virtual ~Enrichment() = default;
    // 1 + number of Heaviside slots carried by `node` (1 for a node that is not enriched).
    virtual int nodeSlots(int node) const = 0;
    // True when the element on `cell` is an X-FEM element (integrated on sub-cells).
    virtual bool isEnriched(int cell) const = 0;
    // Integration description of an enriched element (volume or skin cell).
    virtual void integration(int cell, ElementIntegration& out) const = 0;
    // Smallest retained volume fraction of an enrichment support, for the log (conditioning).
    virtual double smallestRetainedFraction() const { return 1.0; }
};

}  // namespace ma
