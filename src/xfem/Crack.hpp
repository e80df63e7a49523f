#pragma once
// The crack concept (fiss_xfem) made by DEFI_FISS_XFEM with TYPE_DISCONTINUITE='INTERFACE':
// the normal level set at the nodes, the cut cells, the enriched nodes and the junction data
// (xfem_spec §1, §2).
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "core/Concept.hpp"
#include "mesh/Mesh.hpp"

namespace ma::xfem {

class Crack;

// One master of a branch interface (JONCTION): the branch exists only where
// coef * LSN_master < 0 (the side of POINT).
struct JunctionMaster {
    std::shared_ptr<const Crack> crack;
    double coef = 0.0;     // -1 or +1 (xfem_spec §2.1)
    bool declared = true;  // listed under JONCTION/FISSURE (false: inherited through a chain)
};

class Crack : public Concept {
public:
    std::string typeName() const override { return "fiss_xfem"; }

    std::shared_ptr<const Mesh> mesh;
    std::vector<double> lsn;                         // normal level set at every mesh node
    std::vector<std::array<double, 3>> lsnGradient;  // nodal average of the cell gradients (§1.3), nodes of cut cells
    std::vector<int> cutCells;                       // MAFIS (§1.4), increasing
    std::vector<unsigned char> nodeStatus;           // STNO: 1 = Heaviside enriched (§1.5, §2.4)
    std::vector<int> heavisideCells;                 // MAILFISS.HEAV (§1.6), increasing
    std::vector<JunctionMaster> masters;             // JONFISS / JONCOEF (§2.2), chain included
    int adjustedLevelSets = 0;                       // nodal values moved onto the interface (§1.2)

    int enrichedNodeCount() const;
    // True when `crack` is a master (directly or through a chain) of this crack.
    bool hasMaster(const Crack* crack) const;
};

// What DEFI_FISS_XFEM needs beyond the level set.
struct JunctionInput {
    std::vector<std::shared_ptr<const Crack>> masters;  // JONCTION/FISSURE
    std::array<double, 3> point{};                      // JONCTION/POINT
    std::string keywordPath = "JONCTION";               // for messages
};

// Snapping of the nodal level set (§1.2): values whose zero lies within 1e-6 (relative) of an
// edge end are set to 0, cell by cell, edge by edge, in place. Returns the number of changes.
int snapLevelSet(const Mesh& mesh, std::vector<double>& lsn);

// Builds a crack from its (unsnapped) nodal level set: snapping, gradient, cut cells, node
// status with the junction correction, Heaviside cells. UserError when the interface does not
// cut the mesh, when POINT lies in no cell or on a master interface (the master's level set
// interpolated at POINT, which also gives the side). `zone` (GROUP_MA_ENRI, flags by cell): only its
// cells are cut cells, hence only their nodes are enriched; null: the whole mesh.
std::shared_ptr<Crack> buildCrack(const std::shared_ptr<const Mesh>& mesh, std::vector<double> lsn,
                                  const JunctionInput* junction, const std::vector<char>* zone = nullptr);

}  // namespace ma::xfem
