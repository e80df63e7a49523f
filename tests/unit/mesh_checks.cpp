// LIRE_MAILLAGE's checks (mesh/MeshCheck) and the point location of JONCTION/POINT
// (mesh/PointLocation), on meshes built in memory; the same through the binary:
// tests/cli/input_checks.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "core/Error.hpp"
#include "mesh/MeshCheck.hpp"
#include "mesh/PointLocation.hpp"
#include "scenes/Ssnv511Mesh.hpp"

using namespace ma;

namespace {

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const UserError& e) { return e.what(); }
    return "no error";
}

Mesh unitSquare() {
    Mesh m;
    m.dim = 2;
    for (auto [x, y] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}) m.addNode({x, y, 0.0});
    return m;
}

}  // namespace

// Three cells on one node set, in three node orders: three pairs, named with the later cell's type.
TEST(MeshChecks, DoubleCellsAreEveryPairOnOneNodeSet) {
    Mesh m = unitSquare();
    m.addCell(CellType::QUAD4, std::vector<int>{0, 1, 2, 3});
    m.addCell(CellType::TRIA3, std::vector<int>{0, 1, 2});
    m.addCell(CellType::QUAD4, std::vector<int>{2, 3, 0, 1});
    m.addCell(CellType::QUAD4, std::vector<int>{3, 2, 1, 0});
    m.addCell(CellType::TRIA3, std::vector<int>{0, 2, 3});
    const auto alarms = veriMail(m, "f", 1e-3);
    ASSERT_EQ(alarms.size(), 1u);
    EXPECT_EQ(alarms[0].id, "MODELISA8_13");
    EXPECT_NE(alarms[0].text.find("mesh f: 3 pair(s) of cells have the same nodes (double cells): M1 and M3 (QUAD4), "
                                  "M1 and M4 (QUAD4), M3 and M4 (QUAD4);"),
              std::string::npos)
        << alarms[0].text;
}

TEST(MeshChecks, RepeatedNodeIsAnErrorAndFlatCellsAnAlarm) {
    Mesh m = unitSquare();
    m.addCell(CellType::QUAD4, std::vector<int>{0, 1, 1, 3});
    EXPECT_EQ(errorOf([&] { veriMail(m, "f", 1e-3); }),
              "mesh f: 1 cell(s) have the same node twice in their connectivity (topologically degenerate; "
              "code_aster stops on them too, MODELISA4_10): M1 (QUAD4): N2 twice");
    Mesh flat = unitSquare();
    flat.coords[2][1] = flat.coords[3][1] = 5e-4;
    flat.addCell(CellType::QUAD4, std::vector<int>{0, 1, 2, 3});
    auto alarms = veriMail(flat, "f", 1e-3);
    ASSERT_EQ(alarms.size(), 1u);
    EXPECT_EQ(alarms[0].id, "MODELISA8_15");
    EXPECT_NE(alarms[0].text.find("M1 (QUAD4) ratio 0.0005"), std::string::npos) << alarms[0].text;
    EXPECT_TRUE(veriMail(flat, "f", 1e-4).empty()) << "APLAT decides";
}

TEST(MeshChecks, CoordinatesMustBeFiniteAndInRange) {
    Mesh m = unitSquare();
    m.addCell(CellType::QUAD4, std::vector<int>{0, 1, 2, 3});
    checkCoordinates(m, "f");
    m.coords[2][0] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(errorOf([&] { checkCoordinates(m, "f"); }), "mesh f: node N3 has a non-finite coordinate: (nan, 1, 0)");
    m.coords[2][0] = -2e50;
    EXPECT_NE(errorOf([&] { checkCoordinates(m, "f"); }).find("node N3 has the coordinate -2e+50, beyond 1e+50"),
              std::string::npos);
    for (auto& x : m.coords) x = {x[0] * 1e49, x[1] * 1e49, 0.0};
    m.coords[2][0] = 1e49;
    checkCoordinates(m, "f");  // 1e49: inside the range
    for (auto& x : m.coords) x = {x[0] * 1e-100, x[1] * 1e-100, 0.0};
    EXPECT_NE(errorOf([&] { checkCoordinates(m, "f"); }).find("the mesh measures 1e-51 (largest side"),
              std::string::npos);
}

// A point inside, on the boundary and outside, on every linear cell type, with coarse and fine
// cells and away from the origin: the cell found contains it, and a linear field interpolated there
// is exact.
TEST(MeshChecks, PointLocationInterpolatesLinearFieldsExactly) {
    using Kind = Ssnv511MeshOptions::Kind;
    for (Kind kind : {Kind::Quad4, Kind::Tria3, Kind::Hexa8, Kind::Tetra4})
        for (int n : {4, 51})
            for (double shift : {0.0, 1e6}) {
                SCOPED_TRACE(testing::Message() << int(kind) << " N = " << n << " shift " << shift);
                Ssnv511MeshOptions o;
                o.kind = kind;
                o.divisions = n;
                o.offsetX = 0.3, o.offsetY = -0.2;
                o.xmin += shift, o.xmax += shift;
                const auto mesh = buildSsnv511Mesh(o);
                std::vector<double> field;
                auto exact = [&](const Vec3& x) { return 2 * (x[0] - shift) - 3 * x[1] + 0.5 * x[2] + 1; };
                for (const auto& x : mesh->coords) field.push_back(exact(x));
                const bool volume = kind == Kind::Hexa8 || kind == Kind::Tetra4;
                for (Vec3 p :
                     {Vec3{0.7, -1.3, 0.4}, Vec3{0, 5, 0}, Vec3{0, -4, 0.5}, Vec3{-5, -5, 0}, Vec3{3.3, 2.1, 1}}) {
                    p[0] += shift;
                    if (!volume) p[2] = 0;
                    const auto at = locatePoint(*mesh, p);
                    ASSERT_GE(at.cell, 0) << p[0] << " " << p[1] << " " << p[2];
                    EXPECT_EQ(cellDimension(mesh->cellTypes[size_t(at.cell)]), volume ? 3 : 2);
                    EXPECT_NEAR(interpolateAt(*mesh, at, field), exact(p), 1e-9);
                }
                EXPECT_EQ(locatePoint(*mesh, {shift, 5.001, 0}).cell, -1);
                EXPECT_EQ(locatePoint(*mesh, {shift + 6, 0, 0}).cell, -1);
                if (volume) { EXPECT_EQ(locatePoint(*mesh, {shift, 0, 1.5}).cell, -1); }
            }
}
