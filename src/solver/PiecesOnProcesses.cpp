#include "solver/PiecesOnProcesses.hpp"

#include <mpi.h>

#include <climits>

#include "core/Error.hpp"
#include "core/Mpi.hpp"

namespace ma {

void SharedPieces::gather(int blockSize, const double* mine, double* whole) const {
    std::vector<int> counts, offsets;
    for (const PieceShare& share : shares) {
        counts.push_back(share.unknowns(blockSize));
        offsets.push_back(blockSize * share.copyBegin);
    }
    MPI_Allgatherv(mine, counts[static_cast<size_t>(rank)], MPI_DOUBLE, whole, counts.data(), offsets.data(),
                   MPI_DOUBLE, MPI_COMM_WORLD);
}

void SharedPieces::sumMine(const std::vector<double>& equations, std::vector<double>& mine) const {
    std::vector<double> send;
    std::vector<int> counts;
    send.reserve(equations.size());
    for (const PieceShare& share : shares) {
        for (int i : share.equations) send.push_back(equations[static_cast<size_t>(i)]);
        counts.push_back(int(share.equations.size()));
    }
    mine.resize(this->mine().equations.size());
    MPI_Reduce_scatter(send.data(), mine.data(), counts.data(), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
}

namespace {

// Rows of a matrix sent to another process: their equations and lengths, then their entries.
struct RowParcel {
    std::vector<int> heads;  // equation, length, equation, length, ...
    std::vector<int> cols;
    std::vector<double> values;
};

// part's rows owned by each process (none for this one's own).
std::vector<RowParcel> parcelsOf(const SharedPieces& shared, const CsrMatrix& part) {
    std::vector<int> owner(size_t(part.rows), -1);
    for (size_t p = 0; p < shared.shares.size(); ++p)
        for (int i : shared.shares[p].equations) owner[size_t(i)] = int(p);
    std::vector<RowParcel> parcels(shared.shares.size());
    for (int i = 0; i < part.rows; ++i) {
        const long long begin = part.rowStart[size_t(i)], end = part.rowStart[size_t(i) + 1];
        if (end == begin || owner[size_t(i)] == shared.rank || owner[size_t(i)] < 0) continue;
        RowParcel& parcel = parcels[size_t(owner[size_t(i)])];
        parcel.heads.push_back(i), parcel.heads.push_back(int(end - begin));
        parcel.cols.insert(parcel.cols.end(), part.cols.begin() + begin, part.cols.begin() + end);
        parcel.values.insert(parcel.values.end(), part.values.begin() + begin, part.values.begin() + end);
    }
    return parcels;
}

template <class T>
std::vector<T> exchange(const std::vector<RowParcel>& parcels, std::vector<T> RowParcel::*field, MPI_Datatype type,
                        std::vector<int>& receivedCounts) {
    const size_t P = parcels.size();
    std::vector<int> sendCounts(P), sendOffsets(P), receiveOffsets(P);
    std::vector<T> send;
    for (size_t p = 0; p < P; ++p) {
        sendOffsets[p] = int(send.size()), sendCounts[p] = int((parcels[p].*field).size());
        send.insert(send.end(), (parcels[p].*field).begin(), (parcels[p].*field).end());
    }
    receivedCounts.assign(P, 0);
    MPI_Alltoall(sendCounts.data(), 1, MPI_INT, receivedCounts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    long long total = 0;
    for (size_t p = 0; p < P; ++p) receiveOffsets[p] = int(total), total += receivedCounts[p];
    // MPI's counts and offsets are int: beyond, every process stops with the same error.
    mpi::collectively([&] {
        if (send.size() > size_t(INT_MAX) || total > INT_MAX)
            throw NumericalError("PETSc: the matrix rows one process sends or receives exceed MPI's int counts");
    });
    std::vector<T> received(static_cast<size_t>(total));
    MPI_Alltoallv(send.data(), sendCounts.data(), sendOffsets.data(), type, received.data(), receivedCounts.data(),
                  receiveOffsets.data(), type, MPI_COMM_WORLD);
    return received;
}

// Adds the sorted row (cols, values) into the sorted row `into`.
void addRow(std::vector<std::pair<int, double>>& into, const int* cols, const double* values, long long length,
            std::vector<std::pair<int, double>>& merged) {
    merged.clear();
    size_t a = 0;
    for (long long b = 0; b < length;) {
        if (a < into.size() && into[a].first < cols[b]) merged.push_back(into[a++]);
        else if (a < into.size() && into[a].first == cols[b]) {
            merged.emplace_back(cols[b], into[a].second + values[b]);
            ++a, ++b;
        } else {
            merged.emplace_back(cols[b], values[b]);
            ++b;
        }
    }
    merged.insert(merged.end(), into.begin() + long(a), into.end());
    into.swap(merged);
}

}  // namespace

void matchSharesToParts(std::vector<int>& ownerOfCopy, const PieceBasis& basis, const CsrMatrix& part) {
    const int processes = mpi::size(), rank = mpi::rank();
    // overlap[p * P + q]: entries of process p's part in the rows of share q.
    std::vector<double> overlap(size_t(processes * processes), 0.0);
    for (int i = 0; i < part.rows && i < basis.T.rows; ++i) {
        const int share = shareOfEquation(basis, ownerOfCopy, i);
        if (share < 0) continue;
        overlap[size_t(rank * processes + share)] += double(part.rowStart[size_t(i) + 1] - part.rowStart[size_t(i)]);
    }
    mpi::sum(overlap);
    // Greedily, the largest overlap left first.
    std::vector<int> processOf(size_t(processes), -1);
    std::vector<char> taken(size_t(processes), 0);
    for (int round = 0; round < processes; ++round) {
        int bestP = -1, bestQ = -1;
        for (int p = 0; p < processes; ++p)
            for (int q = 0; q < processes; ++q)
                if (!taken[size_t(p)] && processOf[size_t(q)] < 0 &&
                    (bestP < 0 || overlap[size_t(p * processes + q)] > overlap[size_t(bestP * processes + bestQ)]))
                    bestP = p, bestQ = q;
        taken[size_t(bestP)] = 1, processOf[size_t(bestQ)] = bestP;
    }
    for (int& owner : ownerOfCopy) owner = processOf[size_t(owner)];
}

CsrMatrix summedShareRows(const SharedPieces& shared, const CsrMatrix& part) {
    // Each process sends its part's rows of the others' equations to their owners, which add them
    // to their own part's rows.
    std::vector<int> heads, cols, counts;
    std::vector<double> values;
    {
        const std::vector<RowParcel> parcels = parcelsOf(shared, part);
        heads = exchange(parcels, &RowParcel::heads, MPI_INT, counts);
        cols = exchange(parcels, &RowParcel::cols, MPI_INT, counts);
        values = exchange(parcels, &RowParcel::values, MPI_DOUBLE, counts);
    }
    const std::vector<int>& mine = shared.mine().equations;
    std::vector<int> localRow(size_t(part.rows), -1);
    for (size_t k = 0; k < mine.size(); ++k) localRow[size_t(mine[k])] = int(k);
    std::vector<std::vector<std::pair<long long, int>>> received(mine.size());  // (offset, length) per row
    long long at = 0;
    for (size_t h = 0; h + 1 < heads.size(); h += 2) {
        const int row = localRow[size_t(heads[h])];
        if (row < 0) throw InternalError("PETSc: a process received matrix rows of an equation it does not own");
        received[size_t(row)].emplace_back(at, heads[h + 1]);
        at += heads[h + 1];
    }
    CsrMatrix rows;
    rows.rows = int(mine.size());
    long long bound = static_cast<long long>(cols.size());  // the entries of the rows, at most
    for (int i : mine) bound += part.rowStart[size_t(i) + 1] - part.rowStart[size_t(i)];
    rows.cols.reserve(size_t(bound)), rows.values.reserve(size_t(bound));
    std::vector<std::pair<int, double>> row, merged;
    for (size_t k = 0; k < mine.size(); ++k) {
        const size_t i = size_t(mine[k]);
        const long long begin = part.rowStart[i], end = part.rowStart[i + 1];
        if (received[k].empty()) {  // most rows: this process's cells only
            rows.cols.insert(rows.cols.end(), part.cols.begin() + begin, part.cols.begin() + end);
            rows.values.insert(rows.values.end(), part.values.begin() + begin, part.values.begin() + end);
        } else {
            row.clear();
            for (long long e = begin; e < end; ++e) row.emplace_back(part.cols[size_t(e)], part.values[size_t(e)]);
            for (const auto& [offset, length] : received[k])
                addRow(row, cols.data() + offset, values.data() + offset, length, merged);
            for (const auto& [c, v] : row) rows.cols.push_back(c), rows.values.push_back(v);
        }
        rows.rowStart.push_back(static_cast<long long>(rows.cols.size()));
    }
    return rows;
}

}  // namespace ma
