#include "core/MemoryUsage.hpp"

#include <algorithm>
#include <atomic>
#include <fstream>
#include <string>

namespace ma {

namespace {

double statusFieldMb(const char* field) {
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key) {
        if (key == field) {
            double kb = 0.0;
            status >> kb;
            return kb / 1024.0;
        }
        std::getline(status, key);
    }
    return 0.0;
}

// The highest VmHWM seen just before a phase's reset.
std::atomic<double> peakBeforeResets{0.0};

void foldPeakBeforeReset() {
    const double peak = statusFieldMb("VmHWM:");
    double seen = peakBeforeResets.load();
    while (peak > seen && !peakBeforeResets.compare_exchange_weak(seen, peak)) {}
}

}  // namespace

double residentMemoryMb() { return statusFieldMb("VmRSS:"); }

double processPeakMb() { return std::max(peakBeforeResets.load(), statusFieldMb("VmHWM:")); }

MemoryPhase::MemoryPhase() {
    foldPeakBeforeReset();
    std::ofstream("/proc/self/clear_refs") << "5";  // VmHWM := VmRSS (Linux >= 4.0)
    start_ = residentMemoryMb();
}

double MemoryPhase::peakMb() const { return statusFieldMb("VmHWM:"); }

}  // namespace ma
