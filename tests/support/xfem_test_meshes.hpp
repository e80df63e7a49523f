#pragma once
// Programmatic meshes of the ssnv511 geometry for the X-FEM unit tests: the square [-5,5]^2
// (2D: QUAD4 or TRIA3) or the slab [-5,5]^2 x [0,1] (3D: HEXA8 or TETRA4), n x n cells, boundary
// SEG2 groups LB/LD/LH/LG (counter-clockwise), cells numbered by type (segments first) like the
// MED meshes.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "fe/Model.hpp"
#include "mesh/Mesh.hpp"
#include "xfem/Crack.hpp"
#include "xfem/XfemModel.hpp"

namespace xfemtest {

// Node coordinates x_i = lo + i * (hi - lo) / n, optionally shifted.
inline std::vector<double> grid(int n, double lo = -5, double hi = 5) {
    std::vector<double> v(n + 1);
    for (int i = 0; i <= n; ++i) v[i] = lo + (hi - lo) * i / n;
    v[n] = hi;
    return v;
}

// 2D square. kind = QUAD4 or TRIA3 (each square split along its diagonal 1-3).
inline std::shared_ptr<ma::Mesh> square(int n, ma::CellType kind, std::vector<double> xs = {},
                                        std::vector<double> ys = {}) {
    if (xs.empty()) xs = grid(n);
    if (ys.empty()) ys = grid(n);
    auto m = std::make_shared<ma::Mesh>();
    m->dim = 2;
    m->name = "MAILLAG";
    auto id = [&](int i, int j) { return j * (n + 1) + i; };
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) m->addNode({xs[i], ys[j], 0.0});
    std::vector<int> lb, ld, lh, lg, surf;
    for (int i = 0; i < n; ++i) lb.push_back(m->addCell(ma::CellType::SEG2, std::vector<int>{id(i, 0), id(i + 1, 0)}));
    for (int j = 0; j < n; ++j) ld.push_back(m->addCell(ma::CellType::SEG2, std::vector<int>{id(n, j), id(n, j + 1)}));
    for (int i = n; i > 0; --i) lh.push_back(m->addCell(ma::CellType::SEG2, std::vector<int>{id(i, n), id(i - 1, n)}));
    for (int j = n; j > 0; --j) lg.push_back(m->addCell(ma::CellType::SEG2, std::vector<int>{id(0, j), id(0, j - 1)}));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            if (kind == ma::CellType::QUAD4) {
                surf.push_back(m->addCell(kind, std::vector<int>{a, b, c, d}));
            } else {
                surf.push_back(m->addCell(kind, std::vector<int>{a, b, c}));
                surf.push_back(m->addCell(kind, std::vector<int>{a, c, d}));
            }
        }
    m->cellGroups.set("LB", lb);
    m->cellGroups.set("LD", ld);
    m->cellGroups.set("LH", lh);
    m->cellGroups.set("LG", lg);
    m->cellGroups.set("SURF", surf);
    return m;
}

// 3D slab 0 <= z <= 1 in `layers` layers (one by default; n layers make ssnv511c's 10:1 flat cells).
// kind = HEXA8 or TETRA4 (each hexahedron split into 6 tetrahedra around its diagonal 1-7).
inline std::shared_ptr<ma::Mesh> slab(int n, ma::CellType kind, int layers = 1) {
    const auto xs = grid(n), ys = grid(n);
    auto m = std::make_shared<ma::Mesh>();
    m->dim = 3;
    m->name = "MAILLAG";
    auto id = [&](int i, int j, int k) { return k * (n + 1) * (n + 1) + j * (n + 1) + i; };
    for (int k = 0; k <= layers; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) m->addNode({xs[i], ys[j], double(k) / layers});
    std::vector<int> volu;
    for (int k = 0; k < layers; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const std::array<int, 8> h{
                    id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
                    id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
                if (kind == ma::CellType::HEXA8) {
                    volu.push_back(m->addCell(kind, std::vector<int>(h.begin(), h.end())));
                } else {
                    // Six tetrahedra around the diagonal 0-6 (positive orientation).
                    const int t[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                                         {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
                    for (const auto& tt : t)
                        volu.push_back(m->addCell(kind, std::vector<int>{h[tt[0]], h[tt[1]], h[tt[2]], h[tt[3]]}));
                }
            }
    m->cellGroups.set("VOLU", volu);
    return m;
}

inline ma::Model model(const std::shared_ptr<ma::Mesh>& mesh, bool withSkin = false) {
    ma::Model mo;
    mo.mesh = mesh;
    const int dim = mesh->maxCellDimension();
    mo.dim = dim;
    mo.modelisation = dim == 3 ? ma::Modelisation::TRI_D : ma::Modelisation::D_PLAN;
    for (int c = 0; c < mesh->cellCount(); ++c) {
        const int d = ma::cellDimension(mesh->cellTypes[c]);
        if (d == dim) mo.elements.push_back({c, mo.modelisation});
        else if (withSkin && d == dim - 1) mo.skinElements.push_back({c, mo.modelisation});
    }
    return mo;
}

// Level set from a function of (x, y, z) at every node.
template <class F>
std::vector<double> levelSet(const ma::Mesh& mesh, F f) {
    std::vector<double> v;
    for (const auto& x : mesh.coords) v.push_back(f(x[0], x[1], x[2]));
    return v;
}

struct Junction3 {
    std::shared_ptr<ma::xfem::Crack> fiss1, fiss2, fiss3;
};

// ssnv511's three interfaces: Y, X restricted to Y > 0 (POINT (0,5)), X restricted to Y < 0,
// with the junction possibly shifted to (x0, y0).
inline Junction3 ssnv511Cracks(const std::shared_ptr<ma::Mesh>& mesh, double x0 = 0, double y0 = 0) {
    Junction3 j;
    j.fiss1 = ma::xfem::buildCrack(mesh, levelSet(*mesh, [&](double, double y, double) { return y - y0; }), nullptr);
    j.fiss1->name = "FISS1";
    ma::xfem::JunctionInput up;
    up.masters = {j.fiss1};
    up.point = {x0, 5, 0};
    j.fiss2 = ma::xfem::buildCrack(mesh, levelSet(*mesh, [&](double x, double, double) { return x - x0; }), &up);
    j.fiss2->name = "FISS2";
    ma::xfem::JunctionInput down = up;
    down.point = {x0, -5, 0};
    j.fiss3 = ma::xfem::buildCrack(mesh, levelSet(*mesh, [&](double x, double, double) { return x - x0; }), &down);
    j.fiss3->name = "FISS3";
    return j;
}

}  // namespace xfemtest
