// Elapsed wall time for the statistics, progress and time limits every command reports: the
// steady clock, which no clock adjustment moves.
#pragma once

#include <chrono>

namespace tp {

// Seconds from `t0` to now.
inline double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace tp
