#include "fe/ExternalForces.hpp"

#include <fmt/format.h>

#include <array>

#include "core/Error.hpp"
#include "fe/ElasticityKernels.hpp"
#include "fe/Enrichment.hpp"
#include "mesh/ShapeFunctions.hpp"

namespace ma {

namespace {

class ExternalForceAssembler {
public:
    ExternalForceAssembler(const Discretisation& space, std::vector<double>& f)
        : space_(space), f_(f), laws_(space.material()) {}

    void addPressure(const PressureLoad& pr, double factor, double inst) {
        const bool anyFunction = pr.function || pr.shear.function;
        const auto pts = anyFunction ? pointsOf(pr.cells, true) : std::vector<std::array<double, 3>>{};
        const auto pres = valuesAt({pr.value, pr.function}, pts, inst);
        const auto shear = valuesAt(pr.shear, pts, inst);
        size_t next = 0;
        distribute(pr.cells, true, [&](size_t p, const PointGeometry& g) {
            const size_t i = next++;
            return traction(g.normal[p], factor * pick(pres, i, pr.value), factor * pick(shear, i, pr.shear.value));
        });
    }

    void addSurfaceForce(const SurfaceForce& sf, double factor, double inst) {
        bool anyFunction = false;
        for (const auto& c : sf.component) anyFunction = anyFunction || c.function;
        const auto pts = anyFunction ? pointsOf(sf.cells, true) : std::vector<std::array<double, 3>>{};
        std::array<std::vector<double>, 3> values;
        for (int c = 0; c < 3; ++c) values[c] = valuesAt(sf.component[c], pts, inst);
        size_t next = 0;
        distribute(sf.cells, true, [&](size_t, const PointGeometry&) {
            std::array<double, 3> t{};
            for (int c = 0; c < 3; ++c) t[c] = factor * pick(values[c], next, sf.component[c].value);
            ++next;
            return t;
        });
    }

    // Both lips of an interface or crack: each side's faces with that side's psi (and crack-tip
    // fields) and outward normal.
    void addLipPressure(const LipPressure& lp, double factor, double inst) {
        const Model& model = space_.model();
        std::vector<LipIntegration> lips;
        if (!model.enrichment || !model.enrichment->lipIntegration(*lp.crack, lips))
            throw InternalError(lp.path + ": the interface is not one of the model's");
        for (auto& lip : lips) {
            if (!lp.onlyCells.empty() && !lp.onlyCells[size_t(lip.element.cell)]) continue;
            if (lip.element.hasTip()) {  // Phi of this lip only (the lips' points, ~10^5 on a 3D front)
                const IsotropicLaw& law = laws_.of(ModelElement{lip.element.cell, model.modelisation});
                model.enrichment->tipFields(lip.element.cell, TipLaw(law.lambdaEff, law.mu), lip.element);
            }
            const auto pres = valuesAt(lp.pressure, lip.xyz, inst);
            const auto shear = valuesAt(lp.shear, lip.xyz, inst);
            localDofs(space_.mesh(), space_.numbering(), lip.element, dofs_);
            const int n = lip.element.nodeCount;
            std::vector<double> N(static_cast<size_t>(n));
            for (size_t p = 0; p < lip.xyz.size(); ++p) {
                shapeValues(space_.mesh().cellTypes[size_t(lip.element.cell)], lip.element.refPoints[p], N);
                const auto t = traction(lip.normal[p], factor * pick(pres, p, lp.pressure.value),
                                        factor * pick(shear, p, lp.shear.value));
                addAtPoint(lip.element, int(p), N.data(), lip.weight[p], t);
            }
            std::vector<double>().swap(lip.element.tipPhi);
        }
    }

