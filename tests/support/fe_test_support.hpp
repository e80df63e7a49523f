#pragma once
// Helpers for the fe_* tests: structured (optionally distorted) meshes with boundary groups,
// calls of registered commands with hand-built keyword sets, functions of X, Y, Z.
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/Function.hpp"
#include "core/Messages.hpp"
#include "fe/Material.hpp"
#include "fe/MechanicalLoad.hpp"
#include "fe/Model.hpp"
#include "fields/Fields.hpp"
#include "mesh/Mesh.hpp"
#include "parser/Catalog.hpp"
#include "parser/CommandRegistry.hpp"

namespace fetest {

using namespace ma;

// A function of X, Y, Z given by a C++ lambda (stands for a FORMULE).
class LambdaFunction : public Function {
public:
    explicit LambdaFunction(std::function<double(double, double, double)> f) : f_(std::move(f)) { name.push_back('F'); }
    std::string typeName() const override { return "formule"; }
    const std::vector<std::string>& parameters() const override { return params_; }
    double evaluate(std::span<const double> a) const override { return f_(a[0], a[1], a[2]); }

private:
    std::vector<std::string> params_{"X", "Y", "Z"};
    std::function<double(double, double, double)> f_;
};

// A function of INST only (FONC_MULT).
class TimeFunction : public Function {
public:
    explicit TimeFunction(std::function<double(double)> f) : f_(std::move(f)) { name.append("RAMPE", 5); }
    std::string typeName() const override { return "formule"; }
    const std::vector<std::string>& parameters() const override { return params_; }
    double evaluate(std::span<const double> a) const override { return f_(a[0]); }

private:
    std::vector<std::string> params_{"INST"};
    std::function<double(double)> f_;
};

inline ConceptPtr run(const std::string& command, const KeywordSet& kw, const std::string& resultName = "RES") {
    const auto* fn = CommandRegistry::instance().find(command);
    if (!fn) throw std::runtime_error("command not registered: " + command);
    CommandContext ctx;
    ctx.command = command;
    ctx.resultName = resultName;
    auto out = (*fn)(validateKeywords(command, kw), ctx);
    if (out) out->name = resultName;
    return out;
}

inline void set(KeywordSet& k, const std::string& key, KeywordValue v) { k.setValues(key, {std::move(v)}); }
inline void setTexts(KeywordSet& k, const std::string& key, const std::vector<std::string>& v) {
    std::vector<KeywordValue> vals(v.begin(), v.end());
    k.setValues(key, vals);
}

// Small perturbation of interior nodes so that elements are not parallelograms.
inline double wobble(double x, double y, double z) { return 0.07 * std::sin(3.1 * x + 1.3 * y + 0.7 * z); }

// [0,L]^2 with nx x ny QUAD4 (or 2 TRIA3 per quad), interior nodes distorted. Cell groups ALL
// (volume), LEFT/RIGHT/BOTTOM/TOP (SEG2, counter-clockwise = outward normals), node groups of
// the same names, node group CORNER (0,0) and CORNER_TL (0,L).
inline std::shared_ptr<Mesh> planeMesh(int nx, int ny, bool triangles, double L = 2.0) {
    auto m = std::make_shared<Mesh>();
    m->dim = 2;
    m->name = "MAIL";
    auto id = [&](int i, int j) { return j * (nx + 1) + i; };
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            double x = L * i / nx, y = L * j / ny;
            if (i > 0 && i < nx && j > 0 && j < ny) {
                const double dx = wobble(x, y, 0) * L / nx, dy = wobble(y, x, 0) * L / ny;
                x += dx, y += dy;
            }
            m->addNode({x, y, 0.0});
        }
    std::vector<int> all, left, right, bottom, top;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            if (triangles) {
                all.push_back(m->addCell(CellType::TRIA3, std::vector<int>{a, b, c}));
                all.push_back(m->addCell(CellType::TRIA3, std::vector<int>{a, c, d}));
            } else {
                all.push_back(m->addCell(CellType::QUAD4, std::vector<int>{a, b, c, d}));
            }
        }
    for (int i = 0; i < nx; ++i) bottom.push_back(m->addCell(CellType::SEG2, std::vector<int>{id(i, 0), id(i + 1, 0)}));
    for (int j = 0; j < ny; ++j)
        right.push_back(m->addCell(CellType::SEG2, std::vector<int>{id(nx, j), id(nx, j + 1)}));
    for (int i = nx; i > 0; --i) top.push_back(m->addCell(CellType::SEG2, std::vector<int>{id(i, ny), id(i - 1, ny)}));
    for (int j = ny; j > 0; --j) left.push_back(m->addCell(CellType::SEG2, std::vector<int>{id(0, j), id(0, j - 1)}));
    m->cellGroups.set("ALL", all);
    m->cellGroups.set("LEFT", left);
    m->cellGroups.set("RIGHT", right);
    m->cellGroups.set("BOTTOM", bottom);
    m->cellGroups.set("TOP", top);
    std::vector<int> boundary;
    for (const auto& g : {"LEFT", "RIGHT", "BOTTOM", "TOP"})
        for (int c : m->cellGroups.get(g))
            for (int n : m->cellNodes(c)) boundary.push_back(n);
    std::sort(boundary.begin(), boundary.end());
    boundary.erase(std::unique(boundary.begin(), boundary.end()), boundary.end());
    m->nodeGroups.set("BOUNDARY", boundary);
    m->nodeGroups.set("CORNER", {id(0, 0)});
    m->nodeGroups.set("CORNER_TL", {id(0, ny)});
    return m;
}

