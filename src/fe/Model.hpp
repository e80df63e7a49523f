#pragma once
// The model concept (modele_sdaster): which cells carry which finite element.
#include <memory>
#include <string>
#include <vector>

#include "core/Concept.hpp"
#include "fields/PointGeometryCache.hpp"
#include "mesh/Mesh.hpp"

namespace ma {

class Enrichment;  // fe/Enrichment.hpp, implemented by src/xfem (MODI_MODELE_XFEM)

enum class Modelisation { D_PLAN, C_PLAN, TRI_D /* '3D' */ };
std::string modelisationName(Modelisation m);  // "D_PLAN", "C_PLAN", "3D"

struct ModelElement {
    int cell = -1;
    Modelisation modelisation = Modelisation::TRI_D;
};

class Model : public Concept {
public:
    std::string typeName() const override { return "modele_sdaster"; }

    std::shared_ptr<Mesh> mesh;
    // Elements whose dimension is the model's (2D: TRIA3/QUAD4, 3D: TETRA4/HEXA8), in cell order.
    std::vector<ModelElement> elements;
    // Boundary ("skin") elements: lower-dimension cells named in AFFE, able to carry PRES_REP.
    std::vector<ModelElement> skinElements;
    // X-FEM enrichment (null for a classical model). MODI_MODELE_XFEM makes a new Model that
    // copies MODELE_IN's elements and sets this (the concrete type lives in src/xfem).
    std::shared_ptr<Enrichment> enrichment;

    int dim = 2;                                       // displacement components: 2 (D_PLAN, C_PLAN) or 3
    Modelisation modelisation = Modelisation::D_PLAN;  // the (single) modelisation of the model

    // The point geometry its stress and strain fields share (fe/ResultFields; a copy starts empty).
    PointGeometryCache pointGeometry;
};

}  // namespace ma
