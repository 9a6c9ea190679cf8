// `twinpath bench --sizes`: rays per second against image size, for each backend and mode, so
// that the sizes at which a device is not filled show. Each point renders one image
// size for at least `--sizes-time` seconds (RenderOptions::time_limit_s: as many whole passes
// of samples as fit, so small images get many samples) and keeps the best of `--sizes-rounds`
// rounds; the rounds go over all sizes in turn, so that warm-up and drifting clocks spread over
// every size alike. Rays per second are the render's own statistics: every ray traced (camera,
// extension, shadow) over GPU time (timestamp queries) where the device measures it, else over
// wall time (the CPU). The lab's report gives each rate over the same backend's rate at
// 1920x1080 (tools/lab/sizes_report.h).
#pragma once

#include "bench/backends.h"
#include "bench/options.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace tp::bench {

struct ImageSize {
    uint32_t width = 0, height = 0;
    uint64_t pixels() const { return uint64_t(width) * height; }
    std::string name() const; // "1920x1080", as --sizes-list takes it
    bool operator==(const ImageSize& o) const { return width == o.width && height == o.height; }
};

// "WxH" (or "W×H"), or "N" for NxN; each side 1 to 16384. InputError otherwise.
ImageSize parse_image_size(const std::string& word);

// --sizes-list: in ascending order of pixels (then width), each size once; InputError for an
// empty list or a malformed word.
std::vector<ImageSize> parse_image_sizes(const std::vector<std::string>& words);

// The measurement on one backend and mode: `scenes[i]` is the scene flattened at `sizes[i]`.
// The result holds the points in the order of `sizes` (docs/bench.md, "--sizes").
nlohmann::json run_sizes(const std::vector<FlatScene>& scenes, const std::vector<ImageSize>& sizes,
                         const Backend& backend, const BenchOptions& options,
                         const std::function<void(double)>& progress);

} // namespace tp::bench
