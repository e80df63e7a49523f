#include "solver/CoordinateOrdering.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

#include "core/Timing.hpp"
#include "solver/OrderingGraph.hpp"

namespace ma {

namespace {

constexpr size_t kLeafVertices = 8;                // ordered as they come: their fill is negligible
constexpr double kBandLow = 0.4, kBandHigh = 0.6;  // candidate planes: between these count quantiles
constexpr double kImbalanceCost = 4.0;             // a split 10 % off balance must save 40 % of separator

struct Split {
    float position = 0.0f;  // left part: coordinate <= position
    bool found = false;
};

class Bisection {
public:
    Bisection(const OrderingGraph& g, const std::vector<idx_t>& weight, const std::vector<RowPoint>& point)
        : g_(g),
          weight_(weight),
          point_(point),
          rank_(weight.size()),
          part_(weight.size(), -1),
          coordinate_(weight.size()),
          reach_(weight.size()),
          spacing_(weight.size()) {
        for (size_t v = 0; v < weight.size(); ++v)
            for (idx_t k = g.start[v]; k < g.start[v + 1]; ++k)
                for (int a = 0; a < 3; ++a)
                    spacing_[v][a] = std::max(spacing_[v][a], std::abs(point[g.neighbours[k]][a] - point[v][a]));
    }

    // Parts are disjoint and each vertex's scratch entries belong to its part: the two halves
    // of the top `parallelLevels` levels are ordered on two threads, with the same ranks.
    std::vector<idx_t> run(int parallelLevels) {
        std::vector<idx_t> all(weight_.size());
        for (size_t v = 0; v < all.size(); ++v) all[v] = idx_t(v);
        order(std::move(all), 0, parallelLevels);
        return std::move(rank_);
    }

private:
    void rankInOrder(const std::vector<idx_t>& vertices, idx_t base) {
        for (idx_t v : vertices) rank_[v] = base++;
    }

    // The axis the part spans the most cells along: its extent over the mean spacing of its
    // vertices' neighbours along that axis. The longest extent alone cuts a box of flat cells
    // (10 x 10 x 1, N^3 cells) across its many thin layers: planes of N x N vertices where one of
    // N x N/16 would do (ssnv511c refined at N = 31: 4.0e11 flops against METIS's 2.3e11).
    int longestAxis(const std::vector<idx_t>& vertices) const {
        std::array<float, 3> low, high;
        std::array<double, 3> spacing{};
        low.fill(std::numeric_limits<float>::max()), high.fill(std::numeric_limits<float>::lowest());
        for (idx_t v : vertices)
            for (int a = 0; a < 3; ++a) {
                low[a] = std::min(low[a], point_[v][a]), high[a] = std::max(high[a], point_[v][a]);
                spacing[a] += spacing_[v][a];
            }
        int axis = -1;
        double most = 0.0;
        for (int a = 0; a < 3; ++a) {
            if (!(high[a] > low[a]) || !(spacing[a] > 0.0)) continue;
            const double cells = double(high[a] - low[a]) * double(vertices.size()) / spacing[a];
            if (cells > most) most = cells, axis = a;
        }
        return axis;
    }

    // coordinate_ along the axis; reach_: the largest coordinate of a neighbour in the part
    // (a vertex is in the separator of a plane at c when coordinate <= c < reach).
    // A neighbour is in the part when it carries the part's number (numbers are never reused;
    // the other thread may be renumbering its own vertices meanwhile, hence the atomic access).
    void measure(const std::vector<idx_t>& vertices, int axis) {
        const int part = nextPart_++;
        for (idx_t v : vertices)
            std::atomic_ref<int>(part_[v]).store(part, std::memory_order_relaxed), coordinate_[v] = point_[v][axis];
        for (idx_t v : vertices) {
            float reach = std::numeric_limits<float>::lowest();
            for (idx_t k = g_.start[v]; k < g_.start[v + 1]; ++k)
                if (const idx_t u = g_.neighbours[k];
                    std::atomic_ref<int>(part_[u]).load(std::memory_order_relaxed) == part)
                    reach = std::max(reach, coordinate_[u]);
            reach_[v] = reach;
        }
    }

    float quantile(std::vector<float>& values, double q) const {
        const auto at = values.begin() + std::ptrdiff_t(q * double(values.size() - 1));
        std::nth_element(values.begin(), at, values.end());
        return *at;
    }