// [0,L]^3 with n^3 HEXA8 (or 6 TETRA4 per hexahedron), interior nodes distorted. Cell groups
// ALL, and outward-oriented faces (QUAD4, or 2 TRIA3) XMIN XMAX YMIN YMAX ZMIN ZMAX; node groups
// BOUNDARY, CORNER (0,0,0).
inline std::shared_ptr<Mesh> boxMesh(int n, bool tetras, double L = 2.0) {
    auto m = std::make_shared<Mesh>();
    m->dim = 3;
    m->name = "MAIL";
    auto id = [&](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                double x = L * i / n, y = L * j / n, z = L * k / n;
                const bool interior = i > 0 && i < n && j > 0 && j < n && k > 0 && k < n;
                if (interior) x += wobble(x, y, z) * L / n, y += wobble(y, z, x) * L / n, z += wobble(z, x, y) * L / n;
                m->addNode({x, y, z});
            }
    std::vector<int> all;
    auto signedVolume = [&](const std::array<int, 4>& t) {
        const auto &a = m->coords[t[0]], &b = m->coords[t[1]], &c = m->coords[t[2]], &d = m->coords[t[3]];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]},
                     w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
        return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
               u[2] * (v[0] * w[1] - v[1] * w[0]);
    };
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const int h[8] = {id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
                                  id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
                if (!tetras) {
                    all.push_back(m->addCell(CellType::HEXA8, std::span<const int>(h, 8)));
                    continue;
                }
                // Six tetrahedra around the diagonal 0-6.
                const int tets[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                                        {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
                for (const auto& t : tets) {
                    std::array<int, 4> c{h[t[0]], h[t[1]], h[t[2]], h[t[3]]};
                    if (signedVolume(c) < 0) std::swap(c[1], c[2]);
                    all.push_back(m->addCell(CellType::TETRA4, c));
                }
            }
    m->cellGroups.set("ALL", all);
    // Faces, counter-clockwise seen from outside.
    auto addFaces = [&](const std::string& name, auto corner) {
        std::vector<int> cells;
        for (int b = 0; b < n; ++b)
            for (int a = 0; a < n; ++a) {
                const std::array<int, 4> q = corner(a, b);
                if (tetras) {
                    // Split consistently with the volume tets is not needed for loads (nodes match).
                    cells.push_back(m->addCell(CellType::TRIA3, std::vector<int>{q[0], q[1], q[2]}));
                    cells.push_back(m->addCell(CellType::TRIA3, std::vector<int>{q[0], q[2], q[3]}));
                } else {
                    cells.push_back(m->addCell(CellType::QUAD4, q));
                }
            }
        m->cellGroups.set(name, cells);
    };
    addFaces("XMIN", [&](int a, int b) {
        return std::array<int, 4>{id(0, a, b), id(0, a, b + 1), id(0, a + 1, b + 1), id(0, a + 1, b)};
    });
    addFaces("XMAX", [&](int a, int b) {
        return std::array<int, 4>{id(n, a, b), id(n, a + 1, b), id(n, a + 1, b + 1), id(n, a, b + 1)};
    });
    addFaces("YMIN", [&](int a, int b) {
        return std::array<int, 4>{id(a, 0, b), id(a + 1, 0, b), id(a + 1, 0, b + 1), id(a, 0, b + 1)};
    });
    addFaces("YMAX", [&](int a, int b) {
        return std::array<int, 4>{id(a, n, b), id(a, n, b + 1), id(a + 1, n, b + 1), id(a + 1, n, b)};
    });
    addFaces("ZMIN", [&](int a, int b) {
        return std::array<int, 4>{id(a, b, 0), id(a, b + 1, 0), id(a + 1, b + 1, 0), id(a + 1, b, 0)};
    });
    addFaces("ZMAX", [&](int a, int b) {
        return std::array<int, 4>{id(a, b, n), id(a + 1, b, n), id(a + 1, b + 1, n), id(a, b + 1, n)};
    });
    std::vector<int> boundary;
    for (int node = 0; node < m->nodeCount(); ++node) {
        const auto& x = m->coords[node];
        for (double c : x)
            if (std::abs(c) < 1e-12 || std::abs(c - L) < 1e-12) {
                boundary.push_back(node);
                break;
            }
    }
    m->nodeGroups.set("BOUNDARY", boundary);
    m->nodeGroups.set("CORNER", {id(0, 0, 0)});
    return m;
}

inline std::shared_ptr<Model> affeModele(const std::shared_ptr<Mesh>& mesh, const std::string& modelisation,
                                         const std::vector<std::string>& groups) {
    KeywordSet kw;
    set(kw, "MAILLAGE", mesh);
    auto& a = kw.addOccurrence("AFFE");
    setTexts(a, "GROUP_MA", groups);
    set(a, "PHENOMENE", std::string("MECANIQUE"));
    set(a, "MODELISATION", modelisation);
    return std::dynamic_pointer_cast<Model>(run("AFFE_MODELE", kw, "MODELE"));
}

inline std::shared_ptr<MaterialField> material(const std::shared_ptr<Model>& model, double E, double nu) {
    KeywordSet m;
    auto& e = m.addOccurrence("ELAS");
    set(e, "E", E);
    set(e, "NU", nu);
    auto mat = run("DEFI_MATERIAU", m, "ACIER");
    KeywordSet f;
    set(f, "MODELE", model);
    auto& a = f.addOccurrence("AFFE");
    set(a, "TOUT", std::string("OUI"));
    set(a, "MATER", mat);
    return std::dynamic_pointer_cast<MaterialField>(run("AFFE_MATERIAU", f, "CHMAT"));
}

}  // namespace fetest
