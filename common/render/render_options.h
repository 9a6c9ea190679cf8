// What a render is asked to do beyond the scene itself, and what it returns; the same for
// every backend.
#pragma once

#include "render/film.h"
#include "render/stats.h"

#include <cstdint>
#include <functional>

namespace tp {

struct RenderOptions {
    uint32_t seed = 0;
    double time_limit_s = 0; // 0: none; otherwise stop after the pass that crosses it
    uint32_t threads = 0;    // CPU threads; 0: all cores
    // Called after every pass with the fraction of samples done; may be empty.
    std::function<void(double fraction)> progress;
};

struct RenderResult {
    Film film;
    RenderStats stats;
};

} // namespace tp
