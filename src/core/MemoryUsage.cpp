#include "core/MemoryUsage.hpp"

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

}  // namespace

double residentMemoryMb() { return statusFieldMb("VmRSS:"); }

MemoryPhase::MemoryPhase() {
    std::ofstream("/proc/self/clear_refs") << "5";  // VmHWM := VmRSS (Linux >= 4.0)
    start_ = residentMemoryMb();
}

double MemoryPhase::peakMb() const { return statusFieldMb("VmHWM:"); }

}  // namespace ma
