// POST_MAIL_XFEM / POST_CHAM_XFEM (src/xfem/Visualisation): counts, names, NFISSU on the
// interfaces, and the lip displacements of the four rigid blocks of ssnv511.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "fe/ElementKinematics.hpp"
#include "med_io/MedReader.hpp"
#include "mesh/ShapeFunctions.hpp"
#include "xfem/CellGeometry.hpp"
#include "xfem/Visualisation.hpp"
#include "xfem_test_meshes.hpp"

using namespace ma;
using namespace ma::xfem;

namespace {

int blockOf(double x, double y) { return (x > 0 ? 2 : 0) + (y < 0 ? 1 : 0); }
const std::array<double, 4> kDx{-0.25, -0.5, 0.75, 1.0};  // ssnv511a's block values

// Block of the sub-cell s of a cell (its centroid).
int subcellBlock(const XfemModel& xm, int cell, int s) {
    const CellCut* cut = xm.cut(cell);
    std::array<double, 3> bary{0, 0, 0};
    for (int v = 0; v < cut->vertexCount(); ++v)
        for (int j = 0; j < 3; ++j) bary[j] += cut->points[cut->subcells[s].vertices[v]].ref[j] / cut->vertexCount();
    std::vector<std::array<double, 3>> xs;
    for (int n : xm.mesh().cellNodes(cell)) xs.push_back(xm.mesh().coords[n]);
    const auto x = mapToPhysical(cut->type, xs, bary);
    return blockOf(x[0], x[1]);
}

// DEPL of the four rigid blocks (DX = block value, DY = 0) in the enriched basis.
std::shared_ptr<NodalField> rigidBlocks(const XfemModel& xm) {
    const Mesh& m = xm.mesh();
    auto f = std::make_shared<NodalField>();
    std::vector<std::string> comps{"DX", "DY"};
    for (int k = 1; k <= 3; ++k) comps.push_back(fmt::format("H{}X", k)), comps.push_back(fmt::format("H{}Y", k));
    f->resize(xm.meshPtr(), comps);
    for (int n = 0; n < m.nodeCount(); ++n) {
        const NodeEnrichment* e = xm.node(n);
        auto blockOfDomain = [&](const std::vector<signed char>& key) {
            for (int c : xm.cellsOfNode(n)) {
                const CellCut* cut = xm.cut(c);
                for (int s = 0; s < int(cut->subcells.size()); ++s)
                    if (!cut->skin && xm.domainKey(n, *cut, s) == key) return subcellBlock(xm, c, s);
            }
            return -1;
        };
        const double x = m.coords[n][0], y = m.coords[n][1];
        int own = blockOf(x == 0 ? 1e-9 : x, y == 0 ? 1e-9 : y);
        if (e && xm.activeSlots(n) > 0) own = blockOfDomain(e->own);
        f->set(n, 0, kDx[own]);
        f->set(n, 1, 0.0);
        for (int k = 1; k <= xm.activeSlots(n); ++k) {
            const int b = blockOfDomain(e->slotDomain[k - 1]);
            f->set(n, 2 * k, (kDx[b] - kDx[own]) / e->slotValue[k - 1]);
            f->set(n, 2 * k + 1, 0.0);
        }
    }
    return f;
}

}  // namespace

// ssnv511's three interfaces on `mesh`, its X-FEM model and POST_MAIL_XFEM's mesh.
struct VisualisedScene {
    std::shared_ptr<Model> model;
    std::shared_ptr<XfemModel> xm;
    Visualisation v;
};

VisualisedScene visualisedSsnv511(const std::shared_ptr<Mesh>& mesh) {
    auto j = xfemtest::ssnv511Cracks(mesh);
    VisualisedScene s;
    s.model = std::make_shared<Model>(xfemtest::model(mesh));
    s.xm = std::make_shared<XfemModel>(*s.model, std::vector<std::shared_ptr<const Crack>>{j.fiss1, j.fiss2, j.fiss3});
    s.model->enrichment = s.xm;
    s.v = buildVisualisation(*s.model, *s.xm);
    return s;
}

TEST(XfemVisualisation, Base36Names) {
    EXPECT_EQ(base36(1), "1");
    EXPECT_EQ(base36(10), "A");
    EXPECT_EQ(base36(35), "Z");
    EXPECT_EQ(base36(36), "10");
    EXPECT_EQ(base36(1296), "100");
}

