// Loads on the crack-tip enriched cells of a crack with a front (docs/cracks.md, "Loads on tip
// cells"): the lips' points (each lip's area, clipped at the front), the external forces of AFFE_CHAR_MECA's lip pressure (PRES_REP FISSURE) and boundary
// pressure (PRES_REP on faces whose nodes carry K1, K2[, K3]) against closed forms. Every node is given the
// exact Williams field (modes I + II + III, plane strain) as in astest/xfem_tip_williams_*: DX, DY
// [, DZ] its nodal value, H1 the jump the shifted enrichment implies, K1, K2[, K3] the factors; the
// field lies in the discrete space, so the work f . U of the loads is an integral of the exact field:
// on the lips p times the opening, p K1 (kappa + 1) / mu / sqrt(2 pi) (2/3) a^(3/2) per unit
// thickness (a the lips' length behind the front), modes II and III doing no work. Measured: the
// lip work within 2.2e-15 relative on QUAD4, TRIA3, HEXA8, TETRA4 (so to 1e-13 here), modes II + III
// below 1e-17; the boundary pressure within 6.0e-12 in 2D and 3.2e-12 in 3D (the skin elements'
// Gauss rule on the smooth field; 1e-10 here).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fe/Discretisation.hpp"
#include "fe/ElementKinematics.hpp"
#include "fe/ExternalForces.hpp"
#include "fe_test_support.hpp"
#include "xfem/TipEnrichment.hpp"
#include "xfem_test_meshes.hpp"

