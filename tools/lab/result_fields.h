// Fields of a bench result (bench.json) that the lab's tables, plots and markdown read the same
// way everywhere.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace tp::lab {

// Extension + shadow rays: the rays after the camera ray (thesis Table 5.3's secondary rays).
double secondary_rays(const nlohmann::json& rays);

// Whether the result holds a section ("ladder", "table", "peer", ...).
bool has_section(const nlohmann::json& result, const char* name);

// "cpu/embree", "vulkan/compute", "cpu/embree sobol": the backend, mode and (when not the
// default) sampler of a run.
std::string run_label(const nlohmann::json& run);

} // namespace tp::lab
