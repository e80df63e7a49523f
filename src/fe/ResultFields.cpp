#include "fe/ResultFields.hpp"

#include <atomic>

#include "fe/ElasticityKernels.hpp"
#include "fe/Parallel.hpp"

namespace ma {

std::shared_ptr<NodalField> displacementField(const Discretisation& space, const std::vector<double>& u) {
    auto field = space.numbering().toNodalField(u, space.model().mesh);
    field->quantity = "DEPL_R";
    return field;
}

namespace {

// The components of a symmetric tensor field: XX YY ZZ XY (2D), + XZ YZ (3D), after `prefix`.
std::vector<std::string> tensorComponents(const std::string& prefix, int dim) {
    std::vector<std::string> out;
    for (const char* c : {"XX", "YY", "ZZ", "XY", "XZ", "YZ"})
        if (out.size() < (dim == 2 ? 4u : 6u)) out.push_back(prefix + c);
    return out;
}

// An empty field at the integration points with the point offsets of every element; the points
// still to fill.
std::shared_ptr<GaussField> emptyPointField(const Discretisation& space, const std::string& quantity,
                                            const std::string& prefix) {
    auto field = std::make_shared<GaussField>();
    field->mesh = space.model().mesh;
    field->quantity = quantity;
    field->components = tensorComponents(prefix, space.dim());
    const size_t nElements = space.elementCount();
    field->cells.resize(nElements);
    field->pointOffsets.assign(nElements + 1, 0);
    for (size_t e = 0; e < nElements; ++e) {
        field->cells[e] = space.model().elements[e].cell;
        field->pointOffsets[e + 1] = field->pointOffsets[e] + static_cast<int>(space.pointCount(e));
    }
    const size_t points = size_t(field->pointOffsets.back());
    field->values.resize(points * field->components.size());
    return field;
}

using PointStore = void (*)(const double G[3][3], const IsotropicLaw& law, int dim, double* out);

// The values (and, unless `check`, the geometry) of every point of `field`; with `check`, the
// geometry it holds is compared with the points' instead, `differs` set on the first difference.
void fillPoints(const Discretisation& space, const std::vector<double>& u, GaussField& field, PointStore tensorAt,
                bool check, std::atomic<bool>& differs) {
    const int dim = space.dim();
    const size_t nc = field.components.size();
    const size_t nElements = space.elementCount();
    std::array<double, 3>* coords = check ? nullptr : field.pointCoords.mut().data();
    double* weights = check ? nullptr : field.pointWeights.mut().data();
    int* subcells = check ? nullptr : field.pointSubcell.mut().data();
    std::array<double, 3>* refCoords = check ? nullptr : field.pointRefCoords.mut().data();
    // Every element writes its own points (element ranges on the workers).
    parallelRanges(nElements, nElements >= 4096 ? workerCount() : 1, [&](size_t begin, size_t end, int) {
        GeneralElementScratch scratch;
        std::vector<int> dofs;
        LawCache laws(space.material());
        for (size_t e = begin; e < end; ++e) {
            const auto& element = space.model().elements[e];
            const IsotropicLaw& law = laws.of(element);
            const size_t first = size_t(field.pointOffsets[e]);
            auto store = [&](size_t p, const std::array<double, 3>& xyz, double weight, int subcell,
                             const std::array<double, 3>& ref, const double G[3][3]) {
                const size_t i = first + p;
                if (check) {
                    if (field.pointCoords[i] != xyz || field.pointWeights[i] != weight ||
                        field.pointSubcell[i] != subcell || field.pointRefCoords[i] != ref)
                        differs = true;
                } else {
                    coords[i] = xyz, weights[i] = weight, subcells[i] = subcell, refCoords[i] = ref;
                }
                tensorAt(G, law, dim, field.values.data() + i * nc);
            };
            space.visit(
                e, scratch,
                [&](const auto& ref, const auto& g) {
                    using Ref = std::decay_t<decltype(ref)>;
                    int edofs[Ref::dofs];
                    classicalDofs<Ref>(space.mesh(), space.numbering(), element.cell, edofs);
                    double ue[Ref::dofs];
                    for (int i = 0; i < Ref::dofs; ++i) ue[i] = u[edofs[i]];
                    for (int p = 0; p < Ref::points; ++p) {
                        double G[3][3];
                        classicalGradient(g.grad[p], ue, G);
                        store(size_t(p), g.xyz[p], g.weight[p], 0, ref.point[p], G);
                    }
                },
                [&](const ElementIntegration& ei, const PointGeometry& geo) {
                    localDofs(space.mesh(), space.numbering(), ei, dofs);
                    for (size_t p = 0; p < ei.refPoints.size(); ++p) {
                        double G[3][3];
                        displacementGradient(ei, geo, dofs, u, p, dim, G);
                        store(p, geo.xyz[p], geo.weight[p], ei.pointSubcell.empty() ? 0 : ei.pointSubcell[p],
                              ei.refPoints[p], G);
                    }
                });
        }
    });
}

// A tensor at every integration point (X-FEM sub-cell points included) from the displacement
// gradient there.
std::shared_ptr<GaussField> pointField(const Discretisation& space, const std::vector<double>& u,
                                       std::shared_ptr<GaussField> field, PointStore tensorAt) {
    const size_t points = size_t(field->pointOffsets.back());
    // The model's latest field's geometry when it is this field's: compared point by point, not copied.
    const PointGeometryCache& latest = space.model().pointGeometry;
    const bool shared = latest.adopt(*field, points);
    if (!shared) {
        field->pointCoords.resize(points), field->pointWeights.resize(points);
        field->pointSubcell.resize(points), field->pointRefCoords.resize(points);
    }
    std::atomic<bool> differs{false};
    fillPoints(space, u, *field, tensorAt, shared, differs);
    if (shared && differs) {  // another model's or rule's points: this field's own geometry
        field->pointCoords = std::vector<std::array<double, 3>>(points);
        field->pointWeights = std::vector<double>(points);
        field->pointSubcell = std::vector<int>(points);
        field->pointRefCoords = std::vector<std::array<double, 3>>(points);
        fillPoints(space, u, *field, tensorAt, false, differs);
    }
    if (!shared || differs) latest.watch(*field);
    return field;
}

}  // namespace

std::shared_ptr<GaussField> stressField(const Discretisation& space, const std::vector<double>& u) {
    return pointField(space, u, emptyPointField(space, "SIEF_R", "SI"), storeStress);
}

std::shared_ptr<GaussField> strainField(const Discretisation& space, const std::vector<double>& u) {
    return pointField(space, u, emptyPointField(space, "EPSI_R", "EP"), storeStrain);
}

}  // namespace ma
