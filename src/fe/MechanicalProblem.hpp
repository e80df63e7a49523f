#pragma once
// Small-strain linear elasticity on a Model: the problem that composes the pieces of fe/ in
// deal.II step-8's shape: set up the system (Discretisation, DirichletConstraints,
// SparsityPattern), assemble it (Assembly), solve it (NewtonIncrement on the linear solver) and
// output the results (ResultFields). Shared by MECA_STATIQUE (one iteration from zero) and
// STAT_NON_LINE (increments); other engines (contact) add their terms through AdditionalTerms.
//
// Dirichlet conditions (docs/fe.md): one-term relations c*u_i = v are ELIMINATED (u_i = v/c,
// the stiffness stays symmetric positive definite, MUMPS SYM=1); relations with several terms
// are imposed with Lagrange multipliers lambda, scaled by the mean stiffness diagonal alpha:
//     [ K      alpha*C^T ] [du]   = -[ F_int(u) - F_ext + alpha*C^T*lambda ]
//     [ alpha*C    0     ] [dlam]    [ alpha*(C*u - v)                     ]
// (symmetric indefinite, MUMPS SYM=2). Enriched dofs that no element uses (psi = 0 at every
// point, xfem_spec §3.9) are set to 0 and eliminated.
#include <algorithm>
#include <memory>
#include <vector>

#include "fe/AdditionalTerms.hpp"
#include "fe/DirichletConstraints.hpp"
#include "fe/Discretisation.hpp"
#include "fe/DofNumbering.hpp"
#include "fe/LoadCase.hpp"
#include "fe/Material.hpp"
#include "fe/Model.hpp"
#include "fe/NewtonIncrement.hpp"
#include "fe/ResultFields.hpp"
#include "fields/Fields.hpp"
#include "solver/LinearSolver.hpp"
#include "solver/SparseMatrix.hpp"

namespace ma {

class MechanicalProblem {
public:
    MechanicalProblem(std::shared_ptr<const Model> model, std::shared_ptr<const MaterialField> material,
                      std::vector<LoadCase> loads, SolverOptions solver, const ExtraUnknowns& extra = {});
    ~MechanicalProblem();

    // Extension for other engines (contact): their terms join the matrix and the residual.
    // After a change of what `tangent` returns (new active set), call invalidateMatrix().
    void setAdditionalTerms(std::shared_ptr<const AdditionalTerms> terms);
    void invalidateMatrix() { matrixValid_ = false; }

    const DofNumbering& numbering() const { return space_->numbering(); }
    const Model& model() const { return space_->model(); }
    // Distributed over the processes (docs/mpi.md): whether this process computes `cell` (a model
    // cell); always true on one process.
    bool ownsCell(int cell) const;

    // State: displacement in dof order (size numbering().size()), then the additional terms'
    // own unknowns (AdditionalTerms::extraUnknowns).
    const std::vector<double>& state() const { return u_; }
    // Back to the zero state (each instant of MECA_STATIQUE is solved from zero).
    void resetState() {
        std::fill(u_.begin(), u_.end(), 0.0);
        kept_.reset();
    }

    // What follows the increment's solve. When no solve follows (MECA_STATIQUE's last instant: one
    // solve, options.maxIterations == 0), the factors are freed before the final residual, and that
    // residual's point loop can write SIEF_ELGA for stressField() (no second pass over the points).
    enum class AfterSolve { KeepFactors, ReleaseFactors, ReleaseFactorsKeepStresses };

    // Newton iterations at instant `inst` starting from the current state (ELAS: converges in
    // one iteration up to round-off). Logs every iteration.
    IncrementReport solveIncrement(double inst, const ConvergenceOptions& options,
                                   AfterSolve after = AfterSolve::KeepFactors);

    // Internal forces F_int(displacement) in dof order (numbering().size() entries).
    void internalForces(const std::vector<double>& displacement, std::vector<double>& f) const;

    std::shared_ptr<NodalField> displacementField() const;
    std::shared_ptr<GaussField> stressField() const;  // SIEF_ELGA

    // Frees the factors (MUMPS's memory) when no further solve will come; a later solve
    // factorises again.
    void releaseFactorisation();

private:
    // The constraints at `inst`; the pattern is rebuilt when their structure changed.
    void distributeCells();
    void setupSystem(double inst);
    void assembleSystem();
    void solveLinear(std::vector<double>& rhs);
    // The Newton residual's internal forces, which write SIEF_ELGA when the last solve asked for it.
    void residualForces(const std::vector<double>& displacement, std::vector<double>& f);

    std::vector<LoadCase> loads_;
    SolverOptions solverOptions_;
    std::unique_ptr<Discretisation> space_;
    std::vector<double> u_;
    std::unique_ptr<DirichletConstraints> constraints_;
    std::vector<double> lambda_;
    CsrMatrix matrix_;
    std::unique_ptr<LinearSolver> solver_;
    bool factorised_ = false;
    bool matrixValid_ = false;
    std::shared_ptr<const AdditionalTerms> additional_;
    double alpha_ = 1.0;
    AfterSolve afterSolve_ = AfterSolve::KeepFactors;
    bool keepNextStresses_ = false;
    // SIEF_ELGA written by the last residual and the state it is of; taken by stressField().
    struct KeptStresses {
        std::unique_ptr<PointFieldRecording> recording;
        std::vector<double> state;
    };
    mutable std::unique_ptr<KeptStresses> kept_;
};

}  // namespace ma
