#pragma once
// AFFE_CHAR_MECA / AFFE_CHAR_MECA_F (char_meca): Dirichlet conditions as linear relations,
// pressure and forces on skin elements, pressure on the lips of X-FEM interfaces, volume forces.
//
// Every Dirichlet condition is a linear relation  sum_i coef_i * u(node_i, component_i) = value.
// DDL_IMPO makes one-term relations; on a model with an enrichment every DDL_IMPO request is first
// offered to it (Enrichment::imposeDof: X-FEM boundary conditions on enriched nodes, xfem_spec §4,
// make multi-term ones).
#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/Concept.hpp"
#include "core/Function.hpp"
#include "fe/DirichletRelation.hpp"
#include "fe/Model.hpp"

namespace ma {

// A load value: a real, or (AFFE_CHAR_MECA_F) a function of X, Y, Z, INST.
struct LoadValue {
    double value = 0.0;
    std::shared_ptr<const Function> function;  // null: constant value
};

// PRES_REP on boundary cells: traction t = -p n + c (-n_y, n_x) with n the cell's node-order normal
// (c: CISA_2D, plane models only).
struct PressureLoad {
    std::string path;
    std::vector<int> cells;  // skin cells of the model
    double value = 0.0;
    std::shared_ptr<const Function> function;
    LoadValue shear;  // CISA_2D
};

// FORCE_CONTOUR (2D edges), FORCE_FACE (3D faces), FORCE_ARETE (3D edges): a force per unit length
// or area, in the global axes.
struct SurfaceForce {
    std::string path;
    std::vector<int> cells;
    std::array<LoadValue, 3> component{};
};

// PRES_REP(FISSURE=...): a pressure (and in 2D the shear CISA_2D) on both lips of an X-FEM interface.
// On the lip of each side t = -p m + c (-m_y, m_x), m the unit normal out of that side's material
// (code_aster's te0037): a positive pressure pushes the lips apart.
struct LipPressure {
    std::string path;
    std::shared_ptr<const Concept> crack;  // the fiss_xfem; the model's enrichment knows its facets
    LoadValue pressure, shear;
    std::vector<char> onlyCells;  // parent cells whose lips are loaded (empty: all)
};

// FACE_IMPO / ARETE_IMPO DNOR, DTAN: sum_c d_c u_c(node) = value at every node, d the unit normal
// (or tangent) at the node.
struct DirectionalDof {
    std::string path;
    std::vector<int> nodes;
    std::vector<std::array<double, 3>> direction;  // per node
    LoadValue value;
};

// LIAISON_DDL / LIAISON_GROUP: sum_i coef_i u(node_i, component_i) = value, the value a real or a
// function of INST.
struct RelationRequest {
    std::string path;
    std::vector<DofTerm> terms;
    LoadValue value;
};

struct VolumeForce {
    std::string path;
    std::vector<int> cells;  // volume cells of the model
    std::array<double, 3> value{};
    std::array<std::shared_ptr<const Function>, 3> function{};
};

class MechanicalLoad : public Concept {
public:
    std::string typeName() const override { return "char_meca"; }

    std::shared_ptr<const Model> model;
    std::vector<ImposedDof> imposed;
    std::vector<LinearRelation> relations;  // fixed multi-term relations (added by other engines)
    std::vector<DirectionalDof> directional;
    std::vector<RelationRequest> relationRequests;
    std::vector<PressureLoad> pressures;
    std::vector<SurfaceForce> surfaceForces;
    std::vector<LipPressure> lipPressures;
    std::vector<VolumeForce> volumeForces;
    // code_aster <= 2013: AFFE_CHAR_MECA(LIAISON_XFEM='OUI', CONTACT_XFEM=...) carried the X-FEM
    // contact as a load; the contact definition named there (a char_contact, read by STAT_NON_LINE as
    // its CONTACT=; src/commands/LegacyContactLoad.hpp).
    bool xfemLinks = false;  // LIAISON_XFEM='OUI'
    std::shared_ptr<const Concept> xfemContact;

    // All Dirichlet relations at instant `inst` (function values evaluated now; the FONC_MULT
    // factor is applied by the caller). A component a node does not carry is skipped.
    void appendRelations(double inst, std::vector<LinearRelation>& out) const;

private:
    // FACE_IMPO / ARETE_IMPO DNOR, DTAN: one relation per node (one term when the direction is an axis).
    void appendDirectional(double inst, std::vector<LinearRelation>& out) const;
    // The relations of one request's X-FEM enriched nodes (per node, one per side), values unset.
    std::map<int, std::vector<LinearRelation>> enrichedDirectional(const DirectionalDof& request, double inst) const;
};

// Values of `f` at the given points (columns X, Y, Z and INST), in one batch.
std::vector<double> evaluateAtPoints(const Function& f, const std::vector<std::array<double, 3>>& points, double inst);

}  // namespace ma