TEST(XfemVisualisation, NamesNeverContainAnotherPrefix) {
    // 40 x 40 cells: more than 36^2 new nodes, so base-36 counters such as "NP" (853) occur.
    auto mesh = xfemtest::square(40, CellType::QUAD4);
    auto j = xfemtest::ssnv511Cracks(mesh);
    auto model = std::make_shared<Model>(xfemtest::model(mesh));
    auto xm = std::make_shared<XfemModel>(*model, std::vector<std::shared_ptr<const Crack>>{j.fiss1, j.fiss2, j.fiss3});
    const Visualisation v = buildVisualisation(*model, *xm);
    ASSERT_GT(v.mesh->nodeCount(), 1400);
    for (const auto& name : v.mesh->nodeNames) {
        if (name.rfind("N", 0) != 0 || name.size() < 3) continue;
        for (const char* p : {"NP", "NM", "NX"}) EXPECT_EQ(name.find(p, 1), std::string::npos) << name;
    }
}

TEST(XfemVisualisation, Ssnv511aMeshAndLips) {
    msg().setEcho(false);
    for (auto kind : {CellType::QUAD4, CellType::TRIA3}) {
        for (int n : {5, 6}) {
            auto mesh = xfemtest::square(n, kind);
            const auto scene = visualisedSsnv511(mesh);
            const auto& model = scene.model;
            const auto& xm = scene.xm;
            const Visualisation& v = scene.v;
            const Mesh& vm = *v.mesh;
            // Cells: the classical ones copied first, then one per sub-cell.
            int subcells = 0, classical = 0;
            for (int c = 0; c < mesh->cellCount(); ++c) {
                if (cellDimension(mesh->cellTypes[c]) != 2) continue;
                if (xm->isEnriched(c)) subcells += int(xm->cut(c)->subcells.size());
                else ++classical;
            }
            EXPECT_EQ(vm.cellCount(), classical + subcells);
            if (kind == CellType::QUAD4 && n == 5) {
                EXPECT_EQ(classical, 4);
                EXPECT_EQ(vm.cellNames[4], "MX1");
                EXPECT_EQ(vm.nodeNames[16].substr(0, 2), "NX");  // corner cells' 16 nodes are copied first
            }
            EXPECT_TRUE(vm.cellGroups.has("SURF"));
            EXPECT_EQ(vm.cellGroups.get("SURF").size(), size_t(vm.cellCount()));
            EXPECT_FALSE(vm.cellGroups.has("LG"));  // segments are not in the model
            // NFISSU: NP/NM nodes, all on an interface (x = 0 or y = 0).
            ASSERT_TRUE(vm.nodeGroups.has("NFISSU"));
            const auto& crack = vm.nodeGroups.get("NFISSU");
            EXPECT_GT(crack.size(), 10u);
            int np = 0, nm = 0;
            for (int id : crack) {
                const auto& x = vm.coords[id];
                EXPECT_TRUE(std::abs(x[0]) < 1e-12 || std::abs(x[1]) < 1e-12) << vm.nodeNames[id];
                const std::string prefix = vm.nodeNames[id].substr(0, 2);
                EXPECT_TRUE(prefix == "NP" || prefix == "NM") << vm.nodeNames[id];
                np += prefix == "NP", nm += prefix == "NM";
            }
            EXPECT_GT(np, 0);
            EXPECT_GT(nm, 0);
            // Every node name is unique.
            std::map<std::string, int> names;
            for (const auto& s : vm.nodeNames) EXPECT_EQ(names[s]++, 0) << s;

            // POST_CHAM_XFEM of the four rigid blocks: each new node has its side's value.
            Result res("evol_elas");
            res.name = "UTOT1";
            res.mesh = mesh;
            res.model = model;
            ResultStep step;
            step.order = 1;
            step.inst = 0.0;
            step.nodalFields.emplace_back("DEPL", rigidBlocks(*xm));
            // SIEF_ELGA: value = 10 * parent cell + sub-cell + 0.1 * point on X-FEM elements (the mean
            // per sub-cell is then known), 7 on classical ones.
            auto sief = std::make_shared<GaussField>();
            sief->mesh = mesh;
            sief->components = {"SIXX"};
            ElementIntegration ei;
            for (const auto& el : model->elements) {
                sief->cells.push_back(el.cell);
                const int points =
                    xm->isEnriched(el.cell) ? (xm->integration(el.cell, ei), int(ei.refPoints.size())) : 4;
                for (int p = 0; p < points; ++p) {
                    const bool x = xm->isEnriched(el.cell);
                    sief->pointCoords.push_back({0, 0, 0});
                    sief->pointWeights.push_back(1.0);
                    sief->pointSubcell.push_back(x ? ei.pointSubcell[p] : 0);
                    sief->pointRefCoords.push_back({0, 0, 0});
                    sief->values.push_back(x ? 10.0 * el.cell + ei.pointSubcell[p] + 0.1 * (p % 4) : 7.0);
                }
                sief->pointOffsets.push_back(int(sief->pointWeights.size()));
            }
            step.gaussFields.emplace_back("SIEF_ELGA", sief);
            res.steps.push_back(step);
            auto visuModel = std::make_shared<Model>(xfemtest::model(v.mesh));
            auto out = visualisationResult(res, visuModel);
            ASSERT_EQ(out->steps.size(), 1u);
            EXPECT_EQ(out->typeName(), "evol_elas");
            const auto depl = out->steps[0].nodal("DEPL");
            ASSERT_TRUE(depl);
            for (int id = 0; id < vm.nodeCount(); ++id) {
                const auto& info = v.nodes[id];
                const double expected = info.original >= 0 ? kDx[blockOf(vm.coords[id][0], vm.coords[id][1])]
                                                           : kDx[subcellBlock(*xm, info.parentCell, info.subcell)];
                EXPECT_NEAR(depl->at(id, 0), expected, 1e-14) << vm.nodeNames[id];
                EXPECT_NEAR(depl->at(id, 1), 0.0, 1e-14);
            }
            const auto sOut = out->steps[0].gauss("SIEF_ELGA");
            ASSERT_TRUE(sOut);
            EXPECT_EQ(sOut->cells.size(), size_t(vm.cellCount()));
            for (size_t e = 0; e < sOut->cells.size(); ++e) {
                const auto& info = v.cells[sOut->cells[e]];
                for (int p = sOut->pointOffsets[e]; p < sOut->pointOffsets[e + 1]; ++p) {
                    if (info.original >= 0) {
                        EXPECT_EQ(sOut->values[p], 7.0);
                    } else {
                        // FPG4 (multi) and FPG12 (mono) rules: 0.1 * mean(p % 4) = 0.15 either way.
                        EXPECT_NEAR(sOut->values[p], 10.0 * info.parentCell + info.subcell + 0.15, 1e-12);
                        EXPECT_GT(sOut->pointWeights[p], 0.0);
                    }
                }
            }
            // Zones of ssnv511 (xfem_spec §8.8): NP with x > 0.02 are on the upper lip, right half.
            for (int id : crack)
                if (vm.nodeNames[id].substr(0, 2) == "NP" && vm.coords[id][0] > 0.02) {
                    EXPECT_NEAR(depl->at(id, 0), 0.75, 1e-14) << vm.nodeNames[id];
                }
            // A model on another mesh is refused.
            EXPECT_THROW(visualisationResult(res, model), UserError);
        }
    }
}

