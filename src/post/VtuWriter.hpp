#pragma once
// VTK XML unstructured grid (.vtu) files for ParaView / VTK (miniaster convert, docs/visualisation.md):
// the mesh's cells of every type, point and cell data arrays, base64 binary, written atomically.
#include <string>
#include <vector>

#include "mesh/Mesh.hpp"

namespace ma::vtu {

struct DataArray {
    std::string name;
    std::vector<std::string> componentNames;  // one per component (shown by ParaView)
    std::vector<double> values;               // tuple by tuple; NaN where a tuple has no value
    bool flag = false;                        // 0/1 membership (groups): written as UInt8
    int componentCount() const { return int(componentNames.size()); }
};

// VTK cell type of a miniaster cell type and the internal node of each VTK node
// (quadratic hexahedra and prisms list their edges in another order; the face and centre nodes of
// HEXA27 / PENTA18 are not written: VTK's quadratic hexahedron / wedge).
struct VtkCell {
    int type;
    std::vector<int> internalNode;  // empty: the same order
    int nodes;
};
VtkCell vtkCellOf(CellType t);

// Writes `mesh` with the arrays (point data: nodeCount tuples, cell data: cellCount tuples).
// `activeVectors` names the point array ParaView takes as the vectors (Warp By Vector, Glyph).
void write(const std::string& path, const Mesh& mesh, const std::vector<DataArray>& pointData,
           const std::vector<DataArray>& cellData, const std::string& activeVectors = "");

// A VTK collection (.pvd): one dataset file per time value, in order, named relative to the
// .pvd's folder (ParaView reads it as a time series, the time value as its time).
struct CollectionStep {
    double time;
    std::string file;
};
void writeCollection(const std::string& path, const std::vector<CollectionStep>& steps);

}  // namespace ma::vtu