namespace {

using namespace ma;

constexpr double kE = 2.0e5, kNu = 0.3, kXt = 0.29, kYt = 0.37;
constexpr double kMu = kE / (2 * (1 + kNu)), kKappa = 3 - 4 * kNu;

struct Factors {
    double k1 = 0, k2 = 0, k3 = 0;
};

// Williams' displacement of modes I, II (plane strain) and III at (x, y), front along z at (kXt, kYt).
Vec3 williams(double x, double y, const Factors& k) {
    const double r = std::hypot(x - kXt, y - kYt), t = std::atan2(y - kYt, x - kXt);
    const double s = std::sqrt(r / (2 * std::numbers::pi)) / (2 * kMu);
    const double c1 = s * k.k1 * (kKappa - std::cos(t)), c2 = s * k.k2;
    return {c1 * std::cos(t / 2) + c2 * std::sin(t / 2) * (kKappa + 2 + std::cos(t)),
            c1 * std::sin(t / 2) + c2 * std::cos(t / 2) * (2 - kKappa - std::cos(t)), s * k.k3 * 4 * std::sin(t / 2)};
}

struct Scene {
    std::shared_ptr<Mesh> mesh;
    std::shared_ptr<xfem::Crack> crack;
    std::shared_ptr<Model> model;
    std::shared_ptr<Discretisation> space;
};

Scene scene(std::shared_ptr<Mesh> mesh) {
    Scene s;
    s.mesh = mesh;
    s.crack =
        xfem::buildCrackWithFront(mesh, xfemtest::levelSet(*mesh, [](double, double y, double) { return y - kYt; }),
                                  xfemtest::levelSet(*mesh, [](double x, double, double) { return x - kXt; }));
    s.crack->name = "FISS";
    xfem::enrichCrackTipZone(*s.crack, 100.0, 0);  // every node carries the tip unknowns
    s.model = std::make_shared<Model>(xfemtest::model(mesh, true));
    s.model->enrichment =
        std::make_shared<xfem::XfemModel>(*s.model, std::vector<std::shared_ptr<const xfem::Crack>>{s.crack});
    s.space = std::make_shared<Discretisation>(s.model, fetest::material(s.model, kE, kNu), ExtraUnknowns{});
    return s;
}

// The exact field's unknowns (docs/cracks.md: H1 = sign (F(x, y) - F(x, 2 yt - y)) / 2).
std::vector<double> exactUnknowns(const Scene& s, const Factors& k) {
    const auto& numbering = s.space->numbering();
    const int dim = numbering.dim();
    std::vector<double> U(numbering.size(), 0.0);
    const double K[3] = {k.k1, k.k2, k.k3};
    for (int n = 0; n < s.mesh->nodeCount(); ++n) {
        const auto& x = s.mesh->coords[size_t(n)];
        const Vec3 u = williams(x[0], x[1], k), mirror = williams(x[0], 2 * kYt - x[1], k);
        const double side = x[1] > kYt ? 1.0 : -1.0;
        for (int c = 0; c < dim; ++c) {
            if (const int d = numbering.dof(n, 0, c); d >= 0) U[size_t(d)] = u[size_t(c)];
            if (const int d = numbering.dof(n, 1, c); d >= 0)
                U[size_t(d)] = side * 0.5 * (u[size_t(c)] - mirror[size_t(c)]);
            if (const int d = numbering.tipDof(n, c); d >= 0) U[size_t(d)] = K[c];
        }
    }
    return U;
}

double work(const Scene& s, const std::shared_ptr<MechanicalLoad>& load, const Factors& k) {
    std::vector<double> f;
    assembleExternalForces(*s.space, {LoadCase{load, nullptr}}, 0.0, f);
    const auto U = exactUnknowns(s, k);
    double w = 0.0;
    for (size_t i = 0; i < f.size(); ++i) w += f[i] * U[i];
    return w;
}

std::shared_ptr<MechanicalLoad> lipPressure(const Scene& s, double p) {
    auto load = std::make_shared<MechanicalLoad>();
    LipPressure lp;
    lp.path = "PRES_REP[1]/FISSURE";
    lp.crack = s.crack;
    lp.pressure.value = p;
    load->lipPressures.push_back(lp);
    return load;
}

// Lips from x = -5 (the mesh's edge) to the front: length a = kXt + 5.
double lipWork(double p, double k1, double thickness) {
    const double a = kXt + 5;
    return p * k1 * (kKappa + 1) / kMu / std::sqrt(2 * std::numbers::pi) * (2.0 / 3.0) * std::pow(a, 1.5) * thickness;
}

TEST(XfemLipLoads, LipPressureWorkOnWilliamsFieldIsTheClosedForm) {
    const double p = 3.0e3;
    for (CellType type : {CellType::QUAD4, CellType::TRIA3, CellType::HEXA8, CellType::TETRA4}) {
        const bool plane = type == CellType::QUAD4 || type == CellType::TRIA3;
        const auto s = scene(plane ? xfemtest::square(9, type) : xfemtest::slab(9, type));
        const double exact = lipWork(p, 3.0, 1.0);
        const double w = work(s, lipPressure(s, p), {3.0, 0.0, 0.0});
        EXPECT_NEAR(w / exact, 1.0, 1e-13) << cellTypeName(type) << ": " << w << " vs " << exact;
        // Modes II and III open nothing: their work under a normal pressure vanishes.
        EXPECT_NEAR(work(s, lipPressure(s, p), {0.0, 2.0, plane ? 0.0 : 1.0}) / exact, 0.0, 1e-14)
            << cellTypeName(type);
    }
}

// Each lip, clipped at the front, is the strip -5 <= x <= kXt of the crack plane: the lip points'
// weights sum to its length (2D) or area (3D, thickness 1) on either side, so a pressure p puts the
// force p a on each lip, and the two lips' forces cancel.
TEST(XfemLipLoads, EachLipCarriesPressureTimesItsArea) {
    for (CellType type : {CellType::QUAD4, CellType::TRIA3, CellType::HEXA8, CellType::TETRA4}) {
        const bool plane = type == CellType::QUAD4 || type == CellType::TRIA3;
        const auto s = scene(plane ? xfemtest::square(9, type) : xfemtest::slab(9, type));
        std::vector<LipIntegration> lips;
        ASSERT_TRUE(s.model->enrichment->lipIntegration(*s.crack, lips));
        double upper = 0.0, lower = 0.0, xmax = -1e300;
        Vec3 resultant{};
        for (const auto& lip : lips)
            for (size_t p = 0; p < lip.weight.size(); ++p) {
                (lip.normal[p][1] < 0 ? upper : lower) += lip.weight[p];
                for (size_t c = 0; c < 3; ++c) resultant[c] += lip.weight[p] * lip.normal[p][c];
                xmax = std::max(xmax, lip.xyz[p][0]);
            }
        const double area = kXt + 5;
        EXPECT_NEAR(upper / area, 1.0, 1e-13) << cellTypeName(type);
        EXPECT_NEAR(lower / area, 1.0, 1e-13) << cellTypeName(type);
        EXPECT_LT(norm(resultant), 1e-13 * area) << cellTypeName(type);
        EXPECT_LT(xmax, kXt) << cellTypeName(type);  // no point ahead of the front
    }
}

// The slab with its face x = 5 as skin cells LD (QUAD4 on HEXA8, the tetrahedra's TRIA3 on TETRA4),
// outward normal +x.
std::shared_ptr<Mesh> slabWithRightFace(int n, CellType type) {
    auto m = xfemtest::slab(n, type);
    auto id = [&](int i, int j, int k) { return k * (n + 1) * (n + 1) + j * (n + 1) + i; };
    std::vector<int> ld;
    for (int j = 0; j < n; ++j) {
        const int a = id(n, j, 0), b = id(n, j + 1, 0), c = id(n, j + 1, 1), d = id(n, j, 1);
        if (type == CellType::HEXA8) {
            ld.push_back(m->addCell(CellType::QUAD4, std::vector<int>{a, b, c, d}));
        } else {  // the faces of the tetrahedra around the hexahedron's diagonal 0-6
            ld.push_back(m->addCell(CellType::TRIA3, std::vector<int>{a, b, c}));
            ld.push_back(m->addCell(CellType::TRIA3, std::vector<int>{a, c, d}));
        }
    }
    m->cellGroups.set("LD", ld);
    return m;
}

// PRES_REP on the edge x = 5 of the square or the face x = 5 of the slab (their nodes carry K1, K2
// [, K3]): the work equals -p int u_x dy (dz) of the exact field (20 Gauss points per cell).
TEST(XfemLipLoads, BoundaryPressureOnTipEnrichedCellsWorksOnTheExactField) {
    for (CellType type : {CellType::QUAD4, CellType::TRIA3, CellType::HEXA8, CellType::TETRA4}) {
        const bool plane = type == CellType::QUAD4 || type == CellType::TRIA3;
        const auto s = scene(plane ? xfemtest::square(9, type) : slabWithRightFace(9, type));
        auto load = std::make_shared<MechanicalLoad>();
        PressureLoad pr;
        pr.path = "PRES_REP[1]";
        pr.cells = s.mesh->cellGroups.get("LD");
        pr.value = 2.0e3;
        load->pressures.push_back(pr);
        const Factors k{3.0, 2.0, plane ? 0.0 : 1.0};
        std::vector<double> x, w;
        xfem::gaussLegendre01(20, x, w);
        double exact = 0.0;
        const double h = 10.0 / 9.0;
        for (int cell = 0; cell < 9; ++cell)
            for (size_t q = 0; q < x.size(); ++q)
                exact += -pr.value * williams(5.0, -5.0 + h * (cell + x[q]), k)[0] * w[q] * h;
        const double got = work(s, load, k);
        EXPECT_NEAR(got / exact, 1.0, 1e-10) << cellTypeName(type) << ": " << got << " vs " << exact;
    }
}

// FORCE_INTERNE f = (fx, fy[, fz]) on every cell: the work is f . int u over the mesh, the exact field
// integrated on the four rectangles around the front, each with a Gauss rule graded towards the
// front (x = xt -+ s^2, y = yt -+ t^2; 80 x 80 points, converged to 1.3e-12). Measured: 5.6e-11
// (QUAD4), 1.1e-10 (TRIA3): the elements' rules on the smooth but not polynomial tip fields away
// from the front; 1.1e-6 (HEXA8), 2.4e-7 (TETRA4): the 3D tip rule (docs/cracks.md).
double volumeWorkReference(const Factors& k, const Vec3& f) {
    std::vector<double> x, w;
    xfem::gaussLegendre01(80, x, w);
    double total = 0.0;
    for (int sx : {-1, 1})
        for (int sy : {-1, 1}) {
            const double lx = sx < 0 ? kXt + 5 : 5 - kXt, ly = sy < 0 ? kYt + 5 : 5 - kYt;
            for (size_t i = 0; i < x.size(); ++i)
                for (size_t j = 0; j < x.size(); ++j) {
                    const double px = kXt + sx * lx * x[i] * x[i], py = kYt + sy * ly * x[j] * x[j];
                    const double jac = 2 * lx * x[i] * 2 * ly * x[j];
                    const Vec3 u = williams(px, py, k);
                    total += w[i] * w[j] * jac * (f[0] * u[0] + f[1] * u[1] + f[2] * u[2]);
                }
        }
    return total;
}

TEST(XfemLipLoads, VolumeForceOnTipElementsWorksOnTheExactField) {
    const Vec3 f{700.0, -1300.0, 500.0};
    for (CellType type : {CellType::QUAD4, CellType::TRIA3, CellType::HEXA8, CellType::TETRA4}) {
        const bool plane = type == CellType::QUAD4 || type == CellType::TRIA3;
        const auto s = scene(plane ? xfemtest::square(9, type) : xfemtest::slab(9, type));
        const Factors k{3.0, 2.0, plane ? 0.0 : 1.0};
        auto load = std::make_shared<MechanicalLoad>();
        VolumeForce vf;
        vf.path = "FORCE_INTERNE[1]";
        for (const auto& e : s.model->elements) vf.cells.push_back(e.cell);
        vf.value = {f[0], f[1], plane ? 0.0 : f[2]};
        load->volumeForces.push_back(vf);
        const double exact = volumeWorkReference(k, {f[0], f[1], plane ? 0.0 : f[2]});
        const double got = work(s, load, k);
        EXPECT_NEAR(got / exact, 1.0, plane ? 1e-9 : 1e-5) << cellTypeName(type) << ": " << got << " vs " << exact;
    }
}

// A crack-tip element handed out by the Discretisation shares the stored points and psi (no copy
// per pass) and carries the Phi of the complete description (applyTipLaw on its A and B), to the
// bit, whatever the scratch held before (another tip element, a classical cell).
TEST(XfemTipElements, HandedOutWithTheStoredPointsAndTheirPhi) {
    const double lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu));
    for (CellType type : {CellType::QUAD4, CellType::HEXA8}) {
        const auto s = scene(type == CellType::QUAD4 ? xfemtest::square(5, type) : xfemtest::slab(5, type));
        ElementIntegration scratch, other, full;
        int tipElements = 0;
        for (size_t e = 0; e < s.space->elementCount(); ++e) {
            if (!s.space->isEnriched(e)) continue;
            const ElementIntegration& ei = s.space->integrationOf(e, scratch);
            if (!ei.hasTip()) continue;
            ++tipElements;
            const ElementIntegration& again = s.space->integrationOf(e, other);
            EXPECT_EQ(ei.refPoints.watch().lock(), again.refPoints.watch().lock()) << e;
            EXPECT_EQ(ei.refWeights.watch().lock(), again.refWeights.watch().lock()) << e;
            EXPECT_EQ(ei.psi.watch().lock(), again.psi.watch().lock()) << e;
            s.model->enrichment->integration(ei.cell, full);
            applyTipLaw(full, lambda, kMu);
            ASSERT_EQ(ei.refPoints.get(), full.refPoints.get()) << e;
            EXPECT_EQ(ei.refWeights.get(), full.refWeights.get()) << e;
            EXPECT_EQ(ei.pointSubcell.get(), full.pointSubcell.get()) << e;
            EXPECT_EQ(ei.psi.get(), full.psi.get()) << e;
            EXPECT_EQ(ei.tip, full.tip) << e;
            EXPECT_EQ(ei.tipPhi, full.tipPhi) << e;
            classicalIntegration(*s.mesh, ei.cell, false, other);  // the scratch reused: the stored kept
            EXPECT_EQ(s.space->integrationOf(e, scratch).refPoints.get(), full.refPoints.get()) << e;
        }
        EXPECT_GT(tipElements, 4) << cellTypeName(type);
    }
}

}  // namespace
