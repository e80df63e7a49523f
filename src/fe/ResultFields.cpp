#include "fe/ResultFields.hpp"

#include <algorithm>
#include <atomic>
#include <numeric>

#include "core/Mpi.hpp"
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

// Every point of the elements this process owns, written by `points` (element ranges on the workers).
void fillPoints(const Discretisation& space, const std::vector<double>& u, PointWriter& points) {
    const size_t nElements = space.elementCount();
    const int dim = space.dim();
    parallelRanges(nElements, nElements >= 4096 ? workerCount() : 1, [&](size_t begin, size_t end, int) {
        GeneralElementScratch scratch;
        std::vector<int> dofs;
        LawCache laws(space.material());
        for (size_t e = begin; e < end; ++e) {
            if (!space.owns(e)) continue;  // another process's (gatherElementPoints)
            const auto& element = space.model().elements[e];
            const IsotropicLaw& law = laws.of(element);
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
                        points.classicalPoint(e, ref, g, p, G, law);
                    }
                },
                [&](const ElementIntegration& ei, const PointGeometry& geo) {
                    localDofs(space.mesh(), space.numbering(), ei, dofs);
                    for (size_t p = 0; p < ei.refPoints.size(); ++p) {
                        double G[3][3];
                        displacementGradient(ei, geo, dofs, u, p, dim, G);
                        points.generalPoint(e, ei, geo, p, G, law);
                    }
                });
        }
    });
}

// fillPoints on every process; on a distributed discretisation collectively (a failure on one
// process stops them all).
void fillOwnPoints(const Discretisation& space, const std::vector<double>& u, PointWriter& points) {
    if (space.distributed()) mpi::collectively([&] { fillPoints(space, u, points); });
    else fillPoints(space, u, points);
}

// Elements per exchange of gatherElementPoints: buffers of a few MB whatever the model's size.
constexpr size_t kGatheredElements = 4096;

// On a distributed discretisation each process filled its own elements' points: every process
// receives the others' values (and their geometry when `geometry`), so that each holds the whole
// field, the same bits as one process computing them all.
void gatherElementPoints(const Discretisation& space, GaussField& field, bool geometry) {
    const size_t nc = field.components.size(), stride = nc + (geometry ? 8 : 0);
    std::array<double, 3>* coords = geometry ? field.pointCoords.mut().data() : nullptr;
    std::array<double, 3>* refCoords = geometry ? field.pointRefCoords.mut().data() : nullptr;
    double* weights = geometry ? field.pointWeights.mut().data() : nullptr;
    int* subcells = geometry ? field.pointSubcell.mut().data() : nullptr;
    auto pack = [&](size_t i, double* out) {
        std::copy_n(field.values.data() + i * nc, nc, out);
        if (!geometry) return;
        out += nc;
        std::copy_n(coords[i].data(), 3, out), std::copy_n(refCoords[i].data(), 3, out + 3);
        out[6] = weights[i], out[7] = double(subcells[i]);
    };
    auto unpack = [&](size_t i, const double* in) {
        std::copy_n(in, nc, field.values.data() + i * nc);
        if (!geometry) return;
        in += nc;
        std::copy_n(in, 3, coords[i].data()), std::copy_n(in + 3, 3, refCoords[i].data());
        weights[i] = in[6], subcells[i] = int(in[7]);
    };
    const int me = mpi::rank();
    std::vector<size_t> counts(size_t(mpi::size())), offsets(counts.size());
    std::vector<double> mine, whole;
    for (size_t first = 0; first < field.cells.size(); first += kGatheredElements) {
        const size_t last = std::min(field.cells.size(), first + kGatheredElements);
        std::fill(counts.begin(), counts.end(), 0);
        mine.clear();
        for (size_t e = first; e < last; ++e) {
            const size_t p0 = size_t(field.pointOffsets[e]), p1 = size_t(field.pointOffsets[e + 1]);
            counts[size_t(space.ownerOf(e))] += (p1 - p0) * stride;
            if (space.ownerOf(e) != me) continue;
            const size_t base = mine.size();
            mine.resize(base + (p1 - p0) * stride);
            for (size_t i = p0; i < p1; ++i) pack(i, mine.data() + base + (i - p0) * stride);
        }
        whole.resize(std::reduce(counts.begin(), counts.end()));
        mpi::gatherToAll(mine, whole, counts);
        std::exclusive_scan(counts.begin(), counts.end(), offsets.begin(), size_t(0));
        for (size_t e = first; e < last; ++e) {
            const size_t p0 = size_t(field.pointOffsets[e]), p1 = size_t(field.pointOffsets[e + 1]);
            size_t& at = offsets[size_t(space.ownerOf(e))];
            if (space.ownerOf(e) != me)
                for (size_t i = p0; i < p1; ++i) unpack(i, whole.data() + at + (i - p0) * stride);
            at += (p1 - p0) * stride;
        }
    }
}

}  // namespace

