// The memory limit of a run (src/core/MemoryLimit): sizes beyond it are refused with the size and
// the limit; a limit too large to count in bytes is no limit.
#include <gtest/gtest.h>

#include <limits>

#include "core/Error.hpp"
#include "core/MemoryLimit.hpp"

namespace {

std::string errorOf(double bytes) {
    try {
        ma::checkAllocation(bytes, "the list");
    } catch (const ma::UserError& e) { return e.what(); }
    return "(no error)";
}

TEST(MemoryLimit, SizesBeyondTheLimitAreRefusedWithBoth) {
    ma::setMemoryLimit(256);
    EXPECT_TRUE(ma::memoryLimitIsSet());
    EXPECT_EQ(ma::memoryLimitBytes(), 256u << 20);
    EXPECT_EQ(errorOf(256.0 * (1 << 20)), "(no error)");
    EXPECT_EQ(errorOf(512.0 * (1 << 20)),
              "the list needs 512 MB of memory, more than the memory_limit of 256 MB (P memory_limit in the .export)");
}

TEST(MemoryLimit, ALimitBeyondWhatBytesCountIsNoLimit) {
    ma::setMemoryLimit(1e99);  // P memory_limit 1e99
    EXPECT_EQ(ma::memoryLimitBytes(), std::numeric_limits<std::size_t>::max());
    EXPECT_EQ(errorOf(1e18), "(no error)");
}

}  // namespace
