// The image options that `twinpath bench` and `twinpath-lab peer` share: every measured render's
// width, height and maximum depth. Header only: the executables have CLI11, tp_bench need not.
#pragma once

#include "bench/options.h"

#include <CLI/CLI.hpp>

namespace tp::bench {

inline void add_image_options(CLI::App* c, BenchOptions& o) {
    c->add_option("--width", o.width, "Image width")
        ->check(CLI::Range(1u, 16384u))
        ->capture_default_str();
    c->add_option("--height", o.height, "Image height")
        ->check(CLI::Range(1u, 16384u))
        ->capture_default_str();
    c->add_option("--max-depth", o.max_depth, "Maximum depth (default: each scene's)")
        ->check(CLI::Range(1u, 1000u));
}

} // namespace tp::bench
