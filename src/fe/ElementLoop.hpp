#pragma once
// Element loops of the mechanical problem: the one classical/general dispatch of a volume element,
// and a threaded loop over elements whose floating-point sums keep the serial order.
#include <algorithm>
#include <atomic>
#include <barrier>
#include <chrono>
#include <cstdint>
#include <exception>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/Timing.hpp"
#include "fe/ClassicalElement.hpp"
#include "fe/ElementIntegration.hpp"
#include "fe/ElementKinematics.hpp"

namespace ma {

// What the general path of a volume element reuses from one element to the next.
struct GeneralElementScratch {
    ElementIntegration ei;
    PointGeometry geo;
};

// Volume element on `cell` of a model of dimension `dim`, on its fastest path: a classical cell
// (not enriched, fixed sizes) calls onClassical(ref, g) with its reference data and fixed-size
// geometry (classical::Reference / classical::Geometry); any other calls onGeneral(ei, geo) with the
// description integrationOf(scratch.ei) returns and its point geometry.
template <class IntegrationOf, class OnClassical, class OnGeneral>
void visitVolumeElement(const Mesh& mesh, int dim, int cell, bool enriched, GeneralElementScratch& scratch,
                        IntegrationOf&& integrationOf, OnClassical&& onClassical, OnGeneral&& onGeneral) {
    if (!enriched && classical::dispatch(mesh.cellTypes[cell], dim, [&](const auto& ref) {
            using Ref = std::decay_t<decltype(ref)>;
            classical::Geometry<Ref> g;
            classical::computeGeometry(ref, mesh, cell, g);
            onClassical(ref, g);
        }))
        return;
    const ElementIntegration& ei = integrationOf(scratch.ei);
    computePointGeometry(mesh, cell, dim, false, ei, scratch.geo);
    onGeneral(ei, scratch.geo);
}

// Elements per batch of batchedElementLoop, and the workers for a loop over nElements: one per
// batch at most (threads cost more than small loops).
constexpr size_t kElementBatch = 4096;
int elementWorkers(size_t nElements);

// Element loop on `workers` threads whose sums keep the serial order. Elements go in batches;
// begin(worker) at the start of each batch; phase 1: compute(e, worker) for the worker's share of
// the batch (e in increasing order); phase 2: scatter(first, count, worker) on every worker for the
// whole batch, each worker adding only into the entries it owns, in element order. A failing
// element stops the loop after its batch's phase 1; the exception of the first failing element is
// rethrown (what a serial loop reports). cpu[worker] receives each worker's CPU time.
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

// Entries of the global arrays a worker owns in phase 2: blocks of 64 indices dealt in turn.
inline bool ownedBy(int index, int worker, int workers) { return (index >> 6) % workers == worker; }

}  // namespace ma
