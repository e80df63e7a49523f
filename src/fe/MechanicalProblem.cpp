#include "fe/MechanicalProblem.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <barrier>
#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>
#include <numeric>
#include <thread>
#include <type_traits>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "fe/ClassicalElement.hpp"
#include "fe/ElementKinematics.hpp"
#include "fe/Parallel.hpp"
#include "fe/Quadrature.hpp"
#include "fe/Enrichment.hpp"

namespace ma {

namespace {

double seconds(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// CPU time of the calling thread: phase costs that do not depend on the machine's load.
double threadCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// Global dofs of the element's local unknowns (node-major, then slot, then component).
void localDofs(const Mesh& mesh, const DofNumbering& numbering, const ElementIntegration& ei, std::vector<int>& dofs) {
    const auto nodes = mesh.cellNodes(ei.cell);
    const int dim = numbering.dim();
    dofs.clear();
    for (int a = 0; a < ei.nodeCount; ++a)
        for (int k = 0; k < ei.slots[a]; ++k)
            for (int c = 0; c < dim; ++c) {
                const int d = numbering.dof(nodes[a], k, c);
                if (d < 0)
                    throw std::logic_error(fmt::format("element on cell {} uses slot {} of node {}, which the "
                                                       "enrichment does not give to the node",
                                                       mesh.cellNames[ei.cell], k, mesh.nodeNames[nodes[a]]));
                dofs.push_back(d);
            }
}

// Displacement gradient G[c][j] = du_c/dx_j at point p of an element (all slots, psi included).
void displacementGradient(const ElementIntegration& ei, const PointGeometry& geo, const std::vector<int>& dofs,
                          const std::vector<double>& u, size_t p, int dim, double G[3][3]) {
    for (int c = 0; c < 3; ++c)
        for (int j = 0; j < 3; ++j) G[c][j] = 0.0;
    const int n = ei.nodeCount;
    int i = 0;
    for (int a = 0; a < n; ++a) {
        const double* ga = &geo.gradN[(p * n + a) * 3];
        for (int k = 0; k < ei.slots[a]; ++k) {
            const double pa = ei.multiplier(int(p), a, k);
            for (int c = 0; c < dim; ++c, ++i)
                if (pa != 0.0)
                    for (int j = 0; j < dim; ++j) G[c][j] += pa * u[dofs[i]] * ga[j];
        }
    }
}

// Hooke's law of each element, recomputed only when the material or the modelisation changes
// from one element to the next (one material for the whole model is the usual case).
class LawCache {
public:
    explicit LawCache(const MaterialField& field) : field_(field) {}
    const IsotropicLaw& of(const ModelElement& element) {
        const Material& mat = field_.at(element.cell);
        if (&mat != last_ || element.modelisation != modelisation_) {
            law_ = IsotropicLaw::from(mat, element.modelisation, mat.name);
            last_ = &mat;
            modelisation_ = element.modelisation;
        }
        return law_;
    }

private:
    const MaterialField& field_;
    const Material* last_ = nullptr;
    Modelisation modelisation_ = Modelisation::D_PLAN;
    IsotropicLaw law_;
};

// Global dofs of a classical element (slot 0 of each node: first(node) + component).
template <class Ref>
void classicalDofs(const Mesh& mesh, const DofNumbering& numbering, int cell, int* dofs) {
    const int* nodes = mesh.connectivity.data() + mesh.cellOffsets[cell];
    for (int a = 0; a < Ref::nodes; ++a)
        for (int c = 0; c < Ref::dim; ++c) dofs[a * Ref::dim + c] = numbering.first(nodes[a]) + c;
}

// Displacement gradient G[c][j] = du_c/dx_j of a classical element at one point (ue: the element's
// dofs node-major) and the stress S = lambda' tr(G) I + mu (G + G^T) in the model's dimensions;
// the operations of displacementGradient and of the general loops with psi = 1.
template <int NN, int D>
void classicalGradient(const double (&grad)[NN][D], const double* ue, double G[3][3]) {
    for (int c = 0; c < 3; ++c)
        for (int j = 0; j < 3; ++j) G[c][j] = 0.0;
    for (int a = 0; a < NN; ++a)
        for (int c = 0; c < D; ++c)
            for (int j = 0; j < D; ++j) G[c][j] += ue[a * D + c] * grad[a][j];
}

template <int NN, int D>
void classicalStress(const double (&grad)[NN][D], const double* ue, const IsotropicLaw& law, double S[3][3]) {
    double G[3][3];
    classicalGradient<NN, D>(grad, ue, G);
    double tr = 0.0;
    for (int c = 0; c < D; ++c) tr += G[c][c];
    for (int c = 0; c < D; ++c)
        for (int j = 0; j < D; ++j) S[c][j] = law.mu * (G[c][j] + G[j][c]) + (c == j ? law.lambdaEff * tr : 0.0);
}

// Stiffness of a classical element (upper blocks, mirrored), row-major nd x nd. The same operations
// as generalStiffness would do with psi = 1.
template <class Ref>
void classicalStiffness(const classical::Geometry<Ref>& g, const IsotropicLaw& law, double* Ke) {
    constexpr int n = Ref::nodes, dim = Ref::dim, nd = Ref::dofs;
    for (int i = 0; i < nd * nd; ++i) Ke[i] = 0.0;
    for (int p = 0; p < Ref::points; ++p) {
        const double w = g.weight[p];
        for (int a = 0; a < n; ++a) {
            const double* ga = g.grad[p][a];
            for (int b = a; b < n; ++b) {
                const double* gb = g.grad[p][b];
                double dot = ga[0] * gb[0] + ga[1] * gb[1];
                if constexpr (dim == 3) dot += ga[2] * gb[2];
                const double wdot = w * law.mu * dot;
                for (int ci = 0; ci < dim; ++ci)
                    for (int di = 0; di < dim; ++di) {
                        const double v = w * (law.lambdaEff * ga[ci] * gb[di] + law.mu * ga[di] * gb[ci]) +
                                         (ci == di ? wdot : 0.0);
                        Ke[(a * dim + ci) * nd + b * dim + di] += v;
                    }
            }
        }
    }
    for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b)
            for (int ci = 0; ci < dim; ++ci)
                for (int di = 0; di < dim; ++di) Ke[(b * dim + di) * nd + a * dim + ci] = Ke[(a * dim + ci) * nd + b * dim + di];
}

// Stiffness of any element described by an ElementIntegration (X-FEM sub-cells, psi), nd x nd.
void generalStiffness(const ElementIntegration& ei, const PointGeometry& geo, const IsotropicLaw& law, int dim, int nd,
                      std::vector<double>& Ke) {
    const int n = ei.nodeCount;
    std::vector<int> base(n + 1, 0);  // local index of (a, slot 0)
    for (int a = 0; a < n; ++a) base[a + 1] = base[a] + ei.slots[a] * dim;
    Ke.assign(size_t(nd) * nd, 0.0);
    for (size_t p = 0; p < ei.refPoints.size(); ++p) {
        const double w = geo.weight[p];
        for (int a = 0; a < n; ++a) {
            const double* ga = &geo.gradN[(p * n + a) * 3];
            for (int k = 0; k < ei.slots[a]; ++k) {
                const double pa = ei.multiplier(int(p), a, k);
                if (pa == 0.0) continue;
                const int ia = base[a] + k * dim;
                for (int b = 0; b < n; ++b) {
                    const double* gb = &geo.gradN[(p * n + b) * 3];
                    const double dot = ga[0] * gb[0] + ga[1] * gb[1] + ga[2] * gb[2];
                    for (int l = 0; l < ei.slots[b]; ++l) {
                        const double pb = ei.multiplier(int(p), b, l);
                        if (pb == 0.0) continue;
                        const double s = w * pa * pb;
                        const int ib = base[b] + l * dim;
                        for (int ci = 0; ci < dim; ++ci)
                            for (int di = 0; di < dim; ++di)
                                Ke[size_t(ia + ci) * nd + ib + di] +=
                                    s * (law.lambdaEff * ga[ci] * gb[di] + law.mu * ga[di] * gb[ci] +
                                         (ci == di ? law.mu * dot : 0.0));
                    }
                }
            }
        }
    }
}

// Element loop on `workers` threads whose sums keep the serial order. Elements go in batches;
// phase 1: compute(e, worker) for the worker's share of the batch (e in increasing order);
// phase 2: scatter(first, count, worker) on every worker for the whole batch, each worker adding
// only into the entries it owns, in element order. A failing element stops the loop after its
// batch's phase 1; the exception of the first failing element is rethrown (what a serial loop
// reports). cpu[worker] receives each worker's CPU time.
template <class Begin, class Compute, class Scatter>
void batchedElementLoop(size_t nElements, size_t batch, int workers, std::vector<double>& cpu, Begin&& begin,
                        Compute&& compute, Scatter&& scatter) {
    cpu.assign(workers, 0.0);
    std::atomic<bool> failed{false};
    std::vector<std::pair<size_t, std::exception_ptr>> errors(workers, {SIZE_MAX, nullptr});
    std::barrier sync(workers);
    auto work = [&](int t) {
        const double cpu0 = threadCpuSeconds();
        for (size_t first = 0; first < nElements; first += batch) {
            const size_t count = std::min(batch, nElements - first);
            begin(t);
            size_t e = first + count * t / workers;
            try {
                for (; e < first + count * (t + 1) / workers; ++e) compute(e, t);
            } catch (...) {
                errors[t] = {e, std::current_exception()};
                failed = true;
            }
            sync.arrive_and_wait();
            if (failed) break;  // every worker sees the same value here
            scatter(first, count, t);
            sync.arrive_and_wait();
        }
        cpu[t] = threadCpuSeconds() - cpu0;
    };
    {
        std::vector<std::jthread> threads;
        for (int t = 1; t < workers; ++t) threads.emplace_back(work, t);
        work(0);
    }
    if (failed) {
        auto first = std::min_element(errors.begin(), errors.end(),
                                      [](const auto& a, const auto& b) { return a.first < b.first; });
        std::rethrow_exception(first->second);
    }
}

// What one worker of an element loop reuses from element to element (general path buffers, law).
struct WorkerScratch {
    explicit WorkerScratch(const MaterialField& material) : laws(material) {}
    ElementIntegration ei;
    PointGeometry geo;
    std::vector<int> dofs;
    std::vector<double> values;  // element matrix or vector
    LawCache laws;
};

// Workers for an element loop: one per 4096 elements at most (threads cost more than small loops).
constexpr size_t kElementBatch = 4096;
int elementWorkers(size_t nElements) {
    return static_cast<int>(std::min<size_t>(workerCount(), std::max<size_t>(1, nElements / kElementBatch)));
}

}  // namespace

IsotropicLaw IsotropicLaw::from(const Material& m, Modelisation modelisation, const std::string& where) {
    IsotropicLaw law;
    const double E = m.E, nu = m.nu;
    law.mu = E / (2.0 * (1.0 + nu));
    if (modelisation == Modelisation::C_PLAN) {
        law.lambdaEff = E * nu / (1.0 - nu * nu);
        law.lambdaZ = 0.0;
        return law;
    }
    if (nu >= 0.5)
        throw UserError(fmt::format("material {} has NU = {}: an incompressible material cannot be modelled "
                                    "with {} displacement elements (lambda is infinite); use NU < 0.5",
                                    where, nu, modelisationName(modelisation)));
    law.lambdaEff = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    law.lambdaZ = modelisation == Modelisation::D_PLAN ? law.lambdaEff : 0.0;
    return law;
}

struct MechanicalProblem::Constraints {
    std::vector<char> fixed;
    std::vector<double> fixedValue;
    std::vector<int> eq;  // dof -> equation (-1: eliminated)
    int freeCount = 0;
    struct Relation {
        std::vector<std::pair<int, double>> terms;  // free dofs only
        double value = 0.0;                         // right-hand side after substitution of eliminated dofs
    };
    std::vector<Relation> multi;
    int unattached = 0;

