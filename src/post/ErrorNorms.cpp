#include "post/ErrorNorms.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <future>
#include <map>

#include "core/Error.hpp"
#include "core/Function.hpp"
#include "core/Mpi.hpp"
#include "fe/FieldSampling.hpp"
#include "fe/Material.hpp"
#include "fe/Model.hpp"
#include "fe/Parallel.hpp"
#include "fields/Fields.hpp"
#include "post/TableOperations.hpp"

namespace ma {
namespace {

// Elements per batch of points: the reference formulas are evaluated one batch at a time (about
// 1e5 points for QUAD4), so that a refined model never holds all its samples at once.
constexpr size_t kBatchElements = 32768;

// Batches per process on several processes: dealt in turn, they share the points evenly even where
// the costly elements (X-FEM sub-cells) gather in one part of the numbering.
constexpr size_t kBatchesPerProcess = 8;

// This process's batches of n elements (docs/mpi.md): batches of at most kBatchElements dealt to
// the processes in turn, from rank 0; each process sums its own and the sums are reduced. One
// process: every batch, as many as before.
struct Batches {
    size_t size = kBatchElements, start = 0, stride = kBatchElements;
    explicit Batches(size_t n) {
        const size_t k = size_t(mpi::size()), parts = k == 1 ? 1 : k * kBatchesPerProcess;
        size = std::max<size_t>(1, std::min(kBatchElements, (n + parts - 1) / parts));
        start = size * size_t(mpi::rank());
        stride = size * k;
    }
};

// Cells of `group` that carry an element of the model.
std::vector<int> groupElements(const Model& model, const std::string& group) {
    const Mesh& mesh = *model.mesh;
    const auto& members = namedGroup(mesh, GroupKind::Cells, group, "GROUP_MA");
    std::vector<char> inModel(size_t(mesh.cellCount()), 0);
    for (const auto& e : model.elements) inModel[size_t(e.cell)] = 1;
    std::vector<int> out;
    for (int c : members)
        if (inModel[size_t(c)]) out.push_back(c);
    if (out.empty()) throw UserError(fmt::format("GROUP_MA: group {} has no element of model {}", group, model.name));
    return out;
}

// Reference values of every component at the points whose coordinates are the columns X, Y[, Z]:
// one batch per distinct formula (SIXX=ZERO, SIYY=ZERO ... evaluate ZERO once), null = 0.
std::vector<std::vector<double>> evaluateReference(const ReferenceFormulas& ref, size_t group,
                                                   const std::map<std::string, std::vector<double>>& columns,
                                                   size_t npoints) {
    std::vector<std::vector<double>> out(ref.components.size());
    for (size_t c = 0; c < ref.components.size(); ++c) {
        const Function* f = ref.formulas[c].empty() ? nullptr : ref.formulas[c].at(group).get();
        size_t same = c;
        for (size_t b = 0; b < c && same == c; ++b)
            if (!ref.formulas[b].empty() && ref.formulas[b].at(group).get() == f && f) same = b;
        if (same != c) out[c] = out[same];
        else out[c] = f ? f->evaluateColumns(columns, npoints) : std::vector<double>(npoints, 0.0);
    }
    return out;
}

void checkFormulaCounts(const ReferenceFormulas& ref, size_t groups) {
    for (size_t c = 0; c < ref.components.size(); ++c)
        if (!ref.formulas[c].empty() && ref.formulas[c].size() != groups)
            throw UserError(
                fmt::format("{} gives {} formulas for {} groups of GROUP_MA: one formula per group is "
                            "needed (code_aster PREPOST_12)",
                            ref.components[c], ref.formulas[c].size(), groups));
}

std::shared_ptr<Table> errorTable(const std::vector<std::string>& groups, const std::vector<double>& difference,
                                  const std::vector<double>& reference, double totalDifference, double totalReference,
                                  bool withRelative, double relative, const std::string& title) {
    // An overflow (loads of 1e300: squares beyond 1.8e308) would print inf/nan as if it were a
    // value, or a "zero reference": the norm is refused instead.
    for (double v : {totalDifference, totalReference, withRelative ? relative : 0.0})
        if (!std::isfinite(v))
            throw NumericalError(
                fmt::format("{}: the norm is not finite (DIFFERENCE = {}, REFERENCE = {}): the field "
                            "or the reference values overflow (a value beyond about 1e154 squares "
                            "beyond the largest double); check the loads and the units",
                            title, totalDifference, totalReference));
    auto table = std::make_shared<Table>();
    size_t width = 5;  // "TOTAL"
    for (const auto& g : groups) width = std::max(width, g.size());
    table->addColumn("GROUP_MA", textColumnFor(width));
    table->addColumn("DIFFERENCE", ColumnType::real());
    table->addColumn("REFERENCE", ColumnType::real());
    if (withRelative) table->addColumn("ERREUR RELATIVE", ColumnType::real());
    for (size_t g = 0; g < groups.size(); ++g) {
        const size_t r = table->addRow();
        table->set(r, 0, groups[g]);
        table->set(r, 1, difference[g]);
        table->set(r, 2, reference[g]);
    }
    const size_t r = table->addRow();
    table->set(r, 0, std::string("TOTAL"));
    table->set(r, 1, totalDifference);
    table->set(r, 2, totalReference);
    if (withRelative) table->set(r, 3, relative);
    table->title = {title};
    return table;
}

}  // namespace

double elasticEnergyDensity(const double s[6], double E, double nu, bool planeStress) {
    const double zz = planeStress ? 0.0 : s[2];
    const double normal = s[0] * s[0] + s[1] * s[1] + zz * zz - 2.0 * nu * (s[0] * s[1] + s[1] * zz + zz * s[0]);
    const double shear = s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
    return normal / (2.0 * E) + (1.0 + nu) / E * shear;
}

std::shared_ptr<Table> displacementErrorTable(const Model& model, const NodalField& displacement,
                                              const std::vector<std::string>& groups,
                                              const ReferenceFormulas& reference, const MaterialField* material) {
    checkFormulaCounts(reference, groups.size());
    const int dim = model.dim;
    std::vector<double> diff(groups.size()), ref(groups.size());
    std::vector<DisplacementSample> samples, nextSamples;
    std::map<std::string, std::vector<double>> columns;
    const char* names[3] = {"X", "Y", "Z"};
    for (size_t g = 0; g < groups.size(); ++g) {
        std::vector<char> wanted(size_t(model.mesh->cellCount()), 0);
        for (int c : groupElements(model, groups[g])) wanted[size_t(c)] = 1;
        double sums[2] = {0.0, 0.0};  // squared difference and reference
        double& d2 = sums[0];
        double& r2 = sums[1];
        const Batches batches(model.elements.size());
        // The next batch is sampled on a second thread while the formulas of this one run
        // (Python, one thread): the sums below keep their order.
        auto sample = [&](size_t first, std::vector<DisplacementSample>& out) {
            out.clear();
            appendDisplacementSamples(model, displacement, wanted, first,
                                      std::min(first + batches.size, model.elements.size()), out, material);
        };
        const bool overlap = workerCount() > 1;
        mpi::collectively([&] {
            if (batches.start < model.elements.size()) sample(batches.start, samples);
            for (size_t first = batches.start; first < model.elements.size(); first += batches.stride) {
                const size_t following = first + batches.stride;
                std::future<void> ahead;
                if (following < model.elements.size()) {
                    if (overlap) ahead = std::async(std::launch::async, sample, following, std::ref(nextSamples));
                }
                if (!samples.empty()) {
                    for (int d = 0; d < dim; ++d) {
                        auto& col = columns[names[d]];
                        col.resize(samples.size());
                        for (size_t p = 0; p < samples.size(); ++p) col[p] = samples[p].xyz[size_t(d)];
                    }
                    const auto uref = evaluateReference(reference, g, columns, samples.size());
                    for (size_t p = 0; p < samples.size(); ++p) {
                        double dp = 0.0, rp = 0.0;
                        for (size_t c = 0; c < reference.components.size(); ++c) {
                            const double u = uref[c][p];
                            rp += u * u;
                            if (int(c) < dim) dp += (samples[p].u[c] - u) * (samples[p].u[c] - u);
                        }
                        d2 += samples[p].weight * dp;
                        r2 += samples[p].weight * rp;
                    }
                }
                if (following < model.elements.size()) {
                    if (overlap) ahead.get();
                    else sample(following, nextSamples);
                    samples.swap(nextSamples);
                }
            }
        });
        mpi::sum(sums);
        diff[g] = std::sqrt(d2);
        ref[g] = std::sqrt(r2);
    }
    double d2 = 0.0, r2 = 0.0;
    for (size_t g = 0; g < groups.size(); ++g) {
        d2 += diff[g] * diff[g];
        r2 += ref[g] * ref[g];
    }
    const double totalDiff = std::sqrt(d2), totalRef = std::sqrt(r2);
    const bool relative = totalRef > 1e-16;
    return errorTable(groups, diff, ref, totalDiff, totalRef, relative, relative ? totalDiff / totalRef : 0.0,
                      "ERREUR EN NORME L2 DU DEPLACEMENT");
}

namespace {

// The six stress slots SIXX SIYY SIZZ SIXY SIXZ SIYZ of the energy norm: the field component and
// the reference formula of each (-1: absent, counts as zero).
struct StressSlots {
    int field[6];
    int reference[6];
};

StressSlots stressSlots(const GaussField& stress, const ReferenceFormulas& reference) {
    static const char* kNames[6] = {"SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ"};
    StressSlots slots;
    for (int k = 0; k < 6; ++k) slots.field[k] = stress.componentIndex(kNames[k]);
    if (slots.field[0] < 0 || slots.field[1] < 0)
        throw UserError(
            fmt::format("CHAM_GD: field {} has no stress components SIXX, SIYY (SIEF_ELGA expected)", stress.name));
    for (int k = 0; k < 6; ++k) {
        slots.reference[k] = -1;
        for (size_t c = 0; c < reference.components.size(); ++c)
            if (reference.components[c] == kNames[k]) slots.reference[k] = int(c);
    }
    return slots;
}

}  // namespace

std::shared_ptr<Table> energyErrorTable(const Model& model, const GaussField& stress, const MaterialField& material,
                                        const std::vector<std::string>& groups, const ReferenceFormulas& reference) {
    checkFormulaCounts(reference, groups.size());
    const int dim = model.dim;
    const bool planeStress = model.modelisation == Modelisation::C_PLAN;
    const StressSlots slots = stressSlots(stress, reference);
    const int* fieldComp = slots.field;
    const int* refComp = slots.reference;
    const size_t nc = stress.components.size();
    // Components the difference uses: 2*dim of them (SIXX, SIYY, SIZZ, SIXY[, SIXZ, SIYZ]).
    const int used = dim == 3 ? 6 : 4;

    std::vector<double> diff(groups.size()), ref(groups.size());
    for (size_t g = 0; g < groups.size(); ++g) {
        std::vector<char> inGroup(size_t(model.mesh->cellCount()), 0);
        for (int c : groupElements(model, groups[g])) inGroup[size_t(c)] = 1;
        auto selected = [&](size_t e) {
            return stress.cells[e] >= 0 && stress.cells[e] < int(inGroup.size()) && inGroup[size_t(stress.cells[e])];
        };
        double sums[2] = {0.0, 0.0};  // energies of the difference and of the reference
        double& eDiff = sums[0];
        double& eRef = sums[1];
        std::map<std::string, std::vector<double>> columns;
        const char* names[3] = {"X", "Y", "Z"};
        const Batches batches(stress.cells.size());
        mpi::collectively([&] {
            for (size_t first = batches.start; first < stress.cells.size(); first += batches.stride) {
                const size_t last = std::min(first + batches.size, stress.cells.size());
                // Coordinates of the batch's points in the group, in field order.
                size_t npoints = 0;
                for (size_t e = first; e < last; ++e)
                    if (selected(e)) npoints += size_t(stress.pointOffsets[e + 1] - stress.pointOffsets[e]);
                if (npoints == 0) continue;
                for (int d = 0; d < dim; ++d) {
                    auto& col = columns[names[d]];
                    col.clear();
                    for (size_t e = first; e < last; ++e)
                        if (selected(e))
                            for (int p = stress.pointOffsets[e]; p < stress.pointOffsets[e + 1]; ++p)
                                col.push_back(stress.pointCoords[size_t(p)][size_t(d)]);
                }
                const auto sref = evaluateReference(reference, g, columns, npoints);
                size_t k = 0;
                for (size_t e = first; e < last; ++e) {
                    if (!selected(e)) continue;
                    const Material& m = material.at(stress.cells[e]);
                    for (int p = stress.pointOffsets[e]; p < stress.pointOffsets[e + 1]; ++p, ++k) {
                        double sr[6] = {0, 0, 0, 0, 0, 0}, sd[6] = {0, 0, 0, 0, 0, 0};
                        for (int j = 0; j < 6; ++j) {
                            sr[j] = refComp[j] >= 0 ? sref[size_t(refComp[j])][k] : 0.0;
                            if (j < used) {
                                const double sh =
                                    fieldComp[j] >= 0 ? stress.values[size_t(p) * nc + size_t(fieldComp[j])] : 0.0;
                                sd[j] = sh - sr[j];
                            }
                        }
                        const double w = stress.pointWeights[size_t(p)];
                        eRef += w * elasticEnergyDensity(sr, m.E, m.nu, planeStress);
                        eDiff += w * elasticEnergyDensity(sd, m.E, m.nu, planeStress);
                    }
                }
            }
        });
        mpi::sum(sums);
        diff[g] = eDiff;
        ref[g] = eRef;
    }
    double totalDiff = 0.0, totalRef = 0.0;
    for (size_t g = 0; g < groups.size(); ++g) {
        totalDiff += diff[g];
        totalRef += ref[g];
    }
    const bool relative = std::sqrt(totalRef) > 1e-16;
    return errorTable(groups, diff, ref, totalDiff, totalRef, relative,
                      relative ? std::sqrt(totalDiff) / std::sqrt(totalRef) : 0.0, "ERREUR EN NORME ENERGIE");
}

}  // namespace ma
