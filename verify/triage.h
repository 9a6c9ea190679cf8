// What verify does when two engines' images differ: the manual loop of docs/debugging.md, by
// itself. (1) The AOVs of both engines at the pixel centres, compared exactly: do the camera
// rays hit the same things (geometry), or is the difference in the shading? (2) The pixels
// compare found most significant. (3) Path logs of their first samples on both engines with one
// seed (the same paths), and pathdiff: the first vertex and field where the engines part, with
// both values.
#pragma once

#include "compare/compare.h"
#include "compare/exact.h"
#include "compare/pathdiff.h"
#include "verify/engine.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace tp {

// How many pixels are logged at most (in the order of pick_pixels, until one diverges at its
// first vertex, where no other can do better), and how many samples of each: the first
// diverging path shows in a few samples of any pixel a bug touches (a bug confined to some
// paths, such as glass seen through a caustic, needs the pixels where it shows, which the
// significance map gives).
constexpr size_t kTriagePixels = 3;
constexpr uint32_t kTriageSamples = 16;

struct PixelPick {
    uint32_t x = 0, y = 0;
    double z = 0;    // compare's per-pixel z of largest magnitude (significance_map.h)
    std::string why; // "most significant", "AOVs differ"
};

struct PixelPaths {
    PixelPick pixel;
    uint32_t samples = 0;   // logged samples 0 .. samples - 1
    EngineRun run_a, run_b; // their renders, with the logs
    nlohmann::json log_a, log_b;
    PathDiffResult diff;
};

struct Triage {
    EngineRun aov_a, aov_b;
    ExactResult aov;
    std::vector<PixelPaths> paths;
    // The divergence at the earliest vertex over the logged pixels (the most significant pixel
    // first among equals); none when every logged path agrees.
    std::optional<size_t> first;
};

// `r`: compare's result of a's image against b's; `seed`: both logs' seed (seeds.h);
// `max_depth`: the scene's, which bounds a path's records.
Triage triage(Engine& a, Engine& b, const CompareResult& r, uint32_t seed, uint32_t max_depth);

// The pixels to log: where the AOVs differ off silhouettes (the first such pixel), then the
// largest |z| of compare's pixel test, kTriagePixels in all, no pixel twice.
std::vector<PixelPick> pick_pixels(const CompareResult& r, const ExactResult& aov);

} // namespace tp
