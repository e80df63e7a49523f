// IMPR_RESU FORMAT='GMSH': result fields as gmsh views, the way code_aster's irgmsh chooses them
// (docs/visualisation.md, "IMPR_RESU FORMAT='GMSH'"). IMPR_RESU (ImprResu.cpp)
// hands the call over here.
#include "commands/ImprResuGmsh.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "core/Mpi.hpp"
#include "core/Units.hpp"
#include "fe/Result.hpp"
#include "post/GmshWriter.hpp"
#include "post/PostMessages.hpp"

namespace ma {
namespace {

using gmsh::View;
using gmsh::ViewKind;

// Files written by IMPR_RESU FORMAT='GMSH' in this run: later calls on the same unit add views.
std::set<std::string>& gmshFilesOfThisRun() {
    static std::set<std::string> files;
    return files;
}

struct ViewRequest {
    std::string typeCham;             // SCALAIRE, VECT_2D, VECT_3D, TENS_2D, TENS_3D
    std::vector<std::string> nomCmp;  // as given (may be empty)
    int version = 2;
};

// The cells written: GROUP_MA / MAILLE of the occurrence, else every cell (mesh order).
std::vector<int> selectedCells(const Mesh& mesh, const KeywordSet& occ) {
    if (!occ.has("GROUP_MA") && !occ.has("MAILLE")) {
        std::vector<int> all(size_t(mesh.cellCount()));
        for (int c = 0; c < mesh.cellCount(); ++c) all[size_t(c)] = c;
        return all;
    }
    std::vector<char> keep(size_t(mesh.cellCount()), 0);
    for (const auto& g : occ.has("GROUP_MA") ? occ.texts("GROUP_MA") : std::vector<std::string>{}) {
        for (int c : namedGroup(mesh, GroupKind::Cells, g, occ.pathOf("GROUP_MA"))) keep[size_t(c)] = 1;
    }
    for (const auto& m : occ.has("MAILLE") ? occ.texts("MAILLE") : std::vector<std::string>{}) {
        const int c = mesh.findCell(m);
        if (c < 0) throw UserError(fmt::format("{}: the mesh {} has no cell '{}'", occ.pathOf("MAILLE"), mesh.name, m));
        keep[size_t(c)] = 1;
    }
    std::vector<int> out;
    for (int c = 0; c < mesh.cellCount(); ++c)
        if (keep[size_t(c)]) out.push_back(c);
    return out;
}

size_t expectedCount(const std::string& typeCham) {
    if (typeCham == "VECT_2D") return 2;
    if (typeCham == "VECT_3D") return 3;
    if (typeCham == "TENS_2D") return 4;
    if (typeCham == "TENS_3D") return 6;
    return 0;
}

// A field at every written step, seen through one accessor per step.
struct FieldSteps {
    std::string title;  // view name prefix: <result>_<NOM_CHAM> or <field>
    std::vector<double> times;
    std::vector<std::shared_ptr<const NodalField>> nodal;  // either nodal...
    std::vector<std::shared_ptr<const GaussField>> gauss;  // ...or Gauss-point values, per step
    std::vector<std::string> components() const {
        return nodal.empty() ? gauss.front()->components : nodal.front()->components;
    }
};

// Per-node tuples of `comps` (0 where a node lacks one).
std::vector<double> nodalTuples(const NodalField& f, const std::vector<std::string>& comps, int width) {
    std::vector<double> out(size_t(f.mesh->nodeCount()) * size_t(width), 0.0);
    for (size_t j = 0; j < comps.size(); ++j) {
        const int k = f.componentIndex(comps[j]);
        if (k < 0) continue;
        for (int n = 0; n < f.mesh->nodeCount(); ++n)
            if (f.has(n, k)) out[size_t(n) * size_t(width) + j] = f.at(n, k);
    }
    return out;
}

// Per-cell mean over the Gauss points of component `comp`; `hasValues` marks the cells.
std::vector<double> cellMeans(const GaussField& g, int comp, std::vector<char>& hasValues) {
    std::vector<double> out(size_t(g.mesh->cellCount()), 0.0);
    const size_t nc = g.components.size();
    for (size_t e = 0; e < g.cells.size(); ++e) {
        const int first = g.pointOffsets[e], last = g.pointOffsets[e + 1];
        if (last == first) continue;
        double sum = 0;
        for (int p = first; p < last; ++p) sum += g.values[size_t(p) * nc + size_t(comp)];
        out[size_t(g.cells[e])] = sum / (last - first);
        hasValues[size_t(g.cells[e])] = 1;
    }
    return out;
}

View nodalView(const FieldSteps& f, const std::string& suffix, ViewKind kind, const std::vector<std::string>& comps,
               const std::vector<int>& cells) {
    View v{f.title + "_" + suffix, kind, f.times, false, {}, cells};
    for (const auto& step : f.nodal) v.steps.push_back(nodalTuples(*step, comps, v.rawComponents()));
    return v;
}

std::vector<View> nodalViews(const FieldSteps& f, const ViewRequest& r, const std::vector<int>& cells,
                             const std::string& where) {
    const auto all = f.components();
    const size_t need = expectedCount(r.typeCham);
    if (r.version == 1) {  // 1.0: TYPE_CHAM is not read
        std::vector<View> out;
        const bool displacement = std::any_of(all.begin(), all.end(),
                                              [](const std::string& c) { return c == "DX" || c == "DY" || c == "DZ"; });
        if (r.nomCmp.empty() && displacement)
            out.push_back(nodalView(f, "VECTEUR", ViewKind::Vector, {"DX", "DY", "DZ"}, cells));
        const bool others = std::any_of(all.begin(), all.end(),
                                        [](const std::string& c) { return c != "DX" && c != "DY" && c != "DZ"; });
        if (!r.nomCmp.empty() || others || !displacement)
            for (const auto& c : r.nomCmp.empty() ? all : r.nomCmp)
                out.push_back(nodalView(f, c, ViewKind::Scalar, {c}, cells));
        return out;
    }
    if (need == 0) {
        std::vector<View> out;
        for (const auto& c : r.nomCmp.empty() ? all : r.nomCmp)
            out.push_back(nodalView(f, c, ViewKind::Scalar, {c}, cells));
        return out;
    }
    if (r.nomCmp.size() != need)
        throw UserError(fmt::format("{}: TYPE_CHAM='{}' needs NOM_CMP with exactly {} components, got {}", where,
                                    r.typeCham, need, r.nomCmp.size()));
    const bool vector = r.typeCham.rfind("VECT", 0) == 0;
    return {
        nodalView(f, vector ? "VECTEUR" : "TENSEUR", vector ? ViewKind::Vector : ViewKind::Tensor, r.nomCmp, cells)};
}

// ELGA fields: scalar views of the cell means, on the selected cells that carry values.
std::vector<View> gaussViews(const FieldSteps& f, const ViewRequest& r, const std::vector<int>& cells,
                             const std::string& where) {
    if (expectedCount(r.typeCham) != 0) msg().alarm(PREPOST6_35, where, r.typeCham);
    std::vector<View> out;
    for (const auto& c : r.nomCmp.empty() ? f.components() : r.nomCmp) {
        View v{f.title + "_" + c, ViewKind::Scalar, f.times, true, {}, {}};
        std::vector<char> hasValues(size_t(f.gauss.front()->mesh->cellCount()), 0);
        for (const auto& step : f.gauss) {
            const int k = step->componentIndex(c);
            if (k < 0) throw UserError(fmt::format("{}: NOM_CMP: the field has no component {}", where, c));
            v.steps.push_back(cellMeans(*step, k, hasValues));
        }
        for (int cell : cells)
            if (hasValues[size_t(cell)]) v.cells.push_back(cell);
        out.push_back(std::move(v));
    }
    return out;
}

std::vector<View> resultViews(const Result& result, const KeywordSet& occ, const ViewRequest& r, const Mesh& mesh) {
    const auto steps = selectedResultSteps(result, occ);
    std::vector<std::string> names;
    if (occ.has("NOM_CHAM")) {
        names = occ.texts("NOM_CHAM");
    } else if (!steps.empty()) {
        for (const auto& [n, f] : steps.front()->nodalFields) names.push_back(n);
        for (const auto& [n, f] : steps.front()->gaussFields) names.push_back(n);
    }
    const auto cells = selectedCells(mesh, occ);
    std::vector<View> out;
    for (const auto& nomCham : names) {
        FieldSteps f{result.name.substr(0, 8) + "_" + nomCham, {}, {}, {}};
        for (const ResultStep* s : steps) {
            if (auto n = s->nodal(nomCham)) f.nodal.push_back(n), f.times.push_back(s->inst);
            else if (auto g = s->gauss(nomCham)) f.gauss.push_back(g), f.times.push_back(s->inst);
        }
        if (f.times.empty() || (!f.nodal.empty() && !f.gauss.empty())) {
            msg().alarm(PREPOST2_59, occ.path(), nomCham, result.name);
            continue;
        }
        auto views = f.nodal.empty() ? gaussViews(f, r, cells, occ.path()) : nodalViews(f, r, cells, occ.path());
        for (auto& v : views) out.push_back(std::move(v));
    }
    return out;
}

std::vector<View> fieldViews(const ConceptPtr& field, const KeywordSet& occ, const ViewRequest& r) {
    FieldSteps f{field->name, {0.0}, {}, {}};
    std::shared_ptr<const Mesh> mesh;
    if (auto n = std::dynamic_pointer_cast<NodalField>(field)) f.nodal.push_back(n), mesh = n->mesh;
    else if (auto g = std::dynamic_pointer_cast<GaussField>(field)) f.gauss.push_back(g), mesh = g->mesh;
    else throw UserError(occ.pathOf("CHAM_GD") + ": this kind of field cannot be printed in GMSH format");
    if (!mesh) throw UserError(occ.pathOf("CHAM_GD") + ": the field has no mesh");
    const auto cells = selectedCells(*mesh, occ);
    return f.nodal.empty() ? gaussViews(f, r, cells, occ.path()) : nodalViews(f, r, cells, occ.path());
}

std::string readExisting(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

ConceptPtr imprResuGmsh(const KeywordSet& kw, CommandContext& ctx) {
    if (!ctx.units) throw UserError("IMPR_RESU: no logical units are defined for this run");
    const double versionValue = kw.real("VERSION");
    if (versionValue != 1.0 && versionValue != 1.2)
        throw UserError(fmt::format("VERSION={}: FORMAT='GMSH' writes version 1.0 or 1.2", versionValue));
    const int version = versionValue == 1.2 ? 2 : 1;
    const int unit = int(kw.integer("UNITE"));
    const std::string path = ctx.units->output(unit);
    if (!mpi::isRoot()) return nullptr;  // rank 0 writes (docs/mpi.md)
    const bool append = gmshFilesOfThisRun().count(path) > 0;

    std::string text = append ? readExisting(path) : std::string();
    bool headerWritten = append;
    int written = 0;
    for (const auto& occ : kw.factor("RESU")) {
        if (occ.has("MAILLAGE")) {  // the mesh alone, gmsh's mesh format 1.0 (code_aster's irmgms)
            const auto mesh = occ.object<Mesh>("MAILLAGE");
            text += gmsh::meshFormat1(*mesh);
            msg().infof("    mesh {} ({} nodes, {} cells) in gmsh's mesh format 1.0", mesh->name, mesh->nodeCount(),
                        mesh->cellCount());
            if (!occ.has("RESULTAT") && !occ.has("CHAM_GD")) continue;
        }
        if (!headerWritten) text += gmsh::header(version), headerWritten = true;
        // TYPE_CHAM has no catalog default: the RESU keywords are shared with FORMAT='MED', which has
        // none; code_aster's default for GMSH is 'SCALAIRE'.
        const std::string type = occ.has("TYPE_CHAM") ? occ.text("TYPE_CHAM") : std::string("SCALAIRE");
        const ViewRequest request{type, occ.has("NOM_CMP") ? occ.texts("NOM_CMP") : std::vector<std::string>{},
                                  version};
        std::vector<View> views;
        std::shared_ptr<const Mesh> mesh;
        if (occ.has("RESULTAT")) {
            auto result = occ.object<Result>("RESULTAT");
            if (!result->mesh) throw UserError(occ.pathOf("RESULTAT") + ": result " + result->name + " has no mesh");
            mesh = result->mesh;
            views = resultViews(*result, occ, request, *mesh);
        } else {
            const ConceptPtr field = occ.rawObject("CHAM_GD");
            views = fieldViews(field, occ, request);
            if (auto n = std::dynamic_pointer_cast<NodalField>(field)) mesh = n->mesh;
            else mesh = std::dynamic_pointer_cast<GaussField>(field)->mesh;
        }
        for (const auto& v : views) {
            std::vector<CellType> skipped;
            text += gmsh::view(*mesh, v, version, &skipped);
            if (!skipped.empty())
                msg().alarm(ALGELINE_64, occ.path(), v.name, skipped.size(), cellTypeName(skipped.front()));
            msg().infof("    view {} ({} steps, {} cells)", v.name, v.times.size(), v.cells.size());
            ++written;
        }
    }
    writeFileAtomically(path, text);
    gmshFilesOfThisRun().insert(path);
    msg().infof("    GMSH file {} on unit {} ({}, {} views, version {})", append ? "completed" : "written", unit, path,
                written, version == 2 ? "1.2" : "1.0");
    return nullptr;
}

}  // namespace ma
