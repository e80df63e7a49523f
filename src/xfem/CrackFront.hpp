#pragma once
// The front of a crack (DEFI_FISS_XFEM, TYPE_DISCONTINUITE='FISSURE'): where the surface LSN = 0
// meets LST = 0 inside the mesh, for the interpolated nodal level sets (docs/cracks.md).
#include <optional>
#include <span>
#include <vector>

#include "core/Vec3.hpp"
#include "mesh/Mesh.hpp"

namespace ma::xfem {

// One connected front: its points in order and their curvilinear abscissa (chord lengths summed
// from the first point). A closed front repeats its first point at the end, as code_aster does.
// In 2D every front point is a front of its own (abscissa 0).
struct CrackFront {
    std::vector<Vec3> points;
    std::vector<double> abscissa;
    bool closed = false;
};

// The fronts crossing the tip cells (code_aster's MAFOND: cells of the mesh's dimension whose nodes
// all see the front). 3D: one point where the front crosses each face of a tip cell, chained
// through the cells; 2D: the point inside each tip cell. Fronts start at the end point met first
// (tip cells in increasing number, faces in local order); closed fronts at their first point.
std::vector<CrackFront> crackFronts(const Mesh& mesh, const std::vector<double>& lsn, const std::vector<double>& lst,
                                    const std::vector<int>& tipCells);

// The point of a TRIA3 or QUAD4 (a 2D cell or a face of a 3D cell, vertices in cyclic order) where
// both interpolated level sets vanish, when it lies in the cell (Newton in reference coordinates).
std::optional<Vec3> zeroOfTwoLevelSets(CellType type, std::span<const Vec3> vertices, std::span<const double> lsn,
                                       std::span<const double> lst);

}  // namespace ma::xfem
