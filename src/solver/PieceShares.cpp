#include "solver/PieceShares.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

namespace ma {

namespace {

// Nodes as the groups of copies linked through the equations that read them (union-find over T's
// rows): group of each copy, numbered from 0.
std::vector<int> groupsOfCopies(const PieceBasis& basis, int& groups) {
    std::vector<int> parent(static_cast<size_t>(basis.copies));
    std::iota(parent.begin(), parent.end(), 0);
    const auto root = [&parent](int c) {
        while (parent[size_t(c)] != c) c = parent[size_t(c)] = parent[size_t(parent[size_t(c)])];
        return c;
    };
    const CsrMatrix& T = basis.T;
    for (int i = 0; i < T.rows; ++i)
        for (long long k = T.rowStart[size_t(i)] + 1; k < T.rowStart[size_t(i) + 1]; ++k) {
            const int a = root(T.cols[size_t(T.rowStart[size_t(i)])] / basis.blockSize);
            const int b = root(T.cols[size_t(k)] / basis.blockSize);
            if (a != b) parent[size_t(std::max(a, b))] = std::min(a, b);
        }
    std::vector<int> group(size_t(basis.copies), -1), number(size_t(basis.copies), -1);
    groups = 0;
    for (int c = 0; c < basis.copies; ++c) {
        int& g = number[size_t(root(c))];
        if (g < 0) g = groups++;
        group[size_t(c)] = g;
    }
    return group;
}

struct CoordinateBisection {
    const std::vector<double>& point;  // per group, dim coordinates
    const std::vector<double>& weight;
    int dim;
    std::vector<int>& owner;

    // Splits groups[begin, end) between the processes [first, first + parts).
    void split(std::vector<int>& groups, size_t begin, size_t end, int first, int parts) {
        if (parts == 1) {
            for (size_t g = begin; g < end; ++g) owner[size_t(groups[g])] = first;
            return;
        }
        int axis = 0;
        double longest = -1.0;
        for (int d = 0; d < dim; ++d) {
            double lo = 1e300, hi = -1e300;
            for (size_t g = begin; g < end; ++g) {
                const double x = point[size_t(groups[g] * dim + d)];
                lo = std::min(lo, x), hi = std::max(hi, x);
            }
            if (hi - lo > longest) longest = hi - lo, axis = d;
        }
        std::sort(groups.begin() + long(begin), groups.begin() + long(end), [&](int a, int b) {
            const double xa = point[size_t(a * dim + axis)], xb = point[size_t(b * dim + axis)];
            return xa < xb || (xa == xb && a < b);
        });
        const int left = parts / 2;
        double total = 0.0;
        for (size_t g = begin; g < end; ++g) total += weight[size_t(groups[g])];
        size_t cut = begin;
        for (double sum = 0.0; cut < end && sum < total * left / parts; ++cut) sum += weight[size_t(groups[cut])];
        split(groups, begin, cut, first, left);
        split(groups, cut, end, first + left, parts - left);
    }
};

// The copies renumbered by owner (then by their old number), T and the per-unknown arrays after them.
void renumberCopies(PieceBasis& basis, const std::vector<int>& ownerOfCopy) {
    const size_t bs = size_t(basis.blockSize), copies = size_t(basis.copies), n = bs * copies;
    std::vector<int> order(copies, 0);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return ownerOfCopy[size_t(a)] < ownerOfCopy[size_t(b)]; });
    std::vector<size_t> newCopy(copies);
    for (size_t k = 0; k < copies; ++k) newCopy[size_t(order[k])] = k;
    const auto unknown = [&](size_t u) { return newCopy[u / bs] * bs + u % bs; };
    for (int& c : basis.T.cols) c = int(unknown(size_t(c)));
    std::vector<char> padding(n);
    for (size_t u = 0; u < n; ++u) padding[unknown(u)] = basis.padding[u];
    basis.padding = std::move(padding);
    std::vector<double> modes(basis.modes.size());
    for (size_t m = 0; m < basis.modes.size() / std::max<size_t>(n, 1); ++m)
        for (size_t u = 0; u < n; ++u) modes[m * n + unknown(u)] = basis.modes[m * n + u];
    basis.modes = std::move(modes);
    std::vector<double> coordinates(basis.coordinates.size());
    for (size_t u = 0; u < std::min(n, coordinates.size()); ++u) coordinates[unknown(u)] = basis.coordinates[u];
    basis.coordinates = std::move(coordinates);
    // T's rows keep their columns sorted
    CsrMatrix& T = basis.T;
    for (int i = 0; i < T.rows; ++i) {
        std::vector<std::pair<int, double>> row;
        for (long long k = T.rowStart[size_t(i)]; k < T.rowStart[size_t(i) + 1]; ++k)
            row.emplace_back(T.cols[size_t(k)], T.values[size_t(k)]);
        std::sort(row.begin(), row.end());
        for (size_t k = 0; k < row.size(); ++k)
            T.cols[size_t(T.rowStart[size_t(i)]) + k] = row[k].first,
                                                   T.values[size_t(T.rowStart[size_t(i)]) + k] = row[k].second;
    }
}

}  // namespace

std::vector<int> bisectCopies(const PieceBasis& basis, int processes) {
    int groups = 0;
    const std::vector<int> group = groupsOfCopies(basis, groups);
    if (groups < processes || basis.coordinates.size() != size_t(basis.size())) return {};
    const int dim = basis.blockSize;
    std::vector<double> point(size_t(groups * dim)), weight(size_t(groups), 0.0);
    for (int c = 0; c < basis.copies; ++c) {
        const size_t g = size_t(group[size_t(c)]);
        for (int d = 0; d < dim; ++d) point[g * size_t(dim) + size_t(d)] = basis.coordinates[size_t(c * dim + d)];
        weight[g] += 1.0;
    }
    std::vector<int> owner(size_t(groups), 0), order(static_cast<size_t>(groups));
    std::iota(order.begin(), order.end(), 0);
    CoordinateBisection{point, weight, dim, owner}.split(order, 0, order.size(), 0, processes);
    std::vector<int> ownerOfCopy(static_cast<size_t>(basis.copies));
    for (int c = 0; c < basis.copies; ++c) ownerOfCopy[size_t(c)] = owner[size_t(group[size_t(c)])];
    return ownerOfCopy;
}

std::vector<PieceShare> shareCopies(PieceBasis& basis, const std::vector<int>& ownerOfCopy, int processes) {
    if (ownerOfCopy.size() != size_t(basis.copies)) return {};
    std::vector<PieceShare> shares(static_cast<size_t>(processes));
    for (int c = 0; c < basis.copies; ++c) shares[size_t(ownerOfCopy[size_t(c)])].copyEnd += 1;
    for (int p = 0, next = 0; p < processes; ++p) {
        shares[size_t(p)].copyBegin = next;
        next += shares[size_t(p)].copyEnd, shares[size_t(p)].copyEnd = next;
        if (shares[size_t(p)].copyEnd == shares[size_t(p)].copyBegin) return {};
    }
    for (int i = 0; i < basis.T.rows; ++i)
        if (const int share = shareOfEquation(basis, ownerOfCopy, i); share >= 0)
            shares[size_t(share)].equations.push_back(i);
    renumberCopies(basis, ownerOfCopy);
    return shares;
}

}  // namespace ma
