#pragma once
// The point geometry (coordinates, weights, sub-cells, reference coordinates) of the latest
// integration-point field of one model: its next field on the same points (the next solve:
// ssnv185c's three results, ~8e5 points each) shares that storage instead of keeping its own copy
// (60 bytes a point). Watched, not owned: it lives as long as a field holds it. One per model
// (fe/Model.hpp), so that two models' fields never meet; guarded (the commands' threads).
#include <array>
#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

#include "fields/Fields.hpp"

namespace ma {

class PointGeometryCache {
public:
    PointGeometryCache() = default;
    // A copy (a model copied to be enriched: MODI_MODELE_XFEM) watches nothing: it is another
    // model's cache.
    PointGeometryCache(const PointGeometryCache&) {}
    PointGeometryCache& operator=(const PointGeometryCache&);

    // Gives `field` the latest geometry when it has `points` points, taken as it is (the caller
    // checks it point by point); false leaves the field without geometry.
    bool adopt(GaussField& field, std::size_t points) const;
    // Makes `field`'s geometry the latest.
    void watch(const GaussField& field) const;

private:
    // A cache: adopting and watching change no result of the model (const: the model is shared).
    mutable std::mutex guard_;
    mutable std::weak_ptr<const std::vector<std::array<double, 3>>> coords_, refCoords_;
    mutable std::weak_ptr<const std::vector<double>> weights_;
    mutable std::weak_ptr<const std::vector<int>> subcells_;
};

}  // namespace ma