// POST_MAIL_XFEM on code_aster's own meshes (left-handed HEXA8 in ssnv511c): the uncut cells are
// copied with their node order, every sub-cell is written positive (counter-clockwise, right-handed
// in code_aster's node order) whatever its parent's orientation, and the cells tile the domain.
TEST(XfemVisualisation, SubcellsArePositiveOnCodeAstersLeftHandedMeshes) {
    msg().setEcho(false);
    for (const char* file : {"ssnv511a.mmed", "ssnv511c.mmed", "ssnv511d.mmed"}) {
        auto mesh = med::readMesh(std::string(MINIASTER_SHARED_DIR) + "/astest/" + file);
        const auto scene = visualisedSsnv511(mesh);
        const auto& model = scene.model;
        const auto& xm = scene.xm;
        const Visualisation& v = scene.v;
        const Mesh& vm = *v.mesh;
        double total = 0.0;
        int subcells = 0;
        for (int c = 0; c < vm.cellCount(); ++c) {
            if (cellDimension(vm.cellTypes[c]) != model->dim) continue;
            std::vector<std::array<double, 3>> x;
            for (int n : vm.cellNodes(c)) x.push_back(vm.coords[n]);
            if (v.cells[c].original >= 0) {
                const auto in = mesh->cellNodes(v.cells[c].original);
                for (size_t k = 0; k < x.size(); ++k)
                    EXPECT_EQ(x[k], mesh->coords[in[k]]) << file << " " << vm.cellNames[c];
                continue;
            }
            ++subcells;
            const double measure = xfem::simplexMeasure(model->dim, x);
            EXPECT_GT(measure, 0.0) << file << " " << vm.cellNames[c];
            total += measure;
        }
        EXPECT_GT(subcells, 20) << file;
        // The X-FEM parents' measure: their elements' weights (|det J|, whatever the orientation).
        double parents = 0.0;
        for (int c : xm->xfemCells()) {
            if (cellDimension(mesh->cellTypes[c]) != model->dim) continue;
            ElementIntegration ei;
            classicalIntegration(*mesh, c, false, ei);
            PointGeometry geo;
            computePointGeometry(*mesh, c, model->dim, false, ei, geo);
            for (double w : geo.weight) parents += w;
        }
        EXPECT_NEAR(total, parents, 1e-12 * parents) << file;
    }
}
