// core/Mpi: the sums and the error agreement. On one process (as ctest runs every unit test) and on
// two and three, started by mpirun (ctest core_mpi.processes_2 / processes_3,
// tests/CMakeLists.txt): a failure on one process only is thrown, with its type and text, on every
// process; sums are the same bits on every process.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <numeric>
#include <thread>
#include <vector>

#include "core/Error.hpp"
#include "core/Mpi.hpp"

namespace ma {
namespace {

TEST(Mpi, SumsAreTheSameOnEveryProcess) {
    const int k = mpi::size(), me = mpi::rank();
    std::vector<double> v = {1.0 + me, 1e-17 * (me + 1), -0.1 * me};
    mpi::sum(v);
    EXPECT_EQ(v[0], k + k * (k - 1) / 2.0);
    EXPECT_NEAR(v[1], 1e-17 * k * (k + 1) / 2, 1e-31);
    // Every process holds rank 0's bits.
    std::vector<double> mine = v;
    mpi::broadcast(v);
    EXPECT_EQ(std::memcmp(v.data(), mine.data(), sizeof(double) * v.size()), 0);

    std::vector<long double> l = {1.0L / 3.0L};
    mpi::sum(l);
    EXPECT_NEAR(double(l[0]), k / 3.0, 1e-15);
    std::vector<double> m = {double(me), -double(me)};
    mpi::max(m);
    EXPECT_EQ(m[0], k - 1.0);
    EXPECT_EQ(m[1], 0.0);
}

// Process r gives r + 1 values r + 0.5, r + 1.5, ...: every process receives them all in rank order.
TEST(Mpi, GatherToAllLaysTheProcessesEndToEnd) {
    const int k = mpi::size(), me = mpi::rank();
    std::vector<size_t> counts;
    for (int r = 0; r < k; ++r) counts.push_back(size_t(r + 1));
    std::vector<double> mine(size_t(me + 1)), whole(size_t(k * (k + 1) / 2), -1.0), expected;
    std::iota(mine.begin(), mine.end(), me + 0.5);
    for (int r = 0; r < k; ++r)
        for (int i = 0; i <= r; ++i) expected.push_back(r + i + 0.5);
    mpi::gatherToAll(mine, whole, counts);
    EXPECT_EQ(whole, expected);
}

TEST(Mpi, AFailureOnTheLastProcessIsThrownOnEveryProcess) {
    const int last = mpi::size() - 1;
    try {
        mpi::collectively([&] {
            if (mpi::rank() == last) throw NumericalError("the element of process " + std::to_string(last) + " failed");
        });
        FAIL() << "no exception on rank " << mpi::rank();
    } catch (const NumericalError& e) {
        EXPECT_EQ(std::string(e.what()), "the element of process " + std::to_string(last) + " failed");
    }
    // The lowest failing rank wins; the others go on together afterwards.
    try {
        mpi::collectively([&] {
            if (mpi::rank() > 0 || mpi::size() == 1) throw UserError("rank " + std::to_string(mpi::rank()));
        });
        FAIL() << "no exception on rank " << mpi::rank();
    } catch (const UserError& e) { EXPECT_EQ(std::string(e.what()), mpi::size() == 1 ? "rank 0" : "rank 1"); }
    EXPECT_NO_THROW(mpi::collectively([] {}));
    EXPECT_FALSE(mpi::agree(std::nullopt).has_value());
}

// The last resort (ctest core_mpi.last_resort, MINIASTER_TEST_LAST_RESORT=1, on 2 processes): the
// last process fails while the others never come to the agreement (as when they wait inside
// MUMPS's collectives, which look for no announcement; here they sleep); past its wait it writes
// its failure on stderr and aborts the job.
TEST(MpiLastResort, AFailureNobodyJoinsAbortsTheJob) {
    if (!std::getenv("MINIASTER_TEST_LAST_RESORT") || mpi::size() == 1) GTEST_SKIP() << "ctest core_mpi.last_resort";
    if (mpi::rank() == mpi::size() - 1) mpi::agreeOnRun(mpi::Failure{0, "<F> <ERROR> the last process failed"}, 1.0);
    else std::this_thread::sleep_for(std::chrono::seconds(60));
    FAIL() << "the job was not aborted";
}

// The run's agreement (the supervisor's): the last process fails alone and announces it; the
// others, inside a sum that process never joins, stop there (OtherProcessFailed) and learn its
// failure at the agreement; later agreements return it at once. Last in the file: the job then
// stays failed (later collectives would throw).
TEST(Mpi, RunAgreementStopsTheOthersCollectivesAndStays) {
    const int last = mpi::size() - 1;
    std::optional<mpi::Failure> agreed;
    // The agreement first: once it is done on the last process, every other has left the
    // collectives of the tests before (its announcement would stop them too).
    if (mpi::rank() == last) {
        mpi::agree(std::nullopt);
        agreed = mpi::agreeOnRun(mpi::Failure{0, "process " + std::to_string(last) + " failed"});
    } else {
        std::vector<double> v = {1.0};
        EXPECT_THROW(
            {
                mpi::agree(std::nullopt);
                mpi::sum(v);
            },
            mpi::OtherProcessFailed);
        agreed = mpi::agreeOnRun(std::nullopt);
        EXPECT_THROW(mpi::sum(v), mpi::OtherProcessFailed);
    }
    ASSERT_TRUE(agreed.has_value());
    EXPECT_EQ(agreed->text, "process " + std::to_string(last) + " failed");
    if (mpi::size() > 1) { EXPECT_EQ(agreed->rank, last); }
    const auto again = mpi::agreeOnRun(std::nullopt);
    EXPECT_EQ(again.has_value(), mpi::size() > 1);  // one process: nothing is kept
    if (again) { EXPECT_EQ(again->text, agreed->text); }
}

}  // namespace
}  // namespace ma
