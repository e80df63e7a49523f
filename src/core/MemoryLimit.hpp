#pragma once
// The memory a run may use: `P memory_limit` of the .export (megabytes of resident memory, watched
// by the run guard, parser/RunGuard.cpp), else the memory available on the machine
// (MemAvailable), or the process's own limit when the user set one (ulimit -v / -d: RLIMIT_AS,
// RLIMIT_DATA), whichever binds first; the cause of an allocation failure names it. (miniaster sets no
// RLIMIT itself: the BLAS and MUMPS threads spin rather than fail when their allocations are refused.) Commands that are told a size
// by the user (a list of 2**31 instants) check it here before allocating, so that the run stops at
// once with the size and the limit rather than after seconds of work with a bare allocation failure.
#include <cstddef>
#include <string>

namespace ma {

// Sets the limit (megabytes).
void setMemoryLimit(double megabytes);
// The limit in bytes: the one set above, else the memory available now; at most the process's RLIMIT.
std::size_t memoryLimitBytes();
// True when a limit was set from P memory_limit.
bool memoryLimitIsSet();
// UserError "<what> needs N MB, more than the M MB ..." when `bytes` exceeds the limit.
void checkAllocation(double bytes, const std::string& what);
// The paragraph for an allocation that failed (std::bad_alloc): names the limit and its origin.
std::string outOfMemoryCause();

}  // namespace ma
