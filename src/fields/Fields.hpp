#pragma once
// Fields (cham_no / cham_elem) and the archived steps of a result (fe/Result.hpp).
#include <memory>
#include <string>
#include <vector>

#include "core/Concept.hpp"
#include "core/SharedVector.hpp"
#include "mesh/Mesh.hpp"

namespace ma {

// A field on the nodes (cham_no, e.g. DEPL). Components are the union over all nodes, in the
// order of the physical quantity (DX, DY, DZ, H1X, H1Y, ..., LAGS_C ...); a node carries a
// subset of them (X-FEM: only enriched nodes have H1X...).
class NodalField : public Concept {
public:
    std::string typeName() const override { return "cham_no_sdaster"; }

    std::shared_ptr<const Mesh> mesh;
    std::string quantity = "DEPL_R";      // physical quantity
    std::vector<std::string> components;  // e.g. {"DX","DY","H1X","H1Y"}
    std::vector<double> values;           // nodeCount * components.size()
    std::vector<unsigned char> present;   // same layout: 1 when the node carries the component

    void resize(const std::shared_ptr<const Mesh>& m, std::vector<std::string> comps);
    int componentIndex(const std::string& comp) const;  // -1 when absent
    int componentCount() const { return static_cast<int>(components.size()); }
    double& at(int node, int comp) { return values[size_t(node) * components.size() + comp]; }
    double at(int node, int comp) const { return values[size_t(node) * components.size() + comp]; }
    bool has(int node, int comp) const { return present[size_t(node) * components.size() + comp] != 0; }
    void set(int node, int comp, double v) {
        at(node, comp) = v;
        present[size_t(node) * components.size() + comp] = 1;
    }
};

// A field at integration points (cham_elem ELGA, e.g. SIEF_ELGA). Each point keeps its physical
// coordinates and its weight (|J| included) so that integrals over the model need no element
// knowledge (POST_ERREUR). X-FEM elements list the points of all their sub-cells.
class GaussField : public Concept {
public:
    std::string typeName() const override { return "cham_elem"; }

    std::shared_ptr<const Mesh> mesh;
    std::string quantity = "SIEF_R";
    std::vector<std::string> components;  // e.g. {"SIXX","SIYY","SIZZ","SIXY"}
    std::vector<int> cells;               // mesh cell of each element
    std::vector<int> pointOffsets{0};     // element e has points [pointOffsets[e], pointOffsets[e+1])
    // The point geometry, shared by the fields of the same points (core/SharedVector.hpp).
    SharedVector<std::array<double, 3>> pointCoords;
    SharedVector<double> pointWeights;
    SharedVector<int> pointSubcell;                      // sub-cell index within the element (0 when not X-FEM)
    SharedVector<std::array<double, 3>> pointRefCoords;  // in the parent reference element (MED localisation)
    std::vector<double> values;                          // pointCount * components.size()
    // ELNO (SIGM_ELNO...): the points of an element are its cell's nodes in the mesh's local order
    // (pointRefCoords = the reference nodes), printed in MED on MED_NODE_ELEMENT.
    bool atNodes = false;

    int pointCount() const { return static_cast<int>(pointWeights.size()); }
    int componentCount() const { return static_cast<int>(components.size()); }
    int componentIndex(const std::string& comp) const;
};

// One archived state of a result (NUME_ORDRE, INST and its fields).
struct ResultStep {
    int order = 0;                                                                 // NUME_ORDRE
    double inst = 0.0;                                                             // INST
    std::vector<std::pair<std::string, std::shared_ptr<NodalField>>> nodalFields;  // "DEPL"...
    std::vector<std::pair<std::string, std::shared_ptr<GaussField>>> gaussFields;  // "SIEF_ELGA"...

    std::shared_ptr<NodalField> nodal(const std::string& name) const;
    std::shared_ptr<GaussField> gauss(const std::string& name) const;
};

}  // namespace ma
