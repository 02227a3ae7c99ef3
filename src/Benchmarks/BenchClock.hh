#pragma once
/// @file BenchClock.hh
/// The clocks of the benchmark programs: CPU time of the whole process (all threads), the
/// steadier figure on a machine shared with other jobs, and wall time; plus the best
/// (smallest) wall and CPU time of a step over repeated runs.

#include <algorithm>
#include <chrono>
#include <ctime>

namespace HexExBench {

/// CPU time of the process (all threads) in seconds.
inline double cpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// Wall-clock seconds since an arbitrary start.
inline double wallSeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// Smallest wall and CPU time of one step over repeated runs.
struct BestTime {
    double wall = 1e300;  ///< smallest wall time
    double cpu = 1e300;   ///< smallest CPU time
    /// Offers one run of @p w wall and @p c CPU seconds.
    void offerLap(double w, double c) {
        wall = std::min(wall, w);
        cpu = std::min(cpu, c);
    }
    /// Offers one run that started at wall @p w0 and CPU @p c0 and ends now.
    void offer(double w0, double c0) { offerLap(wallSeconds() - w0, cpuSeconds() - c0); }
};

} // namespace HexExBench
