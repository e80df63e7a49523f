#include "fields/PointGeometryCache.hpp"

namespace ma {

PointGeometryCache& PointGeometryCache::operator=(const PointGeometryCache& other) {
    if (this == &other) return *this;
    const std::lock_guard lock(guard_);
    coords_.reset(), refCoords_.reset(), weights_.reset(), subcells_.reset();
    return *this;
}

bool PointGeometryCache::adopt(GaussField& field, std::size_t points) const {
    const std::lock_guard lock(guard_);
    GaussField candidate;
    if (!candidate.pointCoords.adopt(coords_) || !candidate.pointWeights.adopt(weights_) ||
        !candidate.pointSubcell.adopt(subcells_) || !candidate.pointRefCoords.adopt(refCoords_))
        return false;
    if (candidate.pointWeights.size() != points || candidate.pointCoords.size() != points ||
        candidate.pointSubcell.size() != points || candidate.pointRefCoords.size() != points)
        return false;
    field.pointCoords = candidate.pointCoords, field.pointWeights = candidate.pointWeights;
    field.pointSubcell = candidate.pointSubcell, field.pointRefCoords = candidate.pointRefCoords;
    return true;
}

void PointGeometryCache::watch(const GaussField& field) const {
    const std::lock_guard lock(guard_);
    coords_ = field.pointCoords.watch(), weights_ = field.pointWeights.watch();
    subcells_ = field.pointSubcell.watch(), refCoords_ = field.pointRefCoords.watch();
}

}  // namespace ma
