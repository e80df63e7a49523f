#pragma once
// Keyword readers shared by the mechanics commands (AFFE_MODELE ... STAT_NON_LINE): cell and
// node selections, SOLVEUR, EXCIT. Header-only: included by src/commands files only.
#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "fe/MechanicalProblem.hpp"
#include "fe/Parallel.hpp"
#include "mesh/Mesh.hpp"
#include "parser/KeywordTree.hpp"

namespace ma::mechanics {

// Cells named by TOUT / GROUP_MA / MAILLE in one occurrence (sorted, unique). `what` describes
// the selection for messages; TOUT returns every cell of the mesh.
inline std::vector<int> selectedCells(const Mesh& mesh, const KeywordSet& occ, std::string* what = nullptr) {
    std::vector<int> cells;
    if (occ.has("TOUT")) {
        cells.resize(mesh.cellCount());
        for (int c = 0; c < mesh.cellCount(); ++c) cells[c] = c;
        if (what) *what = "TOUT='OUI'";
        return cells;
    }
    if (occ.has("GROUP_MA")) {
        for (const auto& g : occ.texts("GROUP_MA")) {
            const auto& members = namedGroup(mesh, GroupKind::Cells, g, occ.pathOf("GROUP_MA"));
            cells.insert(cells.end(), members.begin(), members.end());
        }
        if (what) *what = fmt::format("GROUP_MA={}", fmt::join(occ.texts("GROUP_MA"), ","));
    }
    if (occ.has("MAILLE")) {
        for (const auto& n : occ.texts("MAILLE")) {
            const int c = mesh.findCell(n);
            if (c < 0)
                throw UserError(fmt::format("{}: the mesh {} has no cell '{}'", occ.pathOf("MAILLE"), mesh.name, n));
            cells.push_back(c);
        }
        if (what)
            *what = fmt::format("{}{}MAILLE={}", *what, what->empty() ? "" : " ", fmt::join(occ.texts("MAILLE"), ","));
    }
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    return cells;
}

// Nodes named by TOUT / GROUP_MA / MAILLE / GROUP_NO / NOEUD (sorted, unique). TOUT means the
// nodes carrying unknowns (`modelNodes`).
inline std::vector<int> selectedNodes(const Mesh& mesh, const KeywordSet& occ, const std::vector<char>& modelNodes) {
    std::vector<int> nodes;
    if (occ.has("TOUT")) {
        for (int n = 0; n < mesh.nodeCount(); ++n)
            if (modelNodes[n]) nodes.push_back(n);
        return nodes;
    }
    if (occ.has("GROUP_MA") || occ.has("MAILLE")) {
        KeywordSet cellsOnly(occ.path());
        if (occ.has("GROUP_MA")) cellsOnly.setValues("GROUP_MA", occ.values("GROUP_MA"));
        if (occ.has("MAILLE")) cellsOnly.setValues("MAILLE", occ.values("MAILLE"));
        for (int c : selectedCells(mesh, cellsOnly))
            for (int n : mesh.cellNodes(c)) nodes.push_back(n);
    }
    if (occ.has("GROUP_NO"))
        for (const auto& g : occ.texts("GROUP_NO")) {
            const auto& members = namedGroup(mesh, GroupKind::Nodes, g, occ.pathOf("GROUP_NO"));
            nodes.insert(nodes.end(), members.begin(), members.end());
        }
    if (occ.has("NOEUD"))
        for (const auto& n : occ.texts("NOEUD")) {
            const int i = mesh.findNode(n);
            if (i < 0)
                throw UserError(fmt::format("{}: the mesh {} has no node '{}'", occ.pathOf("NOEUD"), mesh.name, n));
            nodes.push_back(i);
        }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    return nodes;
}

// SOLVEUR (a factor keyword with defaults; absent means MUMPS with its defaults).
inline SolverOptions solverOptions(const KeywordSet& kw, int info) {
    SolverOptions o;
    o.info = info;
    o.threads = workerCount();
    o.conditionEstimate = info >= 2;  // MUMPS ICNTL(11)=1 costs a few extra solves: INFO=2 only
    const auto& occ = kw.factor("SOLVEUR");
    if (occ.empty()) return o;
    const KeywordSet& s = occ.front();
    o.method = s.text("METHODE");
    // The keywords below exist (with their catalog defaults) only in the blocks of the methods
    // that have them; SolverOptions keeps its own value for the others.
    if (o.method == "MUMPS") o.renum = s.text("RENUM");  // MD/MDA/METIS/RCMK of the native solvers: Eigen uses AMD
    if (s.has("NPREC")) o.nprec = static_cast<int>(s.integer("NPREC"));
    if (s.has("TYPE_RESOL")) o.typeResol = s.text("TYPE_RESOL");
    if (o.method == "MUMPS") o.acceleration = s.text("ACCELERATION");
    if (s.has("PCENT_PIVOT")) {
        const auto& v = s.values("PCENT_PIVOT")[0];
        o.pcentPivot = std::holds_alternative<long long>(v) ? int(std::get<long long>(v)) : int(std::get<double>(v));
    }
    if (s.has("STOP_SINGULIER") && s.text("STOP_SINGULIER") == "NON") o.nprec = -1;
    if (o.krylov()) {
        o.resiRela = s.real("RESI_RELA");
        o.preconditioner = s.text("PRE_COND");
        if (o.method == "PETSC") o.algorithm = s.text("ALGORITHME"), o.petscOptions = s.text("OPTION_PETSC");
        o.maxIterations = int(s.integer("NMAX_ITER"));
        o.reacPrecond = int(s.integer("REAC_PRECOND"));
        o.fillLevel = int(s.integer("NIVE_REMPLISSAGE"));
        msg().infof("    SOLVEUR: METHODE='{}', ALGORITHME='{}', PRE_COND='{}', RESI_RELA={:g}, NMAX_ITER={}{}",
                    o.method, o.method == "GCPC" ? "CG" : o.algorithm, o.preconditioner, o.resiRela, o.maxIterations,
                    o.petscOptions.empty() ? "" : ", OPTION_PETSC='" + o.petscOptions + "'");
    }
    if (o.method == "MUMPS") {
        o.resiRela = s.real("RESI_RELA");
        o.memory = s.text("GESTION_MEMOIRE");
        if (s.has("MIXER_PRECISION")) o.mixedPrecision = s.text("MIXER_PRECISION") == "OUI";
        if (s.has("FILTRAGE_MATRICE")) o.matrixFilter = s.real("FILTRAGE_MATRICE");
        if (o.mixedPrecision || o.matrixFilter > 0.0 || o.resiRela > 0.0 || o.memory != "AUTO")
            msg().infof(
                "    SOLVEUR: MIXER_PRECISION='{}', RESI_RELA={:g}, FILTRAGE_MATRICE={:g}, GESTION_MEMOIRE='{}'",
                o.mixedPrecision ? "OUI" : "NON", o.resiRela, o.matrixFilter, o.memory);
    }
    // MUMPS pre/post-processing with code_aster's meaning (docs/fe.md, "Linear solvers"):
    // PRETRAITEMENTS='SANS' -> no scaling of the matrix; POSTTRAITEMENTS='SANS' -> no iterative
    // refinement, 'MINI' -> one step, 'AUTO' -> at most 4 (code_aster's ICNTL(10)=4), 'FORCE' -> at
    // most 10; the solver stops earlier when a step no longer halves the backward error.
    // MUMPS keywords; the other methods are scaled and refined as MUMPS is by default.
    const std::string pre = s.has("PRETRAITEMENTS") ? s.text("PRETRAITEMENTS") : "AUTO";
    const std::string post = s.has("POSTTRAITEMENTS") ? s.text("POSTTRAITEMENTS") : "AUTO";
    o.diagonalScaling = pre != "SANS";
    o.maxRefinementSteps = post == "SANS" ? 0 : post == "MINI" ? 1 : post == "FORCE" ? 10 : 4;
    msg().infof("    SOLVEUR: PRETRAITEMENTS='{}' -> {}; POSTTRAITEMENTS='{}' -> {}", pre,
                o.diagonalScaling ? "diagonal scaling D^-1/2 K D^-1/2" : "no scaling", post,
                o.maxRefinementSteps ? fmt::format("iterative refinement, at most {} step(s)", o.maxRefinementSteps)
                                     : std::string("no iterative refinement"));
    return o;
}

// EXCIT occurrences -> load cases.
inline std::vector<LoadCase> loadCases(const KeywordSet& kw) {
    std::vector<LoadCase> out;
    for (const auto& occ : kw.factor("EXCIT")) {
        LoadCase lc;
        lc.load = occ.object<MechanicalLoad>("CHARGE");
        if (occ.has("FONC_MULT")) lc.multiplier = occ.object<Function>("FONC_MULT");
        if (occ.has("COEF_MULT")) lc.coefficient = occ.real("COEF_MULT");
        out.push_back(lc);
    }
    return out;
}

}  // namespace ma::mechanics

namespace ma::mechanics {
// AFFE_CHAR_MECA (reals) and AFFE_CHAR_MECA_F (functions): defined in AffeCharMeca.cpp.
ConceptPtr buildMechanicalLoad(const KeywordSet& kw, bool functions);
}  // namespace ma::mechanics
