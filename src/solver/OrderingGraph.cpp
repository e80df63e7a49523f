#include "solver/OrderingGraph.hpp"

#include <algorithm>
#include <cstring>

namespace ma {

Supervariables consecutiveIdenticalRows(const CsrMatrix& A) {
    Supervariables s;
    s.of.resize(size_t(A.rows));
    for (int i = 0; i < A.rows; ++i) {
        const long long length = A.rowStart[i + 1] - A.rowStart[i];
        const bool same =
            i > 0 && length == A.rowStart[i] - A.rowStart[i - 1] &&
            std::memcmp(&A.cols[A.rowStart[i]], &A.cols[A.rowStart[i - 1]], size_t(length) * sizeof(int)) == 0;
        if (!same) s.size.push_back(0);
        s.of[i] = int(s.size.size()) - 1;
        ++s.size.back();
    }
    return s;
}

OrderingGraph supervariableGraph(const CsrMatrix& A, const Supervariables& s) {
    const size_t n = s.size.size();
    OrderingGraph g;
    g.start.assign(n + 1, 0);
    // The rows of a supervariable have the same columns, so its first row gives all its edges, and
    // a neighbour's columns are consecutive: each edge is visited once, not once per pair of rows.
    auto forEachEdge = [&](auto&& visit) {
        for (int i = 0; i < A.rows; ++i) {
            const int a = s.of[i];
            if (i > 0 && s.of[i - 1] == a) continue;
            int last = a;
            for (long long k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k)
                if (const int j = A.cols[k]; j > i && s.of[j] != last) last = s.of[j], visit(a, last);
        }
    };
    forEachEdge([&](int a, int b) { ++g.start[a + 1], ++g.start[b + 1]; });
    for (size_t v = 0; v < n; ++v) g.start[v + 1] += g.start[v];
    std::vector<idx_t> raw(size_t(g.start[n])), fill(g.start.begin(), g.start.end() - 1);
    forEachEdge([&](int a, int b) { raw[fill[a]++] = b, raw[fill[b]++] = a; });
    // Sort and deduplicate each list in place, compacting as we go.
    idx_t out = 0;
    for (size_t v = 0; v < n; ++v) {
        const auto first = raw.begin() + g.start[v], last = raw.begin() + g.start[v + 1];
        std::sort(first, last);
        const auto end = std::unique(first, last);
        g.start[v] = out;
        out = idx_t(std::copy(first, end, raw.begin() + out) - raw.begin());
    }
    g.start[n] = out;
    raw.resize(size_t(out));
    g.neighbours = std::move(raw);
    return g;
}

std::vector<int> rowRanks(const Supervariables& s, const std::vector<idx_t>& rankOfVertex) {
    const size_t n = s.size.size();
    std::vector<idx_t> byRank(n);
    for (size_t v = 0; v < n; ++v) byRank[rankOfVertex[v]] = idx_t(v);
    std::vector<int> firstRow(n);
    int next = 0;
    for (size_t r = 0; r < n; ++r) firstRow[byRank[r]] = next, next += int(s.size[byRank[r]]);
    std::vector<int> rank(s.of.size());
    for (size_t i = 0; i < rank.size(); ++i) rank[i] = firstRow[s.of[i]]++;
    return rank;
}

}  // namespace ma