    // The plane among the distinct coordinates of the band with the least separator weight
    // times (1 + cost of imbalance), from a sweep over the candidates.
    Split choosePlane(const std::vector<idx_t>& vertices) const {
        std::vector<float> values(vertices.size());
        for (size_t i = 0; i < vertices.size(); ++i) values[i] = coordinate_[vertices[i]];
        const float low = quantile(values, kBandLow), high = quantile(values, kBandHigh);
        std::vector<float> candidates;
        for (float x : values)
            if (x >= low && x <= high) candidates.push_back(x);
        std::sort(candidates.begin(), candidates.end());
        candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
        const size_t K = candidates.size();
        std::vector<double> separatorChange(K + 1, 0.0), leftAdded(K, 0.0);
        double below = 0.0, total = 0.0;
        auto index = [&](float x) {
            return size_t(std::lower_bound(candidates.begin(), candidates.end(), x) - candidates.begin());
        };
        for (idx_t v : vertices) {
            const double w = double(weight_[v]);
            total += w;
            const float x = coordinate_[v];
            if (x > high) continue;
            size_t first = 0;
            if (x < low) below += w;
            else first = index(x), leftAdded[first] += w;
            if (reach_[v] > x)
                if (const size_t last = index(reach_[v]); last > first)
                    separatorChange[first] += w, separatorChange[last] -= w;
        }
        Split best;
        double bestScore = std::numeric_limits<double>::max(), separator = 0.0, left = below;
        for (size_t k = 0; k < K; ++k) {
            separator += separatorChange[k], left += leftAdded[k];
            const double leftPart = left - separator, rightPart = total - left;
            if (leftPart <= 0.0 || rightPart <= 0.0) continue;
            const double score = separator * (1.0 + kImbalanceCost * std::abs(leftPart - rightPart) / total);
            if (score < bestScore) bestScore = score, best.position = candidates[k], best.found = true;
        }
        return best;
    }

    void order(std::vector<idx_t> vertices, idx_t base, int parallelLevels) {
        const int axis = vertices.size() > kLeafVertices ? longestAxis(vertices) : -1;
        if (axis < 0) return rankInOrder(vertices, base);
        measure(vertices, axis);
        const Split plane = choosePlane(vertices);
        if (!plane.found) return rankInOrder(vertices, base);
        std::vector<idx_t> left, right, separator;
        for (idx_t v : vertices) {
            if (coordinate_[v] > plane.position) right.push_back(v);
            else if (reach_[v] > plane.position) separator.push_back(v);
            else left.push_back(v);
        }
        std::vector<idx_t>().swap(vertices);
        const idx_t leftCount = idx_t(left.size()), rightCount = idx_t(right.size());
        rankInOrder(separator, base + leftCount + rightCount);
        if (parallelLevels > 0) {
            std::thread leftHalf([&] { order(std::move(left), base, parallelLevels - 1); });
            order(std::move(right), base + leftCount, parallelLevels - 1);
            leftHalf.join();
        } else {
            order(std::move(left), base, 0);
            order(std::move(right), base + leftCount, 0);
        }
    }

    const OrderingGraph& g_;
    const std::vector<idx_t>& weight_;
    const std::vector<RowPoint>& point_;
    std::vector<idx_t> rank_;
    std::vector<int> part_;  // the number of the part each vertex was last measured in
    std::atomic<int> nextPart_ = 0;
    std::vector<float> coordinate_, reach_;
    std::vector<std::array<float, 3>> spacing_;  // largest coordinate difference to a neighbour, per axis
};

}  // namespace

FillReducingOrdering coordinateNestedDissection(const CsrMatrix& A, std::span<const RowPoint> rowPoints, int threads) {
    const auto t0 = std::chrono::steady_clock::now();
    FillReducingOrdering ordering;
    const Supervariables s = consecutiveIdenticalRows(A);
    const OrderingGraph g = supervariableGraph(A, s);
    const std::vector<idx_t> weight(s.size);
    std::vector<RowPoint> point(s.size.size());
    for (size_t i = s.of.size(); i-- > 0;) point[s.of[i]] = rowPoints[i];  // the first row's point
    ordering.vertices = idx_t(s.size.size());
    ordering.graphEdges = g.start.back() / 2;
    ordering.pivotRank = rowRanks(s, Bisection(g, weight, point).run(threads >= 4 ? 2 : threads >= 2 ? 1 : 0));
    ordering.seconds = secondsSince(t0);
    return ordering;
}

}  // namespace ma
