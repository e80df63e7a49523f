#pragma once
// Small-strain linear elasticity on a Model: assembly, Dirichlet relations, Newton iterations.
// Shared by MECA_STATIQUE (one iteration from zero) and STAT_NON_LINE (increments).
//
// Dirichlet conditions (docs/fe.md): one-term relations c*u_i = v are ELIMINATED (u_i = v/c,
// the stiffness stays symmetric positive definite, MUMPS SYM=1); relations with several terms
// are imposed with Lagrange multipliers lambda, scaled by the mean stiffness diagonal alpha:
//     [ K      alpha*C^T ] [du]   = -[ F_int(u) - F_ext + alpha*C^T*lambda ]
//     [ alpha*C    0     ] [dlam]    [ alpha*(C*u - v)                     ]
// (symmetric indefinite, MUMPS SYM=2). Enriched dofs that no element uses (psi = 0 at every
// point, xfem_spec §3.9) are set to 0 and eliminated.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/Function.hpp"
#include "fe/DofNumbering.hpp"
#include "fe/ElementIntegration.hpp"
#include "fe/Material.hpp"
#include "fe/MechanicalLoad.hpp"
#include "fe/Model.hpp"
#include "fields/Fields.hpp"
#include "solver/LinearSolver.hpp"
#include "solver/SparseMatrix.hpp"

namespace ma {

struct LoadCase {
    std::shared_ptr<const MechanicalLoad> load;
    std::shared_ptr<const Function> multiplier;  // FONC_MULT (function of INST), null = 1
};

struct ConvergenceOptions {
    int maxIterations = 10;       // ITER_GLOB_MAXI
    double resiGlobMaxi = -1.0;   // < 0: not checked
    double resiGlobRela = 1e-6;   // < 0: not checked
    bool stopOnFailure = true;    // ARRET='OUI'
};

// Terms another engine adds to the problem (contact: multipliers and their couplings). All
// indices are dofs of numbering(); the extra unknowns themselves come from ExtraUnknowns.
class AdditionalTerms {
public:
    virtual ~AdditionalTerms() = default;
    // Dof pairs (i, j) that may carry matrix entries besides the element couplings (the pattern
    // is made symmetric). Asked when the pattern is built.
    virtual void couplings(std::vector<std::pair<int, int>>& pairs) const = 0;
    // Tangent contributions at state u: add(i, j, value) (both triangles explicitly).
    virtual void tangent(const std::vector<double>& u, const std::function<void(int, int, double)>& add) const = 0;
    // Contribution to the residual R = F_int - F_ext + ... at state u.
    virtual void residual(const std::vector<double>& u, std::vector<double>& R) const = 0;
    // Unknowns of the engine itself (e.g. contact multipliers at integration points), numbered
    // after the dofs of numbering(): u and R then have numbering().size() + extraUnknowns()
    // entries. Their rows are left out of the convergence check (as code_aster skips contact
    // rows) and the matrix is treated as symmetric indefinite.
    virtual int extraUnknowns() const { return 0; }
};

struct IncrementReport {
    int iterations = 0;
    double maxResidual = 0.0;       // max_i |R_i| (RESI_GLOB_MAXI)
    double relativeResidual = 0.0;  // max_i |R_i| / max_i |B^T lambda - F_ext|_i (RESI_GLOB_RELA)
    bool converged = false;
};

class MechanicalProblem {
public:
    MechanicalProblem(std::shared_ptr<const Model> model, std::shared_ptr<const MaterialField> material,
                      std::vector<LoadCase> loads, SolverOptions solver, const ExtraUnknowns& extra = {});
    ~MechanicalProblem();

    // Extension for other engines (contact): their terms join the matrix and the residual.
    // After a change of what `tangent` returns (new active set), call invalidateMatrix().
    void setAdditionalTerms(std::shared_ptr<const AdditionalTerms> terms);
    void invalidateMatrix() { matrixValid_ = false; }

    const DofNumbering& numbering() const { return *numbering_; }
    const Model& model() const { return *model_; }

    // State: displacement in dof order (size numbering().size()), then the additional terms'
    // own unknowns (AdditionalTerms::extraUnknowns).
    std::vector<double> u;

    // Newton iterations at instant `inst` starting from the current state (ELAS: converges in
    // one iteration up to round-off). Logs every iteration.
    IncrementReport solveIncrement(double inst, const ConvergenceOptions& options);

    std::shared_ptr<NodalField> displacementField() const;
    std::shared_ptr<GaussField> stressField() const;  // SIEF_ELGA

    // Frees the factors (MUMPS's memory) when no further solve will come; a later solve
    // factorises again.
    void releaseFactorisation();

    // Element-level pieces (public for tests and for engines that add their own terms).
    void internalForces(const std::vector<double>& displacement, std::vector<double>& f) const;
    void externalForces(double inst, std::vector<double>& f) const;

private:
    struct Constraints;
    void buildConstraints(double inst, Constraints& out) const;
    void buildPattern();
    void assembleMatrix();
    double loadFactor(const LoadCase& lc, double inst) const;
    // The X-FEM description of element e when it is enriched, else its classical one (in scratch).
    const ElementIntegration& integrationOf(size_t e, ElementIntegration& scratch) const;
    bool isEnrichedElement(size_t e) const { return !enrichedIndex_.empty() && enrichedIndex_[e] >= 0; }

    std::shared_ptr<const Model> model_;
    std::shared_ptr<const MaterialField> material_;
    std::vector<LoadCase> loads_;
    SolverOptions solverOptions_;
    std::unique_ptr<DofNumbering> numbering_;
    std::vector<ElementIntegration> enrichedIntegrations_;  // X-FEM elements only
    std::vector<int> enrichedIndex_;  // element -> index in enrichedIntegrations_, -1 (empty: no X-FEM)
    std::vector<char> attached_;                              // per dof: used by some element
    std::unique_ptr<Constraints> constraints_;
    std::vector<double> lambda_;
    CsrMatrix matrix_;
    std::unique_ptr<LinearSolver> solver_;
    bool factorised_ = false;
    bool matrixValid_ = false;
    std::shared_ptr<const AdditionalTerms> additional_;
    double alpha_ = 1.0;
};

// Hooke's law in the form used by the element loops: sigma = lambdaEff*tr(eps)*I + 2*mu*eps
// in the model plane; sigma_zz from lambdaZ (D_PLAN: lambda*(eps_xx+eps_yy), C_PLAN: 0).
struct IsotropicLaw {
    double lambdaEff = 0.0, mu = 0.0, lambdaZ = 0.0;
    static IsotropicLaw from(const Material& m, Modelisation modelisation, const std::string& where);
};

}  // namespace ma