PointWriter::PointWriter(GaussField& field, Tensor tensorAt, int dim, bool compare)
    : field_(field), tensorAt_(tensorAt), dim_(dim), compare_(compare) {
    if (compare) return;
    coords_ = field.pointCoords.mut().data(), weights_ = field.pointWeights.mut().data();
    subcells_ = field.pointSubcell.mut().data(), refCoords_ = field.pointRefCoords.mut().data();
}

void PointWriter::store(size_t element, size_t p, const std::array<double, 3>& xyz, double weight, int subcell,
                        const std::array<double, 3>& ref, const double G[3][3], const IsotropicLaw& law) {
    const size_t i = size_t(field_.pointOffsets[element]) + p;
    if (compare_) {
        if (field_.pointCoords[i] != xyz || field_.pointWeights[i] != weight || field_.pointSubcell[i] != subcell ||
            field_.pointRefCoords[i] != ref)
            differs_ = true;
    } else {
        coords_[i] = xyz, weights_[i] = weight, subcells_[i] = subcell, refCoords_[i] = ref;
    }
    tensorAt_(G, law, dim_, field_.values.data() + i * field_.components.size());
}

namespace {

// The field's own geometry, to be written.
void allocateGeometry(GaussField& field) {
    const size_t points = size_t(field.pointOffsets.back());
    field.pointCoords = std::vector<std::array<double, 3>>(points);
    field.pointWeights = std::vector<double>(points);
    field.pointSubcell = std::vector<int>(points);
    field.pointRefCoords = std::vector<std::array<double, 3>>(points);
}

}  // namespace

PointFieldRecording::PointFieldRecording(const Discretisation& space, Quantity quantity)
    : space_(space), tensorAt_(quantity == Quantity::Stress ? storeStress : storeStrain) {
    field_ =
        quantity == Quantity::Stress ? emptyPointField(space, "SIEF_R", "SI") : emptyPointField(space, "EPSI_R", "EP");
    // The model's latest field's geometry when it is this field's: compared point by point, not copied.
    adopted_ = space.model().pointGeometry.adopt(*field_, size_t(field_->pointOffsets.back()));
    if (!adopted_) allocateGeometry(*field_);
    writer_ = std::make_unique<PointWriter>(*field_, tensorAt_, space.dim(), adopted_);
}

PointFieldRecording::~PointFieldRecording() = default;

std::shared_ptr<GaussField> PointFieldRecording::finish(const std::vector<double>& u) {
    bool differs = writer_->differs();
    if (space_.distributed()) {  // agreed: the processes compared their own elements
        double anyDiffers = differs ? 1.0 : 0.0;
        mpi::max({&anyDiffers, 1});
        differs = anyDiffers != 0.0;
    }
    if (adopted_ && differs) {  // another model's or rule's points: this field's own geometry
        allocateGeometry(*field_);
        PointWriter own(*field_, tensorAt_, space_.dim(), false);
        fillOwnPoints(space_, u, own);
    }
    const bool ownGeometry = !adopted_ || differs;
    if (space_.distributed()) gatherElementPoints(space_, *field_, ownGeometry);
    if (ownGeometry) space_.model().pointGeometry.watch(*field_);
    return field_;
}

namespace {

std::shared_ptr<GaussField> pointField(const Discretisation& space, const std::vector<double>& u,
                                       PointFieldRecording::Quantity quantity) {
    PointFieldRecording recording(space, quantity);
    fillOwnPoints(space, u, recording.writer());
    return recording.finish(u);
}

}  // namespace

std::shared_ptr<GaussField> stressField(const Discretisation& space, const std::vector<double>& u) {
    return pointField(space, u, PointFieldRecording::Quantity::Stress);
}

std::shared_ptr<GaussField> strainField(const Discretisation& space, const std::vector<double>& u) {
    return pointField(space, u, PointFieldRecording::Quantity::Strain);
}

}  // namespace ma