    bool sameStructure(const Constraints& o) const {
        if (fixed != o.fixed || multi.size() != o.multi.size()) return false;
        for (size_t m = 0; m < multi.size(); ++m) {
            if (multi[m].terms.size() != o.multi[m].terms.size()) return false;
            for (size_t t = 0; t < multi[m].terms.size(); ++t)
                if (multi[m].terms[t] != o.multi[m].terms[t]) return false;
        }
        return true;
    }
};

MechanicalProblem::MechanicalProblem(std::shared_ptr<const Model> model, std::shared_ptr<const MaterialField> material,
                                     std::vector<LoadCase> loads, SolverOptions solver, const ExtraUnknowns& extra)
    : model_(std::move(model)), material_(std::move(material)), loads_(std::move(loads)), solverOptions_(std::move(solver)) {
    const auto t0 = std::chrono::steady_clock::now();
    const Mesh& mesh = *model_->mesh;
    for (const auto& lc : loads_)
        if (lc.load->model && lc.load->model.get() != model_.get() && lc.load->model->mesh != model_->mesh)
            throw UserError("load " + lc.load->name + " is defined on another mesh than the model " + model_->name);
    numbering_ = std::make_unique<DofNumbering>(*model_, extra);
    u.assign(numbering_->size(), 0.0);
    attached_.assign(numbering_->size(), 0);
    // Check materials and mark the dofs each element really uses.
    std::vector<int> dofs;
    const bool enriched = model_->enrichment != nullptr;
    if (enriched) enrichedIndex_.assign(model_->elements.size(), -1);
    LawCache laws(*material_);
    for (size_t e = 0; e < model_->elements.size(); ++e) {
        const auto& element = model_->elements[e];
        (void)laws.of(element);
        if (enriched && model_->enrichment->isEnriched(element.cell)) {
            enrichedIndex_[e] = static_cast<int>(enrichedIntegrations_.size());
            model_->enrichment->integration(element.cell, enrichedIntegrations_.emplace_back());
            const auto& x = enrichedIntegrations_.back();
            localDofs(mesh, *numbering_, x, dofs);
            int i = 0;
            for (int a = 0; a < x.nodeCount; ++a)
                for (int k = 0; k < x.slots[a]; ++k) {
                    bool used = k == 0;
                    for (size_t p = 0; p < x.refPoints.size() && !used; ++p) used = x.multiplier(int(p), a, k) != 0.0;
                    for (int c = 0; c < numbering_->dim(); ++c, ++i)
                        if (used) attached_[dofs[i]] = 1;
                }
        } else {
            for (int node : mesh.cellNodes(element.cell))
                for (int c = 0; c < numbering_->dim(); ++c) attached_[numbering_->dof(node, 0, c)] = 1;
        }
    }
    solverOptions_.singularHint = enriched ? "a missing boundary condition (rigid body motion of a part of the model, "
                                             "e.g. a block cut off by the interfaces) or an unattached enriched dof"
                                           : "a missing boundary condition (rigid body motion: DDL_IMPO does not "
                                             "prevent every translation/rotation)";
    solver_ = makeLinearSolver(solverOptions_);
    int nodesWithUnknowns = 0;
    for (int node = 0; node < numbering_->nodeCount(); ++node) nodesWithUnknowns += numbering_->hasNode(node);
    msg().infof("    model {}: {} elements, {} boundary elements, {} nodes with unknowns, {} dofs "
                "(components {}), set-up {:.3f} s",
                model_->name, model_->elements.size(), model_->skinElements.size(),
                nodesWithUnknowns,
                numbering_->size(), fmt::join(numbering_->componentNames(), " "), seconds(t0));
}

MechanicalProblem::~MechanicalProblem() = default;

void MechanicalProblem::setAdditionalTerms(std::shared_ptr<const AdditionalTerms> terms) {
    additional_ = std::move(terms);
    u.resize(numbering_->size() + (additional_ ? additional_->extraUnknowns() : 0), 0.0);
    constraints_.reset();  // the pattern changes: rebuilt at the next increment
}

double MechanicalProblem::loadFactor(const LoadCase& lc, double inst) const {
    if (!lc.multiplier) return 1.0;
    return lc.multiplier->evaluateColumns({{"INST", {inst}}}, 1)[0];
}

void MechanicalProblem::buildConstraints(double inst, Constraints& out) const {
    const Mesh& mesh = *model_->mesh;
    const int ndof = numbering_->size();
    const int total = ndof + (additional_ ? additional_->extraUnknowns() : 0);
    out.fixed.assign(total, 0);
    out.fixedValue.assign(total, 0.0);
    out.multi.clear();
    std::vector<LinearRelation> relations;
    for (const auto& lc : loads_) {
        const size_t before = relations.size();
        lc.load->appendRelations(inst, relations);
        const double factor = loadFactor(lc, inst);
        for (size_t r = before; r < relations.size(); ++r) relations[r].value *= factor;
    }
    auto describe = [&](int dof) {
        return fmt::format("{} of node {}", numbering_->componentOf(dof), mesh.nodeNames[numbering_->nodeOf(dof)]);
    };
    // Inactive Heaviside slots (Enrichment::inactiveSlots, xfem_spec §3.9): fixed to 0 first, so
    // that a user condition giving them another value is reported as a conflict.
    if (model_->enrichment)
        for (const auto& [node, slot] : model_->enrichment->inactiveSlots())
            for (int comp = 0; comp < numbering_->dim(); ++comp) {
                const int d = numbering_->dof(node, slot, comp);
                if (d >= 0) out.fixed[d] = 1, out.fixedValue[d] = 0.0;
            }
    std::vector<std::pair<int, double>> terms;
    std::vector<const LinearRelation*> multiTerm;
    std::vector<std::vector<std::pair<int, double>>> multiTerms;
    for (const auto& rel : relations) {
        terms.clear();
        for (const auto& t : rel.terms) {
            const int d = numbering_->dofOf(t.node, t.component);
            if (d < 0)
                throw UserError(fmt::format("a linear relation uses {} of node {}, which the model {} does not carry",
                                            t.component, mesh.nodeNames[t.node], model_->name));
            auto it = std::find_if(terms.begin(), terms.end(), [&](const auto& p) { return p.first == d; });
            if (it == terms.end()) terms.emplace_back(d, t.coef);
            else it->second += t.coef;
        }
        std::erase_if(terms, [](const auto& p) { return p.second == 0.0; });
        if (terms.empty()) continue;
        if (terms.size() == 1) {
            const int d = terms[0].first;
            const double v = rel.value / terms[0].second;
            if (out.fixed[d] && std::abs(out.fixedValue[d] - v) > 1e-12 * std::max(std::abs(v), std::abs(out.fixedValue[d])))
                throw UserError(fmt::format("conflicting Dirichlet conditions: {} is imposed to {} and to {}", describe(d),
                                            out.fixedValue[d], v));
            out.fixed[d] = 1;
            out.fixedValue[d] = v;
        } else {
            multiTerm.push_back(&rel);
            std::sort(terms.begin(), terms.end());
            multiTerms.push_back(terms);
        }
    }
    // Enriched dofs no element uses: neutralised (value 0), as code_aster's xteddl.
    out.unattached = 0;
    for (int d = 0; d < ndof; ++d)
        if (!attached_[d] && !out.fixed[d]) {
            int slot = 0, comp = 0;
            if (parseDisplacementComponent(numbering_->componentOf(d), slot, comp) && slot > 0) {
                out.fixed[d] = 1;
                ++out.unattached;
            }
        }
    out.eq.assign(total, -1);
    out.freeCount = 0;
    for (int d = 0; d < total; ++d)
        if (!out.fixed[d]) out.eq[d] = out.freeCount++;
    for (size_t m = 0; m < multiTerm.size(); ++m) {
        Constraints::Relation r;
        r.value = multiTerm[m]->value;
        for (const auto& [d, c] : multiTerms[m]) {
            if (out.fixed[d]) r.value -= c * out.fixedValue[d];
            else r.terms.emplace_back(d, c);
        }
        if (r.terms.empty()) {
            if (std::abs(r.value) > 1e-10 * std::max(1.0, std::abs(multiTerm[m]->value)))
                throw UserError(fmt::format("a linear relation on {} contradicts the imposed values of its dofs",
                                            describe(multiTerms[m][0].first)));
            continue;
        }
        out.multi.push_back(std::move(r));
    }
}

void MechanicalProblem::buildPattern() {
    const auto t0 = std::chrono::steady_clock::now();
    const double cpu0 = threadCpuSeconds();
    const Mesh& mesh = *model_->mesh;
    const auto& c = *constraints_;
    const int nNodes = mesh.nodeCount();
    const int nEq = c.freeCount + static_cast<int>(c.multi.size());
    const int workers = workerCount();
    // Node -> elements incidence.
    std::vector<int> start(nNodes + 1, 0);
    for (const auto& e : model_->elements)
        for (int node : mesh.cellNodes(e.cell)) ++start[node + 1];
    for (int i = 0; i < nNodes; ++i) start[i + 1] += start[i];
    std::vector<int> incidence(start.back()), fill(start.begin(), start.end() - 1);
    for (size_t e = 0; e < model_->elements.size(); ++e)
        for (int node : mesh.cellNodes(model_->elements[e].cell)) incidence[fill[node]++] = static_cast<int>(e);
    fill = {};
    // Multipliers touching each dof.
    std::vector<std::vector<int>> dofMultipliers;
    if (!c.multi.empty()) {
        dofMultipliers.resize(numbering_->size());
        for (size_t m = 0; m < c.multi.size(); ++m)
            for (const auto& [d, coef] : c.multi[m].terms) dofMultipliers[d].push_back(c.freeCount + int(m));
    }
    // Couplings of the additional terms, by dof (free dofs only, as equations).
    std::vector<std::vector<int>> extraColumns;
    if (additional_) {
        std::vector<std::pair<int, int>> pairs;
        additional_->couplings(pairs);
        if (!pairs.empty()) extraColumns.resize(c.eq.size());
        for (const auto& [i, j] : pairs) {
            if (c.eq[i] < 0 || c.eq[j] < 0) continue;
            extraColumns[i].push_back(c.eq[j]);
            extraColumns[j].push_back(c.eq[i]);
        }
    }
    // Free dofs (equations) of each node, in dof order.
    std::vector<int> nodeFree(nNodes, 0);
    for (int node = 0; node < nNodes; ++node)
        for (int d = numbering_->first(node); d < numbering_->first(node + 1); ++d) nodeFree[node] += c.eq[d] >= 0;
    // Neighbour nodes of every node (itself included), sorted: one node range per worker, each
    // with its own list, so that the graph is the same for any number of workers.
    struct Graph {
        std::vector<int> offsets{0}, nodes;
    };
    std::vector<Graph> graphs(workers);
    std::vector<int> firstNode(workers + 1, nNodes);
    parallelRanges(size_t(nNodes), workers, [&](size_t begin, size_t end, int t) {
        firstNode[t] = int(begin);
        Graph& g = graphs[t];
        g.offsets.reserve(end - begin + 1);
        g.nodes.reserve((start[end] - start[begin]) * 3);
        std::vector<int> marker(nNodes, -1);  // other node -> last node that listed it
        std::vector<int> neighbours;
        for (size_t node = begin; node < end; ++node) {
            neighbours.clear();
            if (numbering_->hasNode(int(node))) {
                for (int k = start[node]; k < start[node + 1]; ++k)
                    for (int other : mesh.cellNodes(model_->elements[incidence[k]].cell))
                        if (marker[other] != int(node)) {
                            marker[other] = int(node);
                            neighbours.push_back(other);
                        }
                std::sort(neighbours.begin(), neighbours.end());
            }
            g.nodes.insert(g.nodes.end(), neighbours.begin(), neighbours.end());
            g.offsets.push_back(static_cast<int>(g.nodes.size()));
        }
    });
    auto neighboursOf = [&](int t, int node) {
        const Graph& g = graphs[t];
        const int i = node - firstNode[t];
        return std::span<const int>(g.nodes.data() + g.offsets[i], size_t(g.offsets[i + 1] - g.offsets[i]));
    };
    // Row lengths, then the columns: the rows of a node range are a contiguous range of equations.
    matrix_ = CsrMatrix{};
    matrix_.rows = nEq;
    matrix_.rowStart.assign(nEq + 1, 0);
    std::vector<int> rowColumns;
    auto specialRow = [&](int d, std::vector<int>& out, std::span<const int> neighbours) {
        // Rare rows (contact couplings): element columns, couplings and multipliers, sorted, unique.
        out.clear();
        for (int other : neighbours)
            for (int e = numbering_->first(other); e < numbering_->first(other + 1); ++e)
                if (c.eq[e] >= 0) out.push_back(c.eq[e]);
        out.insert(out.end(), extraColumns[d].begin(), extraColumns[d].end());
        if (!dofMultipliers.empty()) out.insert(out.end(), dofMultipliers[d].begin(), dofMultipliers[d].end());
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
    };
    parallelRanges(size_t(nNodes), workers, [&](size_t begin, size_t end, int t) {
        std::vector<int> special;
        for (size_t node = begin; node < end; ++node) {
            const auto neighbours = neighboursOf(t, int(node));
            long long length = 0;
            for (int other : neighbours) length += nodeFree[other];
            for (int d = numbering_->first(int(node)); d < numbering_->first(int(node) + 1); ++d) {
                const int row = c.eq[d];
                if (row < 0) continue;
                if (!extraColumns.empty() && !extraColumns[d].empty()) {
                    specialRow(d, special, neighbours);
                    matrix_.rowStart[row + 1] = static_cast<long long>(special.size());
                } else {
                    matrix_.rowStart[row + 1] = length + (dofMultipliers.empty() ? 0 : long(dofMultipliers[d].size()));
                }
            }
        }
    });
    // Rows of the additional terms' own unknowns: their declared couplings only.
    auto ownRow = [&](int d, std::vector<int>& out) {
        out.clear();
        if (!extraColumns.empty()) out = extraColumns[d];
        out.push_back(c.eq[d]);
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
    };
    for (int d = numbering_->size(); d < int(c.eq.size()); ++d)
        if (c.eq[d] >= 0) {
            ownRow(d, rowColumns);
            matrix_.rowStart[c.eq[d] + 1] = static_cast<long long>(rowColumns.size());
        }
    for (size_t m = 0; m < c.multi.size(); ++m)
        matrix_.rowStart[c.freeCount + int(m) + 1] = static_cast<long long>(c.multi[m].terms.size());
    for (int i = 0; i < nEq; ++i) matrix_.rowStart[i + 1] += matrix_.rowStart[i];
    matrix_.cols.resize(matrix_.rowStart.back());
    parallelRanges(size_t(nNodes), workers, [&](size_t begin, size_t end, int t) {
        std::vector<int> special;
        for (size_t node = begin; node < end; ++node) {
            const auto neighbours = neighboursOf(t, int(node));
            for (int d = numbering_->first(int(node)); d < numbering_->first(int(node) + 1); ++d) {
                const int row = c.eq[d];
                if (row < 0) continue;
                int* out = matrix_.cols.data() + matrix_.rowStart[row];
                if (!extraColumns.empty() && !extraColumns[d].empty()) {
                    specialRow(d, special, neighbours);
                    std::copy(special.begin(), special.end(), out);
                    continue;
                }
                for (int other : neighbours)
                    for (int e = numbering_->first(other); e < numbering_->first(other + 1); ++e)
                        if (c.eq[e] >= 0) *out++ = c.eq[e];
                // Multiplier equations come after every dof equation: the row stays sorted.
                if (!dofMultipliers.empty()) std::copy(dofMultipliers[d].begin(), dofMultipliers[d].end(), out);
            }
        }
    });
    for (int d = numbering_->size(); d < int(c.eq.size()); ++d)
        if (c.eq[d] >= 0) {
            ownRow(d, rowColumns);
            std::copy(rowColumns.begin(), rowColumns.end(), matrix_.cols.begin() + matrix_.rowStart[c.eq[d]]);
        }
    for (size_t m = 0; m < c.multi.size(); ++m) {
        const int row = c.freeCount + int(m);
        auto out = matrix_.cols.begin() + matrix_.rowStart[row];
        for (const auto& [d, coef] : c.multi[m].terms) *out++ = c.eq[d];
        std::sort(matrix_.cols.begin() + matrix_.rowStart[row], matrix_.cols.begin() + matrix_.rowStart[row + 1]);
    }
    // matrix_.values: allocated (and zeroed) by the first assembly.
    msg().infof("    matrix pattern: {} equations ({} free dofs, {} eliminated, {} multipliers), {} non-zeros, "
                "{:.3f} s (cpu {:.3f} s)",
                nEq, c.freeCount, static_cast<int>(c.eq.size()) - c.freeCount, c.multi.size(), matrix_.nonZeros(), seconds(t0),
                threadCpuSeconds() - cpu0);
}

void MechanicalProblem::assembleMatrix() {
    const auto t0 = std::chrono::steady_clock::now();
    const Mesh& mesh = *model_->mesh;
    const auto& c = *constraints_;
    const int dim = numbering_->dim();
    if (matrix_.values.size() != matrix_.cols.size()) matrix_.values.assign(matrix_.cols.size(), 0.0);
    else matrix_.setZero();
    // Phase 1: each worker computes the matrices of its share of the batch (with their equations,
    // sorted). Phase 2: each worker adds the whole batch, in element order, into the rows it owns
    // (blocks of 64 equations dealt in turn). Every matrix entry thus receives its element
    // contributions in element order whatever the number of workers: the same bits.
    const size_t nElements = model_->elements.size();
    const int workers = elementWorkers(nElements);
    struct Part {  // one worker's element matrices of the current batch
        std::vector<int> rows, local;  // per element: m (equation, local index), sorted
        std::vector<double> Ke;
    };
    struct Entry {
        int part = 0, nd = 0, m = 0;
        size_t Ke = 0, rows = 0;
    };
    std::vector<Part> parts(workers);
    std::vector<Entry> entries(kElementBatch);
    std::vector<WorkerScratch> scratch;
    for (int t = 0; t < workers; ++t) scratch.emplace_back(*material_);
    auto keep = [&](int t, size_t slot, const int* edofs, int nd, const double* eK) {
        Part& part = parts[t];
        Entry& entry = entries[slot];
        entry.part = t, entry.nd = nd;
        entry.Ke = part.Ke.size(), entry.rows = part.rows.size();
        part.Ke.insert(part.Ke.end(), eK, eK + size_t(nd) * nd);
        int m = 0;
        for (int j = 0; j < nd; ++j) {
            const int row = c.eq[edofs[j]];
            if (row < 0) continue;
            part.rows.push_back(row), part.local.push_back(j);
            for (size_t i = part.rows.size() - 1; i > entry.rows && part.rows[i - 1] > row; --i) {  // insertion sort
                std::swap(part.rows[i - 1], part.rows[i]);
                std::swap(part.local[i - 1], part.local[i]);
            }
            ++m;
        }
        entry.m = m;
    };
    std::vector<double> cpu;
    batchedElementLoop(
        nElements, kElementBatch, workers, cpu,
        [&](int t) { parts[t].rows.clear(), parts[t].local.clear(), parts[t].Ke.clear(); },
        [&](size_t e, int t) {
            WorkerScratch& w = scratch[t];
            const auto& element = model_->elements[e];
            const IsotropicLaw& law = w.laws.of(element);
            const size_t slot = e % kElementBatch;
            const bool fixedSize =
                !isEnrichedElement(e) && classical::dispatch(mesh.cellTypes[element.cell], dim, [&](const auto& ref) {
                    using Ref = std::decay_t<decltype(ref)>;
                    classical::Geometry<Ref> g;
                    classical::computeGeometry(ref, mesh, element.cell, g);
                    int edofs[Ref::dofs];
                    double eK[Ref::dofs * Ref::dofs];
                    classicalDofs<Ref>(mesh, *numbering_, element.cell, edofs);
                    classicalStiffness(g, law, eK);
                    keep(t, slot, edofs, Ref::dofs, eK);
                });
            if (fixedSize) return;
            const ElementIntegration* ei = &integrationOf(e, w.ei);
            computePointGeometry(mesh, element.cell, dim, false, *ei, w.geo);
            localDofs(mesh, *numbering_, *ei, w.dofs);
            generalStiffness(*ei, w.geo, law, dim, static_cast<int>(w.dofs.size()), w.values);
            keep(t, slot, w.dofs.data(), static_cast<int>(w.dofs.size()), w.values.data());
        },
        [&](size_t, size_t count, int t) {
            const int* cols = matrix_.cols.data();
            double* values = matrix_.values.data();
            for (size_t slot = 0; slot < count; ++slot) {
                const Entry& entry = entries[slot];
                const Part& p = parts[entry.part];
                const int* rows = p.rows.data() + entry.rows;
                const int* local = p.local.data() + entry.rows;
                const double* eK = p.Ke.data() + entry.Ke;
                for (int i = 0; i < entry.m; ++i) {
                    if ((rows[i] >> 6) % workers != t) continue;
                    long long k = matrix_.rowStart[rows[i]];
                    const double* Kr = eK + size_t(local[i]) * entry.nd;
                    for (int j = 0; j < entry.m; ++j) {
                        while (cols[k] < rows[j]) ++k;
                        values[k] += Kr[local[j]];
                    }
                }
            }
        });
    if (additional_)
        additional_->tangent(u, [&](int i, int j, double v) {
            const int row = c.eq[i], col = c.eq[j];
            if (row < 0 || col < 0) return;
            const long long k = matrix_.find(row, col);
            if (k < 0)
                throw std::logic_error(fmt::format("additional term ({}, {}) outside the declared couplings", i, j));
            matrix_.values[k] += v;
        });
    // Multiplier scaling: the mean stiffness diagonal, so that the constraint rows are of the same
    // magnitude as the stiffness rows.
    double sum = 0.0;
    for (int i = 0; i < c.freeCount; ++i) {
        const long long k = matrix_.find(i, i);
        if (k >= 0) sum += std::abs(matrix_.values[k]);
    }
    alpha_ = c.freeCount > 0 && sum > 0.0 ? sum / c.freeCount : 1.0;
    for (size_t m = 0; m < c.multi.size(); ++m) {
        const int row = c.freeCount + int(m);
        for (const auto& [d, coef] : c.multi[m].terms) {
            matrix_.values[matrix_.find(row, c.eq[d])] += alpha_ * coef;
            matrix_.values[matrix_.find(c.eq[d], row)] += alpha_ * coef;
        }
    }
    factorised_ = false;
    matrixValid_ = true;
    const double cpuTotal = std::accumulate(cpu.begin(), cpu.end(), 0.0);
    msg().infof("    stiffness assembled: {} elements, {:.3f} s (cpu {:.3f} s, {:.3f} us per dof, {} thread(s)){}",
                model_->elements.size(), seconds(t0), cpuTotal, 1e6 * cpuTotal / std::max(1, numbering_->size()), workers,
                c.multi.empty() ? "" : fmt::format(", multiplier scaling {:.3e}", alpha_));
}

const ElementIntegration& MechanicalProblem::integrationOf(size_t e, ElementIntegration& scratch) const {
    if (isEnrichedElement(e)) return enrichedIntegrations_[enrichedIndex_[e]];
    classicalIntegration(*model_->mesh, model_->elements[e].cell, false, scratch);
    return scratch;
}

void MechanicalProblem::internalForces(const std::vector<double>& disp, std::vector<double>& f) const {
    const Mesh& mesh = *model_->mesh;
    const int dim = numbering_->dim();
    f.assign(numbering_->size(), 0.0);
    // Element vectors of a batch computed on the workers, then added in element order by the worker
    // owning each block of 64 dofs: the sums of the serial loop, bit for bit.
    const size_t nElements = model_->elements.size();
    const int workers = elementWorkers(nElements);
    struct Part {
        std::vector<int> dofs;
        std::vector<double> fe;
    };
    struct Entry {
        int part = 0, nd = 0;
        size_t offset = 0;
    };
    std::vector<Part> parts(workers);
    std::vector<Entry> entries(kElementBatch);
    std::vector<WorkerScratch> scratch;
    for (int t = 0; t < workers; ++t) scratch.emplace_back(*material_);
    auto keep = [&](int t, size_t e, const int* dofs, const double* fe, int nd) {
        Part& part = parts[t];
        entries[e % kElementBatch] = {t, nd, part.dofs.size()};
        part.dofs.insert(part.dofs.end(), dofs, dofs + nd);
        part.fe.insert(part.fe.end(), fe, fe + nd);
    };
    std::vector<double> cpu;
    batchedElementLoop(
        nElements, kElementBatch, workers, cpu, [&](int t) { parts[t].dofs.clear(), parts[t].fe.clear(); },
        [&](size_t e, int t) {
            WorkerScratch& w = scratch[t];
            const auto& element = model_->elements[e];
            const IsotropicLaw& law = w.laws.of(element);
            const bool fixedSize =
                !isEnrichedElement(e) && classical::dispatch(mesh.cellTypes[element.cell], dim, [&](const auto& ref) {
                    using Ref = std::decay_t<decltype(ref)>;
                    classical::Geometry<Ref> g;
                    classical::computeGeometry(ref, mesh, element.cell, g);
                    int edofs[Ref::dofs];
                    classicalDofs<Ref>(mesh, *numbering_, element.cell, edofs);
                    double ue[Ref::dofs], fl[Ref::dofs] = {};
                    for (int i = 0; i < Ref::dofs; ++i) ue[i] = disp[edofs[i]];
                    for (int p = 0; p < Ref::points; ++p) {
                        double S[3][3];
                        classicalStress(g.grad[p], ue, law, S);
                        const double wp = g.weight[p];
                        for (int a = 0; a < Ref::nodes; ++a)
                            for (int c = 0; c < Ref::dim; ++c) {
                                double sum = 0.0;
                                for (int j = 0; j < Ref::dim; ++j) sum += S[c][j] * g.grad[p][a][j];
                                fl[a * Ref::dim + c] += wp * sum;
                            }
                    }
                    keep(t, e, edofs, fl, Ref::dofs);
                });
            if (fixedSize) return;
            const ElementIntegration* ei = &integrationOf(e, w.ei);
            computePointGeometry(mesh, element.cell, dim, false, *ei, w.geo);
            localDofs(mesh, *numbering_, *ei, w.dofs);
            w.values.assign(w.dofs.size(), 0.0);
            const int n = ei->nodeCount;
            for (size_t p = 0; p < ei->refPoints.size(); ++p) {
                double G[3][3];  // G[c][j] = du_c/dx_j
                displacementGradient(*ei, w.geo, w.dofs, disp, p, dim, G);
                double tr = 0.0;
                for (int c = 0; c < dim; ++c) tr += G[c][c];
                double S[3][3];
                for (int c = 0; c < dim; ++c)
                    for (int j = 0; j < dim; ++j)
                        S[c][j] = law.mu * (G[c][j] + G[j][c]) + (c == j ? law.lambdaEff * tr : 0.0);
                const double wp = w.geo.weight[p];
                int i = 0;
                for (int a = 0; a < n; ++a) {
                    const double* ga = &w.geo.gradN[(p * n + a) * 3];
                    for (int k = 0; k < ei->slots[a]; ++k) {
                        const double pa = ei->multiplier(int(p), a, k);
                        for (int c = 0; c < dim; ++c, ++i) {
                            double sum = 0.0;
                            for (int j = 0; j < dim; ++j) sum += S[c][j] * ga[j];
                            w.values[i] += wp * pa * sum;
                        }
                    }
                }
            }
            keep(t, e, w.dofs.data(), w.values.data(), static_cast<int>(w.dofs.size()));
        },
        [&](size_t, size_t count, int t) {
            for (size_t slot = 0; slot < count; ++slot) {
                const Entry& entry = entries[slot];
                const int* dofs = parts[entry.part].dofs.data() + entry.offset;
                const double* fe = parts[entry.part].fe.data() + entry.offset;
                for (int i = 0; i < entry.nd; ++i)
                    if ((dofs[i] >> 6) % workers == t) f[dofs[i]] += fe[i];
            }
        });
}

void MechanicalProblem::externalForces(double inst, std::vector<double>& f) const {
    const Mesh& mesh = *model_->mesh;
    const int dim = numbering_->dim();
    f.assign(numbering_->size(), 0.0);
    ElementIntegration ei;
    PointGeometry geo;
    std::vector<int> dofs;
    // Distributes a force density given at the points of each cell (two passes when the density is
    // a function: collect the points, evaluate in one batch, then integrate).
    auto distribute = [&](const std::vector<int>& cells, bool boundary, auto&& density) {
        for (int cell : cells) {
            elementIntegration(*model_, cell, boundary, ei);
            computePointGeometry(mesh, cell, dim, boundary, ei, geo);
            localDofs(mesh, *numbering_, ei, dofs);
            const int n = ei.nodeCount;
            for (size_t p = 0; p < ei.refPoints.size(); ++p) {
                const std::array<double, 3> t = density(p, geo);
                const double w = geo.weight[p];
                int i = 0;
                for (int a = 0; a < n; ++a) {
                    const double Na = geo.N[p * n + a];
                    for (int k = 0; k < ei.slots[a]; ++k) {
                        const double pa = ei.multiplier(int(p), a, k);
                        for (int c = 0; c < dim; ++c, ++i) f[dofs[i]] += w * pa * Na * t[c];
                    }
                }
            }
        }
    };
    auto pointsOf = [&](const std::vector<int>& cells, bool boundary) {
        std::vector<std::array<double, 3>> pts;
        for (int cell : cells) {
            elementIntegration(*model_, cell, boundary, ei);
            computePointGeometry(mesh, cell, dim, boundary, ei, geo);
            pts.insert(pts.end(), geo.xyz.begin(), geo.xyz.end());
        }
        return pts;
    };
    for (const auto& lc : loads_) {
        const double factor = loadFactor(lc, inst);
        if (factor == 0.0) continue;
        for (const auto& pr : lc.load->pressures) {
            std::vector<double> values;
            if (pr.function) values = evaluateAtPoints(*pr.function, pointsOf(pr.cells, true), inst);
            size_t next = 0;
            distribute(pr.cells, true, [&](size_t p, const PointGeometry& g) {
                const double pres = factor * (pr.function ? values[next++] : pr.value);
                return std::array<double, 3>{-pres * g.normal[p][0], -pres * g.normal[p][1], -pres * g.normal[p][2]};
            });
        }
        for (const auto& vf : lc.load->volumeForces) {
            std::array<std::vector<double>, 3> values;
            const bool anyFunction = vf.function[0] || vf.function[1] || vf.function[2];
            if (anyFunction) {
                const auto pts = pointsOf(vf.cells, false);
                for (int c = 0; c < 3; ++c)
                    if (vf.function[c]) values[c] = evaluateAtPoints(*vf.function[c], pts, inst);
            }
            size_t next = 0;
            distribute(vf.cells, false, [&](size_t, const PointGeometry&) {
                std::array<double, 3> t{};
                for (int c = 0; c < 3; ++c) t[c] = factor * (vf.function[c] ? values[c][next] : vf.value[c]);
                ++next;
                return t;
            });
        }
    }
}

IncrementReport MechanicalProblem::solveIncrement(double inst, const ConvergenceOptions& options) {
    const auto t0 = std::chrono::steady_clock::now();
    auto fresh = std::make_unique<Constraints>();
    buildConstraints(inst, *fresh);
    const bool rebuild = !constraints_ || !constraints_->sameStructure(*fresh);
    constraints_ = std::move(fresh);
    auto& c = *constraints_;
    if (rebuild) {
        if (c.unattached > 0)
            msg().infof("    {} enriched dofs used by no element are set to 0 (neutralised)", c.unattached);
        buildPattern();
        assembleMatrix();
        lambda_.assign(c.multi.size(), 0.0);
    } else if (!matrixValid_) {
        assembleMatrix();
    }
    const int ndof = numbering_->size();
    const int total = static_cast<int>(c.eq.size());  // dofs + the additional terms' unknowns
    u.resize(total, 0.0);
    for (int d = 0; d < ndof; ++d)
        if (c.fixed[d]) u[d] = c.fixedValue[d];
    std::vector<double> fext, fint, rhs(matrix_.rows);
    externalForces(inst, fext);
    IncrementReport report;
    auto residual = [&](std::vector<double>& R) {
        internalForces(u, fint);
        R.assign(total, 0.0);
        for (int d = 0; d < ndof; ++d) R[d] = fint[d] - fext[d];
        for (size_t m = 0; m < c.multi.size(); ++m)
            for (const auto& [d, coef] : c.multi[m].terms) R[d] += alpha_ * coef * lambda_[m];
        if (additional_) additional_->residual(u, R);
    };
    std::vector<double> R;
    bool zeroLoadNoted = false;
    for (int it = 0; it <= options.maxIterations; ++it) {
        residual(R);
        for (int d = 0; d < total; ++d)
            if (c.eq[d] >= 0) rhs[c.eq[d]] = -R[d];
        for (size_t m = 0; m < c.multi.size(); ++m) {
            double g = -c.multi[m].value;
            for (const auto& [d, coef] : c.multi[m].terms) g += coef * u[d];
            rhs[c.freeCount + m] = -alpha_ * g;
        }
        if (matrix_.rows == 0) {
            msg().info("    every unknown is imposed by a Dirichlet condition: nothing to solve");
        } else {
            if (!factorised_) {
                solver_->factorize(matrix_, c.multi.empty() && total == ndof ? MatrixKind::SymmetricPositiveDefinite
                                                                             : MatrixKind::SymmetricIndefinite);
                factorised_ = true;
            }
            solver_->solve(rhs);
        }
        for (int d = 0; d < total; ++d)
            if (c.eq[d] >= 0) u[d] += rhs[c.eq[d]];
        for (size_t m = 0; m < c.multi.size(); ++m) lambda_[m] += rhs[c.freeCount + m];
        // Convergence (code_aster's nmresi): max |R| over the equations, relative to the largest
        // of the external forces and reactions.
        residual(R);
        double maxR = 0.0, denominator = 0.0;
        std::vector<double> reaction(ndof, 0.0);
        for (size_t m = 0; m < c.multi.size(); ++m)
            for (const auto& [d, coef] : c.multi[m].terms) reaction[d] += alpha_ * coef * lambda_[m];
        for (int d = 0; d < ndof; ++d) {
            if (c.fixed[d]) {
                denominator = std::max(denominator, std::abs(fint[d]));  // reaction - F_ext = -F_int
            } else {
                maxR = std::max(maxR, std::abs(R[d]));
                denominator = std::max(denominator, std::abs(reaction[d] - fext[d]));
            }
        }
        for (size_t m = 0; m < c.multi.size(); ++m) {
            double g = -c.multi[m].value;
            for (const auto& [d, coef] : c.multi[m].terms) g += coef * u[d];
            maxR = std::max(maxR, std::abs(alpha_ * g));
        }
        if (!std::isfinite(maxR))
            throw NumericalError(fmt::format("the residual is not finite at INST {} (iteration {})", inst, it));
        report.iterations = it + 1;
        report.maxResidual = maxR;
        // Loads and reactions that are round-off compared with the elastic forces of the current
        // displacement (imposed rigid motions, zero load): the relative criterion then uses that
        // force scale (mean stiffness diagonal x largest displacement) instead of noise.
        double umax = 0.0;
        for (int d = 0; d < ndof; ++d) umax = std::max(umax, std::abs(u[d]));
        const double forceScale = alpha_ * umax;
        if (denominator <= 1e-12 * forceScale) {
            if (!zeroLoadNoted)
                msg().infof("    loads and reactions are negligible (max {:.3e} vs elastic force scale {:.3e}): "
                            "RESI_GLOB_RELA is taken relative to the force scale",
                            denominator, forceScale);
            zeroLoadNoted = true;
            denominator = forceScale;
        }
        report.relativeResidual = denominator > 0.0 ? maxR / denominator : maxR;
        const bool okMaxi = options.resiGlobMaxi < 0.0 || maxR <= options.resiGlobMaxi;
        const bool okRela = options.resiGlobRela < 0.0 || report.relativeResidual <= options.resiGlobRela;
        msg().infof("    INST {:<12g} Newton iteration {:>2}: RESI_GLOB_RELA {:.6e}  RESI_GLOB_MAXI {:.6e}", inst, it,
                    report.relativeResidual, maxR);
        if (okMaxi && okRela) {
            report.converged = true;
            break;
        }
    }
    msg().infof("    INST {:g}: {} after {} iteration(s), {:.3f} s", inst,
                report.converged ? "converged" : "NOT converged", report.iterations, seconds(t0));
    if (!report.converged) {
        const std::string text = fmt::format(
            "Newton did not converge at INST {} in {} iterations (ITER_GLOB_MAXI): RESI_GLOB_RELA = {:.3e}, "
            "RESI_GLOB_MAXI = {:.3e}",
            inst, options.maxIterations, report.relativeResidual, report.maxResidual);
        if (options.stopOnFailure) throw NumericalError(text);
        msg().alarm("MECANONLINE5_37", text + "\nARRET='NON': the computation goes on with this unconverged state.");
    }
    return report;
}

std::shared_ptr<NodalField> MechanicalProblem::displacementField() const {
    auto field = numbering_->toNodalField(u, model_->mesh);
    field->quantity = "DEPL_R";
    return field;
}

std::shared_ptr<GaussField> MechanicalProblem::stressField() const {
    const Mesh& mesh = *model_->mesh;
    const int dim = numbering_->dim();
    auto field = std::make_shared<GaussField>();
    field->mesh = model_->mesh;
    field->quantity = "SIEF_R";
    field->components = dim == 2 ? std::vector<std::string>{"SIXX", "SIYY", "SIZZ", "SIXY"}
                                 : std::vector<std::string>{"SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ"};
    const size_t nc = field->components.size();
    // Point offsets first; then every element writes its own points (element ranges on the workers).
    const size_t nElements = model_->elements.size();
    field->cells.resize(nElements);
    field->pointOffsets.assign(nElements + 1, 0);
    for (size_t e = 0; e < nElements; ++e) {
        field->cells[e] = model_->elements[e].cell;
        field->pointOffsets[e + 1] =
            field->pointOffsets[e] +
            static_cast<int>(isEnrichedElement(e) ? enrichedIntegrations_[enrichedIndex_[e]].refPoints.size()
                                                  : stiffnessRule(mesh.cellTypes[model_->elements[e].cell]).points.size());
    }
    const size_t points = size_t(field->pointOffsets.back());
    field->pointCoords.resize(points);
    field->pointWeights.resize(points);
    field->pointSubcell.resize(points);
    field->pointRefCoords.resize(points);
    field->values.resize(points * nc);
    auto store = [&](size_t point, const IsotropicLaw& law, const double G[3][3]) {
        double tr = 0.0;
        for (int c = 0; c < dim; ++c) tr += G[c][c];
        auto sigma = [&](int a, int b) { return law.mu * (G[a][b] + G[b][a]) + (a == b ? law.lambdaEff * tr : 0.0); };
        double* out = field->values.data() + point * nc;
        if (dim == 2) {
            out[0] = sigma(0, 0), out[1] = sigma(1, 1), out[2] = law.lambdaZ * (G[0][0] + G[1][1]), out[3] = sigma(0, 1);
        } else {
            out[0] = sigma(0, 0), out[1] = sigma(1, 1), out[2] = sigma(2, 2);
            out[3] = sigma(0, 1), out[4] = sigma(0, 2), out[5] = sigma(1, 2);
        }
    };
    parallelRanges(nElements, nElements >= 4096 ? workerCount() : 1, [&](size_t begin, size_t end, int) {
        ElementIntegration scratch;
        PointGeometry geo;
        std::vector<int> dofs;
        LawCache laws(*material_);
        for (size_t e = begin; e < end; ++e) {
            const auto& element = model_->elements[e];
            const IsotropicLaw& law = laws.of(element);
            const size_t first = size_t(field->pointOffsets[e]);
            const bool fixedSize =
                !isEnrichedElement(e) && classical::dispatch(mesh.cellTypes[element.cell], dim, [&](const auto& ref) {
                    using Ref = std::decay_t<decltype(ref)>;
                    classical::Geometry<Ref> g;
                    classical::computeGeometry(ref, mesh, element.cell, g);
                    int edofs[Ref::dofs];
                    classicalDofs<Ref>(mesh, *numbering_, element.cell, edofs);
                    double ue[Ref::dofs];
                    for (int i = 0; i < Ref::dofs; ++i) ue[i] = u[edofs[i]];
                    for (int p = 0; p < Ref::points; ++p) {
                        double G[3][3];
                        classicalGradient(g.grad[p], ue, G);
                        field->pointCoords[first + p] = g.xyz[p];
                        field->pointWeights[first + p] = g.weight[p];
                        field->pointSubcell[first + p] = 0;
                        field->pointRefCoords[first + p] = ref.point[p];
                        store(first + p, law, G);
                    }
                });
            if (fixedSize) continue;
            const ElementIntegration* ei = &integrationOf(e, scratch);
            computePointGeometry(mesh, element.cell, dim, false, *ei, geo);
            localDofs(mesh, *numbering_, *ei, dofs);
            for (size_t p = 0; p < ei->refPoints.size(); ++p) {
                double G[3][3];
                displacementGradient(*ei, geo, dofs, u, p, dim, G);
                field->pointCoords[first + p] = geo.xyz[p];
                field->pointWeights[first + p] = geo.weight[p];
                field->pointSubcell[first + p] = ei->pointSubcell.empty() ? 0 : ei->pointSubcell[p];
                field->pointRefCoords[first + p] = ei->refPoints[p];
                store(first + p, law, G);
            }
        }
    });
    return field;
}

void MechanicalProblem::releaseFactorisation() {
    solver_ = makeLinearSolver(solverOptions_);
    factorised_ = false;
}

}  // namespace ma
