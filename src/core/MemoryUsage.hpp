#pragma once
// Resident memory of the process for the per-phase figures of the .mess: the current resident
// size and the peak of a phase. A phase's peak is the kernel's high-water mark (VmHWM) after it
// was reset to the current size at the phase's start (/proc/self/clear_refs, "5"). That reset
// also lowers what the kernel keeps as the process's peak (VmHWM, and getrusage's ru_maxrss while
// no thread has exited), so each phase first folds the peak so far into processPeakMb().
namespace ma {

// Current resident size in MB (VmRSS), 0 when /proc is not readable.
double residentMemoryMb();

// Peak resident size of the whole run in MB, across the phases' resets.
double processPeakMb();

// Starts a phase: its peak is measured from now on.
class MemoryPhase {
public:
    MemoryPhase();
    // Peak resident size in MB since the start of the phase (since the start of the process when
    // the kernel refused the reset).
    double peakMb() const;
    double startMb() const { return start_; }

private:
    double start_ = 0.0;
};

}  // namespace ma
