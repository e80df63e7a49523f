#pragma once
// A contact scene for the unit tests of src/contact: the ssnv511 interfaces (FISS1 horizontal,
// FISS2/FISS3 vertical branches meeting it at the origin) on an n x n programmatic mesh, E = 1e8,
// nu = 0.3, one contact zone per interface, every point initially active.
#include <memory>
#include <vector>

#include "contact/ContactLoop.hpp"
#include "contact/ContactTerms.hpp"
#include "fe/Material.hpp"
#include "xfem_test_meshes.hpp"

namespace contacttest {

using namespace ma;
using namespace ma::contact;

struct Scene {
    std::shared_ptr<Model> model;
    std::shared_ptr<MaterialField> material;
    std::unique_ptr<MechanicalProblem> problem;
    std::shared_ptr<ContactDefinition> definition;
    std::shared_ptr<ContactTerms> terms;
};

inline Scene scene(CellType type, int n, ContactAlgorithm algo, bool bilateral = false,
                   const ContactIntegration& integration = {}) {
    Scene s;
    const bool threeD = type == CellType::HEXA8 || type == CellType::TETRA4;
    auto mesh = threeD ? xfemtest::slab(n, type) : xfemtest::square(n, type);
    s.model = std::make_shared<Model>(xfemtest::model(mesh));
    const auto j = xfemtest::ssnv511Cracks(mesh);
    s.model->enrichment =
        std::make_shared<xfem::XfemModel>(*s.model,
                                          std::vector<std::shared_ptr<const xfem::Crack>>{j.fiss1, j.fiss2, j.fiss3},
                                          xfem::XfemContact::Standard);
    auto mat = std::make_shared<Material>();
    mat->E = 1.0e8;
    mat->nu = 0.3;
    s.material = std::make_shared<MaterialField>();
    s.material->mesh = mesh;
    s.material->cellMaterial.assign(size_t(mesh->cellCount()), mat);
    s.problem = std::make_unique<MechanicalProblem>(s.model, s.material, std::vector<LoadCase>{}, SolverOptions{});
    s.definition = std::make_shared<ContactDefinition>();
    s.definition->model = s.model;
    s.definition->maxContactIterations = 30;  // DEFI_CONTACT's ITER_CONT_MAXI default
    int k = 0;
    for (const auto& c : {j.fiss1, j.fiss2, j.fiss3}) {
        ContactZone z;
        z.crack = c;
        z.crackIndex = k++;
        z.algorithm = algo;
        z.penalty = 1e12;
        z.initiallyActive = true;
        z.bilateral = bilateral;
        z.integration = integration;
        s.definition->zones.push_back(z);
    }
    s.terms = attachContact(*s.problem, *s.material, s.definition);
    return s;
}

// u = eps x on the standard dofs (no jump anywhere), Heaviside dofs 0.
inline std::vector<double> uniformStrain(const Scene& s, double eps) {
    std::vector<double> u(s.problem->state().size(), 0.0);
    const auto& num = s.problem->numbering();
    const Mesh& mesh = *s.model->mesh;
    for (int node = 0; node < mesh.nodeCount(); ++node)
        for (int c = 0; c < num.dim(); ++c)
            if (int d = num.dof(node, 0, c); d >= 0) u[d] = eps * mesh.coords[node][c];
    return u;
}

}  // namespace contacttest
