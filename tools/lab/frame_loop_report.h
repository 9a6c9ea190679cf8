// The report of a `twinpath bench --frame-loop` result (bench/frame_loop.h).
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace tp::lab {

// The markdown of the section: one row per scene, backend/mode and samples per frame (median and
// mean ms per frame, the GPU's passes and the host's share), and per scene and backend the fixed
// cost of a frame (frame_loop_fixed_ms).
std::string frame_loop_section(const nlohmann::json& result);

// A frame's cost at zero samples on the line through the mean ms per frame of the points with
// the fewest and the most samples per frame; null with fewer than two sample counts.
nlohmann::json frame_loop_fixed_ms(const nlohmann::json& run);

} // namespace tp::lab
