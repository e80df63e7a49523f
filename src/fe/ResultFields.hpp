#pragma once
// Result fields of a mechanical problem's state: DEPL (nodal), SIEF_ELGA and EPSI_ELGA (stresses and
// strains at the elements' integration points, X-FEM sub-cell points included).
#include <atomic>
#include <memory>
#include <vector>

#include "fe/Discretisation.hpp"
#include "fe/ElasticityKernels.hpp"
#include "fields/Fields.hpp"

namespace ma {

std::shared_ptr<NodalField> displacementField(const Discretisation& space, const std::vector<double>& u);

// SIXX SIYY SIZZ SIXY (2D), + SIXZ SIYZ (3D); every point with its physical coordinates, physical
// weight, reference coordinates and sub-cell.
std::shared_ptr<GaussField> stressField(const Discretisation& space, const std::vector<double>& u);

// EPSI_ELGA: EPXX EPYY EPZZ EPXY (2D), + EPXZ EPYZ (3D), the tensor components (EPXY = (dux/dy +
// duy/dx) / 2), at the same points as stressField; EPZZ is 0 in D_PLAN, the free contraction in C_PLAN.
std::shared_ptr<GaussField> strainField(const Discretisation& space, const std::vector<double>& u);

// Writes the points of a field at the integration points: each point's tensor from its displacement
// gradient and its geometry or, when the field adopted the model's latest geometry, a comparison
// with it. Each element writes only its own points: workers may share a writer.
class PointWriter {
public:
    using Tensor = void (*)(const double G[3][3], const IsotropicLaw& law, int dim, double* out);
    PointWriter(GaussField& field, Tensor tensorAt, int dim, bool compare);

    template <class Ref, class Geometry>
    void classicalPoint(size_t element, const Ref& ref, const Geometry& g, int p, const double G[3][3],
                        const IsotropicLaw& law) {
        store(element, size_t(p), g.xyz[p], g.weight[p], 0, ref.point[p], G, law);
    }
    void generalPoint(size_t element, const ElementIntegration& ei, const PointGeometry& geo, size_t p,
                      const double G[3][3], const IsotropicLaw& law) {
        store(element, p, geo.xyz[p], geo.weight[p], ei.pointSubcell.empty() ? 0 : ei.pointSubcell[p], ei.refPoints[p],
              G, law);
    }
    // With a comparison: whether a point's geometry differed from the adopted one.
    bool differs() const { return differs_; }

private:
    void store(size_t element, size_t p, const std::array<double, 3>& xyz, double weight, int subcell,
               const std::array<double, 3>& ref, const double G[3][3], const IsotropicLaw& law);

    GaussField& field_;
    const Tensor tensorAt_;
    const int dim_;
    const bool compare_;
    std::array<double, 3>* coords_ = nullptr;
    double* weights_ = nullptr;
    int* subcells_ = nullptr;
    std::array<double, 3>* refCoords_ = nullptr;
    std::atomic<bool> differs_{false};
};

// A field at the integration points (SIEF_ELGA, EPSI_ELGA) written by a loop over the points:
// stressField's own, or the internal forces' after an increment's last solve (MechanicalProblem),
// which then give SIEF_ELGA without a second pass over the points. Prepared, written by every
// element this process owns through writer(), then finished: the same field, the same bits.
class PointFieldRecording {
public:
    enum class Quantity { Stress, Strain };
    PointFieldRecording(const Discretisation& space, Quantity quantity);
    ~PointFieldRecording();
    PointWriter& writer() { return *writer_; }
    // Every process calls it (a collective call on a distributed discretisation); u: the state
    // the points were written from (a field on other points than the adopted ones is written again).
    std::shared_ptr<GaussField> finish(const std::vector<double>& u);

private:
    const Discretisation& space_;
    const PointWriter::Tensor tensorAt_;
    std::shared_ptr<GaussField> field_;
    bool adopted_ = false;  // the model's latest geometry: compared, not written
    std::unique_ptr<PointWriter> writer_;
};

}  // namespace ma
