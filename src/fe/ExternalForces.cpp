#include "fe/ExternalForces.hpp"

#include <array>

#include "fe/ElasticityKernels.hpp"

namespace ma {

namespace {

class ExternalForceAssembler {
public:
    ExternalForceAssembler(const Discretisation& space, std::vector<double>& f) : space_(space), f_(f) {}

    void addPressure(const PressureLoad& pr, double factor, double inst) {
        std::vector<double> values;
        if (pr.function) values = evaluateAtPoints(*pr.function, pointsOf(pr.cells, true), inst);
        size_t next = 0;
        distribute(pr.cells, true, [&](size_t p, const PointGeometry& g) {
            const double pres = factor * (pr.function ? values[next++] : pr.value);
            return std::array<double, 3>{-pres * g.normal[p][0], -pres * g.normal[p][1], -pres * g.normal[p][2]};
        });
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
            localDofs(space_.mesh(), space_.numbering(), ei_, dofs_);
            const int n = ei_.nodeCount;
            for (size_t p = 0; p < ei_.refPoints.size(); ++p) {
                const std::array<double, 3> t = density(p, geo_);
                const double w = geo_.weight[p];
                int i = 0;
                for (int a = 0; a < n; ++a) {
                    const double Na = geo_.N[p * n + a];
                    for (int k = 0; k < ei_.slots[a]; ++k) {
                        const double pa = ei_.multiplier(int(p), a, k);
                        for (int c = 0; c < dim; ++c, ++i) f_[dofs_[i]] += w * pa * Na * t[c];
                    }
                }
            }
        }
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
        for (const auto& vf : lc.load->volumeForces) assembler.addVolumeForce(vf, factor, inst);
    }
}

}  // namespace ma
