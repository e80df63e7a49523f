// IMPR_RESU, FORMAT='MED' (issue 3): the mesh with its groups, result fields at the selected
// orders (code_aster names: result name padded with '_' to 8 + NOM_CHAM), or a lone field.
// The first IMPR_RESU of a run on a unit creates the file; later ones on the same unit add to it,
// as code_aster does (docs/med.md). FORMAT='RESULTAT' / 'ASTER': a mesh as a .mail text
// (mesh/AsterMeshWriter), nodal fields as code_aster's listing (ImprResuListing), on the .resu
// (UNITE 8) or a unit.
#include <fmt/format.h>

#include <set>

#include "commands/ImprResuGmsh.hpp"
#include "commands/ImprResuListing.hpp"
#include "commands/TextUnit.hpp"
#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "core/Mpi.hpp"
#include "core/Units.hpp"
#include "fe/Result.hpp"
#include "med_io/MedWriter.hpp"
#include "mesh/AsterMeshWriter.hpp"
#include "parser/CommandRegistry.hpp"
#include "post/PostMessages.hpp"

namespace ma {

// NUME_ORDRE / INST of a RESU occurrence, else every step (shared with the GMSH output).
std::vector<const ResultStep*> selectedResultSteps(const Result& result, const KeywordSet& occ) {
    std::vector<const ResultStep*> steps;
    if (occ.has("NUME_ORDRE")) {
        for (auto order : occ.integers("NUME_ORDRE")) steps.push_back(&result.step(int(order)));
    } else if (occ.has("INST")) {
        const bool relative = occ.text("CRITERE") == "RELATIF";
        const double precision = occ.real("PRECISION");
        for (double inst : occ.reals("INST")) steps.push_back(&result.stepAtInst(inst, precision, relative));
    } else {
        for (const auto& s : result.steps) steps.push_back(&s);
    }
    return steps;
}

namespace {

// Files already written by IMPR_RESU in this run (process): later calls append.
std::set<std::string>& filesOfThisRun() {
    static std::set<std::string> files;
    return files;
}

std::string meshNameOf(const Mesh& mesh) { return mesh.name.empty() ? "MAILLAGE" : mesh.name; }

// A copy restricted to NOM_CMP (in the order asked); UserError when none exists.
std::shared_ptr<const NodalField> restrictComponents(const NodalField& f, const KeywordSet& occ) {
    auto out = std::make_shared<NodalField>();
    out->mesh = f.mesh;
    out->quantity = f.quantity;
    std::vector<int> keep;
    for (const auto& c : occ.texts("NOM_CMP")) {
        const int k = f.componentIndex(c);
        if (k >= 0) {
            keep.push_back(k);
            out->components.push_back(c);
        }
    }
    if (keep.empty()) throw UserError(occ.pathOf("NOM_CMP") + ": none of these components is in the field");
    const size_t nn = f.components.empty() ? 0 : f.values.size() / f.components.size();
    out->values.resize(nn * keep.size());
    out->present.resize(nn * keep.size());
    for (size_t i = 0; i < nn; ++i)
        for (size_t j = 0; j < keep.size(); ++j) {
            out->values[i * keep.size() + j] = f.at(int(i), keep[j]);
            out->present[i * keep.size() + j] = f.has(int(i), keep[j]);
        }
    return out;
}

// The same for a field at Gauss points: every point kept, the NOM_CMP columns only.
std::shared_ptr<const GaussField> restrictComponents(const GaussField& f, const KeywordSet& occ) {
    auto out = std::make_shared<GaussField>(f);
    out->components.clear();
    std::vector<size_t> keep;
    for (const auto& c : occ.texts("NOM_CMP"))
        if (const int k = f.componentIndex(c); k >= 0) {
            keep.push_back(size_t(k));
            out->components.push_back(c);
        }
    if (keep.empty()) throw UserError(occ.pathOf("NOM_CMP") + ": none of these components is in the field");
    const size_t nc = f.components.size();
    out->values.assign(size_t(f.pointCount()) * keep.size(), 0.0);
    for (size_t p = 0; p < size_t(f.pointCount()); ++p)
        for (size_t j = 0; j < keep.size(); ++j) out->values[p * keep.size() + j] = f.values[p * nc + keep[j]];
    return out;
}

void writeGauss(med::MedWriter& w, const std::string& name, const std::string& meshName, const GaussField& g,
                const KeywordSet& occ, int numdt, int numit, double dt) {
    if (occ.has("NOM_CMP")) w.writeGaussField(name, meshName, *restrictComponents(g, occ), numdt, numit, dt);
    else w.writeGaussField(name, meshName, g, numdt, numit, dt);
}

void writeNodal(med::MedWriter& w, const std::string& name, const std::string& meshName, const NodalField& f,
                const KeywordSet& occ, int numdt, int numit, double dt) {
    if (occ.has("NOM_CMP")) w.writeNodalField(name, meshName, *restrictComponents(f, occ), numdt, numit, dt);
    else w.writeNodalField(name, meshName, f, numdt, numit, dt);
}

void printResult(med::MedWriter& w, const Result& result, const KeywordSet& occ) {
    if (!result.mesh) throw UserError(occ.pathOf("RESULTAT") + ": result " + result.name + " has no mesh");
    const std::string meshName = meshNameOf(*result.mesh);
    w.writeMesh(*result.mesh, meshName);
    const bool chosen = occ.has("NOM_CHAM");
    const auto wanted = chosen ? occ.texts("NOM_CHAM") : std::vector<std::string>{};
    for (const ResultStep* step : selectedResultSteps(result, occ)) {
        std::vector<std::string> names = wanted;
        if (!chosen) {
            for (const auto& [n, f] : step->nodalFields) names.push_back(n);
            for (const auto& [n, f] : step->gaussFields) names.push_back(n);
        }
        for (const auto& nomCham : names) {
            const std::string medName = med::resultFieldName(result.name, nomCham);
            if (auto f = step->nodal(nomCham)) {
                writeNodal(w, medName, meshName, *f, occ, step->order, step->order, step->inst);
            } else if (auto g = step->gauss(nomCham)) {
                writeGauss(w, medName, meshName, *g, occ, step->order, step->order, step->inst);
            } else {
                msg().alarm(RESULT1_6, occ.path(), nomCham, step->order, result.name);
                continue;
            }
            msg().infof("    field {} (NUME_ORDRE {}, INST {}) printed as {}", nomCham, step->order, step->inst,
                        medName);
        }
    }
}

void printField(med::MedWriter& w, const ConceptPtr& field, const KeywordSet& occ) {
    if (auto f = std::dynamic_pointer_cast<NodalField>(field)) {
        if (!f->mesh) throw UserError(occ.pathOf("CHAM_GD") + ": the field has no mesh");
        const std::string meshName = meshNameOf(*f->mesh);
        w.writeMesh(*f->mesh, meshName);
        writeNodal(w, f->name, meshName, *f, occ, -1, -1, 0.0);  // MED_NO_DT, MED_NO_IT
        msg().infof("    field {} printed", f->name);
    } else if (auto g = std::dynamic_pointer_cast<GaussField>(field)) {
        if (!g->mesh) throw UserError(occ.pathOf("CHAM_GD") + ": the field has no mesh");
        const std::string meshName = meshNameOf(*g->mesh);
        w.writeMesh(*g->mesh, meshName);
        writeGauss(w, g->name, meshName, *g, occ, -1, -1, 0.0);
        msg().infof("    field {} printed", g->name);
    } else {
        throw UserError(occ.pathOf("CHAM_GD") + ": this kind of field cannot be printed in MED");
    }
}

// FORMAT='RESULTAT' (UNITE 8: the .resu) or 'ASTER': each RESU/MAILLAGE as a .mail text; with
// 'RESULTAT' the nodal fields of RESULTAT / CHAM_GD as code_aster lists them.
ConceptPtr imprResuText(const KeywordSet& kw, CommandContext& ctx) {
    const std::string format = kw.text("FORMAT");
    std::string text;
    for (const auto& occ : kw.factor("RESU")) {
        for (const char* k : {"RESULTAT", "CHAM_GD"})
            if (occ.has(k) && format == "ASTER")
                throw UserError(
                    fmt::format("{} with FORMAT='ASTER': this format prints a mesh (MAILLAGE), not "
                                "fields; print fields with FORMAT='RESULTAT', 'MED' or 'GMSH'",
                                occ.pathOf(k)));
        if (occ.has("RESULTAT") || occ.has("CHAM_GD")) text += resuListing(occ);
        if (!occ.has("MAILLAGE")) continue;
        auto mesh = occ.object<Mesh>("MAILLAGE");
        text +=
            asterMeshText(*mesh,
                          {fmt::format(" MAILLAGE {} (miniaster, IMPR_RESU FORMAT='{}')", meshNameOf(*mesh), format)});
        msg().infof("    mesh {} printed ({} nodes, {} cells)", meshNameOf(*mesh), mesh->nodeCount(),
                    mesh->cellCount());
    }
    printOnUnit("IMPR_RESU", kw.integer("UNITE"), ctx.units, text);
    return nullptr;
}

ConceptPtr imprResu(const KeywordSet& kw, CommandContext& ctx) {
    const std::string format = kw.text("FORMAT");
    if (format == "GMSH") return imprResuGmsh(kw, ctx);
    if (format == "RESULTAT" || format == "ASTER") return imprResuText(kw, ctx);
    if (format != "MED")
        throw NotImplemented("IMPR_RESU: FORMAT='" + format + "' is not supported; use FORMAT='MED' or 'GMSH'");
    for (const auto& occ : kw.factor("RESU"))  // keywords of the GMSH and RESULTAT outputs only
        for (const char* k :
             {"TYPE_CHAM", "GROUP_MA", "MAILLE", "GROUP_NO", "NOEUD", "VALE_MAX", "VALE_MIN", "BORNE_SUP", "BORNE_INF"})
            if (occ.has(k)) throw NotImplemented(occ.pathOf(k) + " is not supported by miniaster's MED output");
    if (!ctx.units) throw UserError("IMPR_RESU: no logical units are defined for this run");
    const int unit = int(kw.integer("UNITE"));
    const std::string path = ctx.units->output(unit);
    auto& written = filesOfThisRun();
    const bool append = written.count(path) > 0;
    if (!mpi::isRoot()) return nullptr;  // rank 0 writes (docs/mpi.md)

    med::MedWriter writer(path, append);
    for (const auto& occ : kw.factor("RESU")) {
        if (occ.has("MAILLAGE")) {
            auto mesh = occ.object<Mesh>("MAILLAGE");
            if (writer.writeMesh(*mesh, meshNameOf(*mesh))) msg().infof("    mesh {} printed", meshNameOf(*mesh));
            else msg().infof("    mesh {} is already in the file", meshNameOf(*mesh));
        }
        if (occ.has("RESULTAT")) printResult(writer, *occ.object<Result>("RESULTAT"), occ);
        if (occ.has("CHAM_GD")) printField(writer, occ.rawObject("CHAM_GD"), occ);
    }
    writer.commit();
    written.insert(path);
    msg().infof("    MED file {} on unit {} ({})", append ? "completed" : "written", unit, path);
    return nullptr;
}

MA_REGISTER_COMMAND("IMPR_RESU", imprResu);

}  // namespace
}  // namespace ma
