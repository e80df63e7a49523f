#pragma once
// The ssnv511-family meshes with N divisions per side (tools/ssnv511_mesh, tests): the rectangle
// [xmin,xmax]x[ymin,ymax] (default the square [-5,5]^2), 2D QUAD4 or TRIA3 with the edge groups
// LB/LD/LH/LG (SEG2, counter-clockwise), or one layer zmin<=z<=zmax of HEXA8 (or `layers` of them) or TETRA4 with VOLU
// and the outward skin ENV (HEXA8 also SD/SG, the faces x=xmax and x=xmin). The same cells and
// group names as code_aster's ssnv511 meshes in ../shared/astest, numbered row by row and with
// right-handed volumes (code_aster's HEXA8 files are left-handed; docs/med.md).
#include <memory>
#include <string>

#include "mesh/Mesh.hpp"

namespace ma {

struct Ssnv511MeshOptions {
    enum class Kind { Quad4, Tria3, Hexa8, Tetra4 };
    Kind kind = Kind::Quad4;
    int divisions = 5;
    double xmin = -5, xmax = 5, ymin = -5, ymax = 5, zmin = 0, zmax = 1;
    // Interior grid lines moved by this fraction of the cell size (|offset| < 1), boundary lines
    // fixed: moves the interfaces x=0 / y=0 and the junction point away from cell centres (odd N)
    // or off the grid lines (even N).
    double offsetX = 0, offsetY = 0;
    // HEXA8 only: the cells in z (a true 3D block for the solver study: N x N x layers).
    int layers = 1;
};

// UserError on bad options (N < 1, empty box, |offset| >= 1).
std::shared_ptr<Mesh> buildSsnv511Mesh(const Ssnv511MeshOptions& options);

// "quad4" | "tria3" | "hexa8" | "tetra4"; false when unknown.
bool ssnv511KindFromName(const std::string& name, Ssnv511MeshOptions::Kind& kind);

}  // namespace ma
