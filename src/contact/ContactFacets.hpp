#pragma once
// Contact facets of the X-FEM interfaces (docs/contact.md). A facet is a face (2D: edge, 3D:
// triangle) of the integration sub-cells that lies on interface c and separates a sub-cell on
// the - side of c from one on the + side. The sub-cells are cut crack after crack, so a facet
// never crosses another interface: at a junction the interface is split at the junction point
// and every piece belongs to one interface branch and separates exactly two blocks (the two
// sub-cells, whose Heaviside tuples differ).
//
// Interfaces that run exactly along faces of the mesh (a facet between two parent cells) are
// matched across the parent face: the + side is the neighbouring parent cell's sub-cell.
#include <array>
#include <vector>

namespace ma::xfem {
class XfemModel;
}

namespace ma::contact {

struct FacetSide {
    int cell = -1;     // parent X-FEM cell
    int subcell = -1;  // sub-cell of that cell adjacent to the facet
    // Measure of the block the sub-cell belongs to inside its parent (all sub-cells of the parent
    // with the same Heaviside tuple): the stress there is one polynomial (weights of the average).
    double blockMeasure = 0.0;
    double cellMeasure = 0.0;                // measure of the parent cell (sum of its blocks)
    std::vector<std::array<double, 3>> ref;  // facet vertices in the parent's reference coordinates
};

struct ContactFacet {
    int crack = -1;  // index in the X-FEM model's crack list
    FacetSide minus, plus;
    std::vector<std::array<double, 3>> vertices;  // physical (dim vertices)
    std::array<double, 3> normal{};               // unit, from the - side to the + side
    double measure = 0.0;                         // length (2D) or area (3D)
    // Total measure of the facets of the same crack between the same two blocks of the same parent
    // cell(s): the interface length/area the block pair shares (Nitsche parameter).
    double pairMeasure = 0.0;
    bool atJunction = false;  // a vertex lies on another interface of the cell
};

struct FacetStatistics {
    int facets = 0;
    int acrossParentFaces = 0;  // interface along mesh faces: sides in two parent cells
    int atJunction = 0;
    // Facets from the intersection of a - and a + face inside one cell (3D: the two sides
    // triangulate a flat region, left by sliver pieces the cut dropped, differently).
    int clipped = 0;
    // Facets whose other side's piece the cut dropped whole: that side is the block across the face
    // (a sub-cell of the same cell, or of a cell around it).
    int acrossDropped = 0;
    double totalMeasure = 0.0;
    // Faces on an interface inside a parent cell that no face of the other side covers, even after
    // clipping (their uncovered measure): no facet there.
    int unmatched = 0;
    double unmatchedMeasure = 0.0;
};

// Facets of the cracks flagged in `withContact` (by crack index of the model).
std::vector<ContactFacet> buildContactFacets(const xfem::XfemModel& xm, const std::vector<char>& withContact,
                                             FacetStatistics* stats = nullptr);

}  // namespace ma::contact
