#pragma once
// The visualisation mesh of an X-FEM model (POST_MAIL_XFEM, xfem_spec §6) and the fields on it
// (POST_CHAM_XFEM, §7).
//
// Mesh: classical cells of the model are copied (names, types, nodes); every X-FEM cell (volume or
// skin, cut or not) is replaced by its sub-cells. New nodes are made per parent cell, one per
// distinct (sub-cell vertex, Heaviside tuple of the sub-cell): original nodes and interface points
// appear once per side and per parent cell. Names: PREF_NOEUD_M/P ('NM'/'NP') for points on an
// interface on its -/+ side, PREF_NOEUD_X ('NX') otherwise, followed by one global counter in
// base 36 (NX1 ... NX9, NXA ... NXZ, NX10 ...); cells PREF_MAILLE_X + decimal counter (MX1 ...),
// after the classical cells. Group PREF_GROUP_CO ('NFISSU') = all interface nodes (NM and NP) in
// creation order. GROUP_MA are carried over (X-FEM cells replaced by their sub-cells, empty groups
// dropped); GROUP_NO are not.
#include <memory>
#include <string>
#include <vector>

#include "fe/Model.hpp"
#include "fe/Result.hpp"
#include "mesh/Mesh.hpp"

namespace ma::xfem {

class XfemModel;

struct VisualisationNames {
    std::string nodeX = "NX", nodeMinus = "NM", nodePlus = "NP", cellX = "MX", crackGroup = "NFISSU";
};

// Where each node and cell of the visualisation mesh comes from.
struct VisualisationNode {
    int original = -1;    // node of the original mesh (copied nodes of classical cells), or -1
    int parentCell = -1;  // X-FEM cell the new node belongs to
    int point = -1;       // CutPoint of that cell
    int subcell = -1;     // first sub-cell that made the node (its Heaviside tuple = the node's side)
    bool onCrack = false;
};
struct VisualisationCell {
    int original = -1;    // copied classical cell, or -1
    int parentCell = -1;  // X-FEM parent
    int subcell = -1;
};

struct Visualisation {
    std::shared_ptr<Mesh> mesh;
    std::vector<VisualisationNode> nodes;
    std::vector<VisualisationCell> cells;
};

// The deterministic traversal shared by POST_MAIL_XFEM and POST_CHAM_XFEM.
Visualisation buildVisualisation(const Model& model, const XfemModel& xm, const VisualisationNames& names = {});

// Name counter of the new nodes: base 36, upper case, no padding (codlet).
std::string base36(long long value);

// POST_CHAM_XFEM: DEPL (and SIEF_ELGA averaged per sub-cell) of every step of `input` on the
// visualisation mesh of `modelVisu`. UserError when modelVisu is not built on the visualisation
// mesh of the result's X-FEM model.
std::shared_ptr<Result> visualisationResult(const Result& input, const std::shared_ptr<Model>& modelVisu);

}  // namespace ma::xfem
