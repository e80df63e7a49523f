#pragma once
// A free X-FEM model (no Dirichlet condition) of a mesh cut by interfaces, each optionally joined
// (JONCTION) to the first: its discretisation, its assembled stiffness and its blocks. For the tests
// of the multigrid near null space and of the piece basis, where every rigid motion of every block
// must be in the kernel.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/Messages.hpp"
#include "fe/Assembly.hpp"
#include "fe/DirichletConstraints.hpp"
#include "fe/NearNullSpace.hpp"
#include "fe/SparsityPattern.hpp"
#include "fe_test_support.hpp"
#include "xfem_test_meshes.hpp"

namespace xfemtest {

using LevelSet = std::function<double(double, double, double)>;

struct Interface {
    LevelSet lsn;
    bool joined = false;            // JONCTION on the first interface
    std::array<double, 3> point{};  // its POINT
};

struct FreeModel {
    std::shared_ptr<ma::Model> model;
    std::unique_ptr<ma::Discretisation> space;
    ma::DirichletConstraints constraints;
    ma::CsrMatrix K;
    ma::ModelBlocks blocks;
};

inline FreeModel freeModel(const std::shared_ptr<ma::Mesh>& mesh, const std::vector<Interface>& interfaces) {
    using namespace ma;
    msg().setEcho(false);
    FreeModel f;
    std::vector<std::shared_ptr<const xfem::Crack>> cracks;
    std::shared_ptr<xfem::Crack> first;
    for (size_t i = 0; i < interfaces.size(); ++i) {
        xfem::JunctionInput junction;
        if (interfaces[i].joined) junction.masters = {first}, junction.point = interfaces[i].point;
        auto crack =
            xfem::buildCrack(mesh, levelSet(*mesh, interfaces[i].lsn), interfaces[i].joined ? &junction : nullptr);
        crack->name = "FISS" + std::to_string(i + 1);
        if (i == 0) first = crack;
        cracks.push_back(crack);
    }
    f.model = std::make_shared<Model>(model(mesh));
    f.model->name = "MODELEK";
    f.model->enrichment = std::make_shared<xfem::XfemModel>(*f.model, cracks, xfem::XfemContact::None, 1e-15);
    f.space = std::make_unique<Discretisation>(f.model, fetest::material(f.model, 2.0e5, 0.3), ExtraUnknowns{});
    f.constraints = buildDirichletConstraints(*f.space, {}, 0.0, 0);
    f.K = buildSparsityPattern(*f.space, f.constraints, nullptr);
    assembleSystemMatrix(*f.space, f.constraints, nullptr, std::vector<double>(f.space->numbering().size(), 0.0), f.K);
    f.blocks = findBlocks(*f.space);
    return f;
}

inline LevelSet plane(double a, double b, double c, double d) {
    return [=](double x, double y, double z) { return a * x + b * y + c * z + d; };
}

// ssnv511's interfaces (y = y0; x = x0 above and below, joined to the first), the junction at
// (x0, y0).
inline std::vector<Interface> junction(double x0, double y0, bool threeD) {
    return {{plane(0, 1, 0, -y0)},
            {plane(1, 0, 0, -x0), true, {x0, 5, threeD ? 0.5 : 0.0}},
            {plane(1, 0, 0, -x0), true, {x0, -5, threeD ? 0.5 : 0.0}}};
}

inline double maxAbs(std::span<const double> v) {
    double m = 0.0;
    for (double x : v) m = std::max(m, std::abs(x));
    return m;
}

}  // namespace xfemtest