    void addVolumeForce(const VolumeForce& vf, double factor, double inst) {
        std::array<std::vector<double>, 3> values;
        if (vf.function[0] || vf.function[1] || vf.function[2]) {
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

private:
    // Distributes a force density given at the points of each cell (when the density is a
    // function, its values were evaluated at pointsOf(cells), in the same order).
    template <class Density>
    void distribute(const std::vector<int>& cells, bool boundary, Density&& density) {
        const int dim = space_.dim();
        for (int cell : cells) {
            elementIntegration(space_.model(), cell, boundary, ei_);
            computePointGeometry(space_.mesh(), cell, dim, boundary, ei_, geo_);
            int materialCell = cell;  // a face's crack-tip fields are its volume's, with its material
            if (boundary && carriesTipUnknowns(cell)) {
                materialCell = space_.model().enrichment->boundaryTipFields(cell, geo_.xyz, ei_);
                if (materialCell < 0)
                    throw NotImplemented(fmt::format(
                        "a distributed load on the face {}, whose nodes carry crack-tip unknowns (K1, K2...): no "
                        "volume element of the model bounded by this face gives the crack-tip fields there",
                        space_.mesh().cellNames[size_t(cell)]));
            }
            applyLaw(ei_, materialCell);
            localDofs(space_.mesh(), space_.numbering(), ei_, dofs_);
            const int n = ei_.nodeCount;
            for (size_t p = 0; p < ei_.refPoints.size(); ++p)
                addAtPoint(ei_, int(p), &geo_.N[p * size_t(n)], geo_.weight[p], density(p, geo_));
        }
    }

    // f += w psi_ak N_a t at one point of an element (dofs_ holds the element's dofs), and on a
    // crack-tip node f(K_m) += w N_a sum_c Phi[c][m] t_c.
    void addAtPoint(const ElementIntegration& ei, int p, const double* N, double w, const std::array<double, 3>& t) {
        const int dim = space_.dim();
        int i = 0;
        for (int a = 0; a < ei.nodeCount; ++a) {
            for (int k = 0; k < ei.slots[size_t(a)]; ++k) {
                const double pa = ei.multiplier(p, a, k);
                for (int c = 0; c < dim; ++c, ++i) f_[size_t(dofs_[size_t(i)])] += w * pa * N[a] * t[size_t(c)];
            }
            if (!ei.tipAt(a)) continue;
            const double* Phi = ei.tipValue(size_t(p), ei.tipGroupOf(a));
            for (int m = 0; m < dim; ++m, ++i) {
                double work = 0.0;
                for (int c = 0; c < dim; ++c) work += Phi[c * 3 + m] * t[size_t(c)];
                f_[size_t(dofs_[size_t(i)])] += w * N[a] * work;
            }
        }
    }

    // The crack-tip fields of an element for the material of `cell` (Phi depends on kappa and mu).
    void applyLaw(ElementIntegration& ei, int cell) {
        if (!ei.hasTip()) return;
        const IsotropicLaw& law = laws_.of(ModelElement{cell, space_.model().modelisation});
        applyTipLaw(ei, law.lambdaEff, law.mu);
    }

    // A face whose nodes carry K1, K2[, K3]: its load works on them through the tip fields of the
    // volume element it bounds (Enrichment::boundaryTipFields).
    bool carriesTipUnknowns(int cell) const {
        const auto* enrichment = space_.model().enrichment.get();
        if (!enrichment) return false;
        for (int node : space_.mesh().cellNodes(cell))
            if (enrichment->tipNode(node)) return true;
        return false;
    }

    // Traction of a pressure p and (plane models) a shear c on a surface of unit outward normal m.
    static std::array<double, 3> traction(const std::array<double, 3>& m, double p, double c) {
        return {-p * m[0] - c * m[1], -p * m[1] + c * m[0], -p * m[2]};
    }

    // Function values at the points (empty for a constant value).
    static std::vector<double> valuesAt(const LoadValue& v, const std::vector<std::array<double, 3>>& pts,
                                        double inst) {
        if (!v.function) return {};
        return evaluateAtPoints(*v.function, pts, inst);
    }
    static double pick(const std::vector<double>& values, size_t i, double constant) {
        return values.empty() ? constant : values[i];
    }

    std::vector<std::array<double, 3>> pointsOf(const std::vector<int>& cells, bool boundary) {
        std::vector<std::array<double, 3>> pts;
        for (int cell : cells) {
            elementIntegration(space_.model(), cell, boundary, ei_);
            computePointGeometry(space_.mesh(), cell, space_.dim(), boundary, ei_, geo_);
            pts.insert(pts.end(), geo_.xyz.begin(), geo_.xyz.end());
        }
        return pts;
    }

    const Discretisation& space_;
    std::vector<double>& f_;
    LawCache laws_;
    ElementIntegration ei_;
    PointGeometry geo_;
    std::vector<int> dofs_;
};

}  // namespace

void assembleExternalForces(const Discretisation& space, const std::vector<LoadCase>& loads, double inst,
                            std::vector<double>& f) {
    f.assign(space.numbering().size(), 0.0);
    ExternalForceAssembler assembler(space, f);
    for (const auto& lc : loads) {
        const double factor = lc.factor(inst);
        if (factor == 0.0) continue;
        for (const auto& pr : lc.load->pressures) assembler.addPressure(pr, factor, inst);
        for (const auto& sf : lc.load->surfaceForces) assembler.addSurfaceForce(sf, factor, inst);
        for (const auto& lp : lc.load->lipPressures) assembler.addLipPressure(lp, factor, inst);
        for (const auto& vf : lc.load->volumeForces) assembler.addVolumeForce(vf, factor, inst);
    }
}

}  // namespace ma
