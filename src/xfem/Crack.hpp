#pragma once
// The crack concept (fiss_xfem) made by DEFI_FISS_XFEM: the level sets at the nodes, the cut
// cells, the node status and the junction data (xfem_spec §1, §2); for TYPE_DISCONTINUITE='FISSURE'
// also the tangential level set, the cells containing the front and the front (docs/cracks.md).
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "core/Concept.hpp"
#include "mesh/Mesh.hpp"
#include "xfem/CrackFront.hpp"

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
    bool isCrack = false;                            // TYPE_DISCONTINUITE='FISSURE': it has a front
    std::vector<double> lsn;                         // normal level set at every mesh node
    std::vector<double> lst;                         // tangential level set (-1 everywhere for an interface)
    std::vector<std::array<double, 3>> lsnGradient;  // nodal average of the cell gradients (§1.3), nodes of cut cells
    std::vector<int> cutCells;                       // MAFIS (§1.4), increasing
    std::vector<unsigned char> nodeStatus;           // STNO: 0, 1 Heaviside, 2 crack tip, 3 both (§1.5, §2.4)
    std::vector<int> tipCells;                       // MAFOND: cut cells whose nodes all have status 2 or 3
    std::vector<CrackFront> fronts;                  // FONDFISS, in order (empty for an interface)
    std::vector<int> heavisideCells;                 // MAILFISS.HEAV (§1.6), increasing
    std::vector<JunctionMaster> masters;             // JONFISS / JONCOEF (§2.2), chain included
    int adjustedLevelSets = 0;                       // nodal values moved onto the interface (§1.2)

    int enrichedNodeCount() const;  // status 1
    int nodeCountWithStatus(int status) const;
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

// Builds an interface from its (unsnapped) nodal level set: snapping, gradient, cut cells, node
// status with the junction correction, Heaviside cells. UserError when the interface does not
// cut the mesh, when POINT lies in no cell or on a master interface (the master's level set
// interpolated at POINT, which also gives the side). `zone` (GROUP_MA_ENRI, flags by cell): only its
// cells are cut cells, hence only their nodes are enriched; null: the whole mesh.
std::shared_ptr<Crack> buildCrack(const std::shared_ptr<const Mesh>& mesh, std::vector<double> lsn,
                                  const JunctionInput* junction, const std::vector<char>* zone = nullptr);

// Builds a crack (TYPE_DISCONTINUITE='FISSURE', no junction) from its unsnapped nodal level sets:
// both snapped as code_aster's xajuls does, cut cells, node status (xstano), tip cells, fronts.
std::shared_ptr<Crack> buildCrackWithFront(const std::shared_ptr<const Mesh>& mesh, std::vector<double> lsn,
                                           std::vector<double> lst);

// TYPE_ENRI_FOND='GEOMETRIQUE' (xstano, xstama): nodes with sqrt(LSN^2 + LST^2) <= radius take the
// crack-tip status too (0 -> 2, 1 -> 3); with radius <= 0, radius = layers (NB_COUCHES) times the
// smallest characteristic length of the tip cells. Returns the radius used (0 without a front).
double enrichCrackTipZone(Crack& crack, double radius, int layers);

// The average at each node of the gradients of a nodal field computed at that node in every cell
// of the mesh's dimension around it (GRLNNO, GRLTNO).
std::vector<std::array<double, 3>> nodalLevelSetGradient(const Mesh& mesh, const std::vector<double>& values);

}  // namespace ma::xfem
