#include "solver/MetisOrdering.hpp"

#include <metis.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <limits>
#include <string>

#include "core/Error.hpp"
#include "core/Timing.hpp"
#include "solver/OrderingGraph.hpp"

namespace ma {

namespace {

[[noreturn]] void metisFailed(const char* function, int status, idx_t n) {
    throw NumericalError(std::string(function) + " failed (" +
                         (status == METIS_ERROR_MEMORY ? "out of memory" : "error " + std::to_string(status)) +
                         ") on a graph of " + std::to_string(n) + " vertices");
}

void setOptions(idx_t* options) {
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_NUMBERING] = 0;
    // Two separators tried at each level, the smaller kept: with one, the factorisation's flops
    // vary by +-8 % with METIS's random seed on the ssnv511 grids; with two they stay within 1.08
    // of the nested-dissection count (docs/study.md, "Orderings").
    options[METIS_OPTION_NSEPS] = 2;
}

// Elimination rank of each vertex of g (weights w), by METIS_NodeND.
std::vector<idx_t> nestedDissection(OrderingGraph& g, std::vector<idx_t>& w) {
    idx_t n = idx_t(w.size());
    std::vector<idx_t> perm(static_cast<size_t>(n)), rank(static_cast<size_t>(n));
    if (g.start.back() == 0) {  // METIS wants edges; without any coupling every order is as good
        for (idx_t v = 0; v < n; ++v) rank[v] = v;
        return rank;
    }
    idx_t options[METIS_NOPTIONS];
    setOptions(options);
    // perm/iperm of METIS: row i of the permuted matrix is row perm[i]; iperm is the rank.
    const int status =
        METIS_NodeND(&n, g.start.data(), g.neighbours.data(), w.data(), options, perm.data(), rank.data());
    if (status != METIS_OK) metisFailed("METIS_NodeND", status, n);
    return rank;
}

// The subgraph of the vertices v with part[v] == which; local -> global vertex in `vertices`.
OrderingGraph inducedSubgraph(const OrderingGraph& g, const std::vector<idx_t>& part, idx_t which,
                              const std::vector<idx_t>& local, std::vector<idx_t>& vertices) {
    OrderingGraph sub;
    sub.start.push_back(0);
    for (size_t v = 0; v + 1 < g.start.size(); ++v) {
        if (part[v] != which) continue;
        vertices.push_back(idx_t(v));
        for (idx_t k = g.start[v]; k < g.start[v + 1]; ++k)
            if (part[g.neighbours[k]] == which) sub.neighbours.push_back(local[g.neighbours[k]]);
        sub.start.push_back(idx_t(sub.neighbours.size()));
    }
    return sub;
}

// Orders the two halves, the second in a child process when `twoProcesses` (threads would share
// METIS's random generator; a process has its own copy, reseeded by each call like this one's):
// the ranks are the same either way. A failed fork or child falls back to this process.
void orderHalves(OrderingGraph (&half)[2], std::vector<idx_t> (&weights)[2], std::vector<idx_t> (&rank)[2],
                 bool twoProcesses) {
    const size_t n1 = weights[1].size(), bytes = (n1 + 1) * sizeof(idx_t);
    void* shared =
        twoProcesses ? mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0) : MAP_FAILED;
    const pid_t child = shared != MAP_FAILED ? fork() : -1;
    if (child == 0) {  // only METIS and memcpy here, then _exit: no atexit handler, no Python
        // The run's own handlers would write into its .mess or wake its watchdog: a signal or a
        // crash here ends only this child (the parent then orders the half itself), and the
        // child does not outlive a parent that is stopped.
        for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTERM, SIGINT, SIGHUP, SIGXCPU})
            std::signal(sig, SIG_DFL);
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        auto* out = static_cast<idx_t*>(shared);
        try {
            const std::vector<idx_t> r = nestedDissection(half[1], weights[1]);
            std::copy(r.begin(), r.end(), out + 1);
            out[0] = 1;
        } catch (...) { out[0] = 0; }
        _exit(0);
    }
    rank[0] = nestedDissection(half[0], weights[0]);
    bool done = false;
    if (child > 0) {
        int status = 0;
        const auto* in = static_cast<const idx_t*>(shared);
        if (waitpid(child, &status, 0) == child && WIFEXITED(status) && in[0] == 1) {
            rank[1].assign(in + 1, in + 1 + n1);
            done = true;
        }
    }
    if (shared != MAP_FAILED) munmap(shared, bytes);
    if (!done) rank[1] = nestedDissection(half[1], weights[1]);
}

// Large graphs: the top separator first (METIS_ComputeVertexSeparator), then the two halves
// ordered apart (on two processes when there are two threads), separator last: what
// METIS_NodeND does at its first level.
constexpr size_t kSplitVertices = 100000;

std::vector<idx_t> splitNestedDissection(OrderingGraph& g, std::vector<idx_t>& w, int threads) {
    idx_t n = idx_t(w.size());
    if (size_t(n) < kSplitVertices || g.start.back() == 0) return nestedDissection(g, w);
    idx_t options[METIS_NOPTIONS], separatorWeight = 0;
    setOptions(options);
    std::vector<idx_t> part(static_cast<size_t>(n));
    const int status = METIS_ComputeVertexSeparator(&n, g.start.data(), g.neighbours.data(), w.data(), options,
                                                    &separatorWeight, part.data());
    if (status != METIS_OK) metisFailed("METIS_ComputeVertexSeparator", status, n);
    std::vector<idx_t> local(static_cast<size_t>(n)), count(3, 0);
    for (idx_t v = 0; v < n; ++v) local[v] = count[part[v]]++;
    std::vector<idx_t> vertices[2], weights[2], rank[2];
    OrderingGraph half[2];
    for (int h = 0; h < 2; ++h) {
        half[h] = inducedSubgraph(g, part, h, local, vertices[h]);
        for (idx_t v : vertices[h]) weights[h].push_back(w[v]);
    }
    orderHalves(half, weights, rank, threads >= 2);
    std::vector<idx_t> order(static_cast<size_t>(n));
    for (int h = 0; h < 2; ++h)
        for (size_t i = 0; i < vertices[h].size(); ++i) order[vertices[h][i]] = (h ? count[0] : 0) + rank[h][i];
    for (idx_t v = 0; v < n; ++v)
        if (part[v] == 2) order[v] = count[0] + count[1] + local[v];
    return order;
}

}  // namespace

FillReducingOrdering nestedDissectionOrdering(const CsrMatrix& A, int threads) {
    const auto t0 = std::chrono::steady_clock::now();
    if (A.nonZeros() > std::numeric_limits<idx_t>::max())
        throw NumericalError("METIS ordering: the matrix has more entries than METIS's 32-bit index");
    FillReducingOrdering ordering;
    const Supervariables s = consecutiveIdenticalRows(A);
    OrderingGraph g = supervariableGraph(A, s);
    std::vector<idx_t> weight(s.size);
    ordering.vertices = idx_t(s.size.size());
    ordering.graphEdges = g.start.back() / 2;
    ordering.pivotRank = rowRanks(s, splitNestedDissection(g, weight, threads));
    ordering.seconds = secondsSince(t0);
    return ordering;
}

}  // namespace ma
