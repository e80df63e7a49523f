#pragma once
// A conforming re-split of a layer of prisms cut into TETRA4 (tools/resplit_layer, tests): the mesh's
// nodes lie on two planes z = zmin and z = zmax, each bottom node has a top node at the same (x, y),
// and every tetrahedron spans three such columns. Its prisms are cut again by one rule for the whole
// mesh: the diagonal of each vertical quadrangle joins the bottom node of its lower-numbered column to
// the top node of the other, so both prisms beside a quadrangle cut it the same way. The nodes and
// their groups are kept; 3D cell groups holding every tetrahedron become every new tetrahedron, TRIA3
// groups holding the whole skin become the new skin, 1D and 0D cells are kept; any other cell group
// is refused (UserError), as is a mesh that is not such a layer.
#include <memory>

#include "mesh/Mesh.hpp"

namespace ma {

std::shared_ptr<Mesh> resplitPrismLayer(const Mesh& layer);

}  // namespace ma
