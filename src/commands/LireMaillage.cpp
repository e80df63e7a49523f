// LIRE_MAILLAGE (commands_spec §7.7): from logical unit UNITE (default 20), FORMAT='MED' (the
// first mesh of the file or NOM_MED, docs/med.md), FORMAT='ASTER' (.mail text) or FORMAT='GMSH' (MSH 2
// text, as PRE_GMSH converts it; docs/mesh.md).
#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "core/Units.hpp"
#include "fe/CellOrientation.hpp"
#include "med_io/MedReader.hpp"
#include "mesh/AsterMeshReader.hpp"
#include "mesh/GmshMeshReader.hpp"
#include "mesh/MeshCheck.hpp"
#include "mesh/MeshConformity.hpp"
#include "mesh/MeshMessages.hpp"
#include "mesh/MeshSummary.hpp"
#include "parser/CommandRegistry.hpp"

namespace ma {
namespace {

std::shared_ptr<Mesh> readMedMesh(const KeywordSet& kw, const std::string& path, int unit, std::string& meshName) {
    const std::string nomMed = kw.has("NOM_MED") ? kw.text("NOM_MED") : std::string();  // "": the first mesh
    med::MeshReadReport report;
    auto mesh = med::readMesh(path, nomMed, &report);
    msg().infof("    mesh '{}' read from unit {} ({}), space dimension {}", report.meshName, unit, path,
                report.spaceDim);
    if (nomMed.empty() && report.meshesInFile.size() > 1)
        msg().alarm(MED_MULTI, report.meshesInFile.size(), report.meshName);
    meshName = report.meshName;
    return mesh;
}

std::shared_ptr<Mesh> readMailMesh(const std::string& path, int unit) {
    AsterMeshReport report;
    auto mesh = readAsterMesh(path, &report);
    msg().infof("    mesh read from unit {} ({}, FORMAT='ASTER'), space dimension {}", unit, path, mesh->dim);
    for (const auto& line : report.title) msg().info("    TITRE: " + line);
    for (const auto& alarm : report.alarms) msg().alarm(alarm);
    return mesh;
}

// PRE_GMSH's conversion, then the mesh as code_aster reads the .mail it writes (docs/mesh.md).
std::shared_ptr<Mesh> readMshMesh(const std::string& path, int unit) {
    auto mesh = readGmshMesh(path);
    msg().infof(
        "    mesh read from unit {} ({}, FORMAT='GMSH', MSH 2 text): {} nodes used by the elements, {} cells, "
        "{} groups GMn",
        unit, path, mesh->nodeCount(), mesh->cellCount(), mesh->cellGroups.size());
    return mesh;
}

std::string cellList(const Mesh& mesh, const std::vector<int>& cells) {
    std::string s;
    for (size_t i = 0; i < cells.size() && i < 5; ++i)
        s += (i ? ", " : "") + mesh.cellNames[size_t(cells[i])] + " (" +
             cellTypeName(mesh.cellTypes[size_t(cells[i])]) + ")";
    return cells.size() > 5 ? s + ", ..." : s;
}

// Reversed volume cells are an alarm (code_aster integrates them with |det J| and says nothing),
// distorted ones code_aster's alarm MAILLAGE1_1, degenerate ones an error before any computation.
void reportOrientation(const Mesh& mesh, const std::string& name) {
    const OrientationCensus census = orientationCensus(mesh);
    if (!census.degenerate.empty())
        throw UserError(
            fmt::format("LIRE_MAILLAGE: mesh {}: {} cell(s) are degenerate, their Jacobian round-off for their "
                        "size (coincident or aligned nodes, or non-finite coordinates): {}",
                        name, census.degenerate.size(), cellList(mesh, census.degenerate)));
    if (census.reversedCount() > 0) {
        std::string counts;
        for (const auto& [type, n] : census.reversed)
            counts +=
                fmt::format("{}{} of {} {}", counts.empty() ? "" : ", ", n, census.total.at(type), cellTypeName(type));
        msg().alarm(MAILLAGE_ORIENTATION, name, census.reversedCount(),
                    census.dimension == 3 ? "left-handed" : "clockwise", counts);
    }
    if (!census.distorted.empty())
        msg().alarm(MAILLAGE1_1, name, census.distorted.size(), cellList(mesh, census.distorted));
}

// code_aster runs a non-conforming mesh without a word; its answer is discontinuous across the
// faults, so no element passes even the patch test there (docs/mesh.md "Conformity").
void reportConformity(const Mesh& mesh, const std::string& name) {
    const ConformityReport r = meshConformity(mesh);
    if (r.overlappingFaces == 0) return;
    msg().alarm(MAILLAGE_NON_CONFORME, name, r.overlappingFaces, r.dimension, r.faultCells.size(),
                cellList(mesh, r.faultCells));
}

ConceptPtr lireMaillage(const KeywordSet& kw, CommandContext& ctx) {
    const std::string format = kw.text("FORMAT");
    if (format != "MED" && format != "ASTER" && format != "GMSH")
        throw NotImplemented("LIRE_MAILLAGE: FORMAT='" + format + "' is not supported; convert the mesh to MED");
    if (!ctx.units) throw UserError("LIRE_MAILLAGE: no logical units are defined for this run");
    const int unit = int(kw.integer("UNITE"));
    const std::string path = ctx.units->input(unit);
    std::string meshName = "MAILLAGE";
    auto mesh = format == "MED"    ? readMedMesh(kw, path, unit, meshName)
                : format == "GMSH" ? readMshMesh(path, unit)
                                   : readMailMesh(path, unit);

    checkCoordinates(*mesh, path);
    for (const auto& occ : kw.factor("VERI_MAIL")) {
        if (occ.text("VERIF") != "OUI") msg().alarm(MODELISA5_49, path);
        else
            for (const auto& defect : veriMail(*mesh, path, occ.real("APLAT"))) msg().alarm(defect);
    }

    const std::string name = ctx.resultName.empty() ? meshName : ctx.resultName;
    msg().info(meshSummary(*mesh, name));
    reportOrientation(*mesh, name);
    reportConformity(*mesh, name);
    return mesh;
}

MA_REGISTER_COMMAND("LIRE_MAILLAGE", lireMaillage);

}  // namespace
}  // namespace ma
