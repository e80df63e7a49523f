#include "fe/MechanicalProblem.hpp"
#include "fe/EquationPoints.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "core/Mpi.hpp"
#include "fe/Assembly.hpp"
#include "fe/ElementLoop.hpp"
#include "fe/ExternalForces.hpp"
#include "fe/InternalForces.hpp"
#include "fe/NearNullSpace.hpp"
#include "fe/PieceCopies.hpp"
#include "fe/ResultFields.hpp"
#include "fe/SparsityPattern.hpp"

namespace ma {

MechanicalProblem::MechanicalProblem(std::shared_ptr<const Model> model, std::shared_ptr<const MaterialField> material,
                                     std::vector<LoadCase> loads, SolverOptions solver, const ExtraUnknowns& extra)
    : loads_(std::move(loads)), solverOptions_(std::move(solver)) {
    const auto t0 = std::chrono::steady_clock::now();
    for (const auto& lc : loads_)
        if (lc.load->model && lc.load->model.get() != model.get() && lc.load->model->mesh != model->mesh)
            throw UserError("load " + lc.load->name + " is defined on another mesh than the model " + model->name);
    space_ = std::make_unique<Discretisation>(model, std::move(material), extra);
    const DofNumbering& numbering = space_->numbering();
    u_.assign(numbering.size(), 0.0);
    solverOptions_.singularHint = model->enrichment
                                      ? "a missing boundary condition (rigid body motion of a part of the model, "
                                        "e.g. a block cut off by the interfaces) or an unattached enriched dof"
                                      : "a missing boundary condition (rigid body motion: DDL_IMPO does not "
                                        "prevent every translation/rotation)";
    if (const std::string cause = degenerateMaterialCause(space_->material()); !cause.empty())
        solverOptions_.singularHint = cause + "; or else " + solverOptions_.singularHint;
    distributeCells();
    solverOptions_.nearNullSpace = [this] {
        NearNullSpace space = blockNearNullSpace(*space_, *constraints_, matrix_.rows);
        if (!space.modes.empty())
            msg().infof("    near null space: {} block(s) of the model in {} colour(s), {} rigid modes each",
                        space.blocks, space.colours, space.perBlock);
        return std::move(space.modes);
    };
    if (model->enrichment)
        solverOptions_.pieceBasis = [this] { return pieceBasisOf(*space_, *constraints_, matrix_.rows); };
    solver_ = makeLinearSolver(solverOptions_);
    int nodesWithUnknowns = 0;
    for (int node = 0; node < numbering.nodeCount(); ++node) nodesWithUnknowns += numbering.hasNode(node);
    msg().infof(
        "    model {}: {} elements, {} boundary elements, {} nodes with unknowns, {} dofs "
        "(components {}), set-up {:.3f} s",
        model->name, model->elements.size(), model->skinElements.size(), nodesWithUnknowns, numbering.size(),
        fmt::join(numbering.componentNames(), " "), secondsSince(t0));
}

MechanicalProblem::~MechanicalProblem() = default;

// With several processes and MUMPS, PETSC or GCPC, each process assembles its own cells into its
// part of the distributed matrix (docs/mpi.md). Eigen's solvers are sequential: every process then
// assembles and solves the whole system (the same on each).
void MechanicalProblem::distributeCells() {
    if (mpi::size() == 1) return;
    if (solverOptions_.method != "MUMPS" && solverOptions_.method != "PETSC" && solverOptions_.method != "GCPC") {
        msg().infof(
            "    SOLVEUR METHODE='{}' is sequential: each of the {} processes assembles and solves the whole "
            "system (METHODE='MUMPS', 'PETSC' or 'GCPC' distributes it)",
            solverOptions_.method, mpi::size());
        return;
    }
    const auto t0 = std::chrono::steady_clock::now();
    space_->distribute(mpi::size(), mpi::rank());
    solverOptions_.distributed = true;
    solverOptions_.wholePattern = [this] {
        return buildSparsityPattern(*space_, *constraints_, additional_.get(), /*allElements=*/true);
    };
    msg().infof(
        "    cells partitioned over {} processes (METIS_PartMeshDual, weighted by integration points, {:.3f} s): "
        "{} elements per process",
        mpi::size(), secondsSince(t0), fmt::join(space_->elementsPerProcess(), " "));
}

bool MechanicalProblem::ownsCell(int cell) const { return space_->ownsCell(cell); }

void MechanicalProblem::setAdditionalTerms(std::shared_ptr<const AdditionalTerms> terms) {
    additional_ = std::move(terms);
    u_.resize(numbering().size() + (additional_ ? additional_->extraUnknowns() : 0), 0.0);
    constraints_.reset();  // the pattern changes: rebuilt at the next increment
}

void MechanicalProblem::setupSystem(double inst) {
    const int extra = additional_ ? additional_->extraUnknowns() : 0;
    auto fresh = std::make_unique<DirichletConstraints>(buildDirichletConstraints(*space_, loads_, inst, extra));
    const bool rebuild = !constraints_ || !constraints_->sameStructure(*fresh);
    constraints_ = std::move(fresh);
    if (rebuild) {
        if (constraints_->unattached > 0)
            msg().infof("    {} enriched dofs used by no element are set to 0 (neutralised)", constraints_->unattached);
        matrix_ = buildSparsityPattern(*space_, *constraints_, additional_.get());
        assembleSystem();
        lambda_.assign(constraints_->multi.size(), 0.0);
    } else if (!matrixValid_) {
        assembleSystem();
    }
}

void MechanicalProblem::assembleSystem() {
    alpha_ = assembleSystemMatrix(*space_, *constraints_, additional_.get(), u_, matrix_);
    factorised_ = false;
    matrixValid_ = true;
}

void MechanicalProblem::solveLinear(std::vector<double>& rhs) {
    if (matrix_.rows == 0) {
        msg().info("    every unknown is imposed by a Dirichlet condition: nothing to solve");
        return;
    }
    if (!factorised_) {
        const bool spd = constraints_->multi.empty() && int(constraints_->eq.size()) == numbering().size();
        solver_->factorize(matrix_, spd ? MatrixKind::SymmetricPositiveDefinite : MatrixKind::SymmetricIndefinite,
                           equationPoints(*space_, *constraints_, matrix_.rows));
        factorised_ = true;
    }
    solver_->solve(rhs);
    if (afterSolve_ == AfterSolve::KeepFactors) return;
    releaseFactorisation();
    keepNextStresses_ = afterSolve_ == AfterSolve::ReleaseFactorsKeepStresses;
}

namespace {

// The fraction of the elastic force scale below which loads and reactions are the linear solver's
// noise: round-off for a factorisation; a Krylov method stops at RESI_RELA, and the reactions of its
// answer carry ~10 x that (FGMRES + LDLT_SP at 1e-12 on ssnv511a's grid at N = 1001: 1.7e-12).
double solverNoiseFloor(const SolverOptions& solver) {
    return solver.krylov() && solver.resiRela > 0.0 ? std::max(1e-12, 100.0 * solver.resiRela) : 1e-12;
}

}  // namespace

IncrementReport MechanicalProblem::solveIncrement(double inst, const ConvergenceOptions& options, AfterSolve after) {
    if (after != AfterSolve::KeepFactors && options.maxIterations != 0)
        throw std::logic_error("MechanicalProblem: the factors are freed only after an increment's one solve");
    const auto t0 = std::chrono::steady_clock::now();
    kept_.reset();
    afterSolve_ = after;
    setupSystem(inst);
    const auto& c = *constraints_;
    const int ndof = numbering().size();
    u_.resize(c.eq.size(), 0.0);  // dofs + the additional terms' unknowns
    for (int d = 0; d < ndof; ++d)
        if (c.fixed[d]) u_[d] = c.fixedValue[d];
    std::vector<double> fext;
    assembleExternalForces(*space_, loads_, inst, fext);
    const NewtonSystem system{c,
                              alpha_,
                              ndof,
                              fext,
                              [this](const std::vector<double>& u, std::vector<double>& f) { residualForces(u, f); },
                              additional_.get(),
                              [this](std::vector<double>& rhs) { solveLinear(rhs); },
                              t0,
                              space_->distributed(),
                              solverNoiseFloor(solverOptions_)};
    return newtonIterations(system, inst, options, u_, lambda_);
}

void MechanicalProblem::internalForces(const std::vector<double>& displacement, std::vector<double>& f) const {
    assembleInternalForces(*space_, displacement, f);
}

void MechanicalProblem::residualForces(const std::vector<double>& displacement, std::vector<double>& f) {
    if (!keepNextStresses_) return assembleInternalForces(*space_, displacement, f);
    keepNextStresses_ = false;
    auto recording = std::make_unique<PointFieldRecording>(*space_, PointFieldRecording::Quantity::Stress);
    assembleInternalForces(*space_, displacement, f, nullptr, &recording->writer());
    kept_ = std::make_unique<KeptStresses>(KeptStresses{std::move(recording), displacement});
}

std::shared_ptr<NodalField> MechanicalProblem::displacementField() const { return ma::displacementField(*space_, u_); }

std::shared_ptr<GaussField> MechanicalProblem::stressField() const {
    const auto kept = std::move(kept_);
    double stale = kept && kept->state == u_ ? 0.0 : 1.0;
    if (space_->distributed()) mpi::max({&stale, 1});  // the same answer on every process
    if (stale != 0.0) return ma::stressField(*space_, u_);
    return kept->recording->finish(u_);
}

void MechanicalProblem::releaseFactorisation() {
    solver_ = makeLinearSolver(solverOptions_);
    factorised_ = false;
}

}  // namespace ma
