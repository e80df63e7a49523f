#pragma once
// AFFE_CHAR_MECA / AFFE_CHAR_MECA_F (char_meca): Dirichlet conditions as linear relations,
// pressure on skin elements, volume forces.
//
// Every Dirichlet condition is a linear relation  sum_i coef_i * u(node_i, component_i) = value.
// DDL_IMPO makes one-term relations; on a model with an enrichment every DDL_IMPO request is first
// offered to it (Enrichment::imposeDof: X-FEM boundary conditions on enriched nodes, xfem_spec §4,
// make multi-term ones).
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "core/Concept.hpp"
#include "core/Function.hpp"
#include "fe/DirichletRelation.hpp"
#include "fe/Model.hpp"

namespace ma {

struct PressureLoad {
    std::string path;
    std::vector<int> cells;  // skin cells of the model
    double value = 0.0;
    std::shared_ptr<const Function> function;
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
    std::vector<PressureLoad> pressures;
    std::vector<VolumeForce> volumeForces;
    // code_aster <= 2013: AFFE_CHAR_MECA(LIAISON_XFEM='OUI', CONTACT_XFEM=...) carried the X-FEM
    // contact as a load; the contact definition named there (a char_contact, read by STAT_NON_LINE as
    // its CONTACT=; src/commands/LegacyContactLoad.hpp).
    bool xfemLinks = false;  // LIAISON_XFEM='OUI'
    std::shared_ptr<const Concept> xfemContact;

    // All Dirichlet relations at instant `inst` (function values evaluated now; the FONC_MULT
    // factor is applied by the caller). A component a node does not carry is skipped.
    void appendRelations(double inst, std::vector<LinearRelation>& out) const;
};

// Values of `f` at the given points (columns X, Y, Z and INST), in one batch.
std::vector<double> evaluateAtPoints(const Function& f, const std::vector<std::array<double, 3>>& points, double inst);

}  // namespace ma
