// The Vulkan engine's two modes (docs/design.md): software BVH traversal in a compute shader, or
// the ray-tracing pipeline, and the words that name them on the command line and in the outputs.
// Compute mode's BVH layout is a choice of its own (--bvh, compute_mode/bvh_builder.h). The enum
// lives with the device because what a device offers decides which modes it runs
// (device_info.h); the modes themselves are the layers above (compute_mode/, pipeline_mode/).
#pragma once

#include <optional>
#include <string>

namespace tp {

enum class VkMode { compute, pipeline };

// "compute" or "pipeline": the --vk-mode words, RenderStats::mode.
const char* vk_mode_name(VkMode mode);
// The mode a word names; nullopt for any other word.
std::optional<VkMode> parse_vk_mode(const std::string& word);

// What --vk-mode asks for: a mode, or none for auto (resolve_vk_mode picks pipeline where the
// device supports it, else compute).
using VkModeRequest = std::optional<VkMode>;

// "auto", "compute" or "pipeline".
const char* vk_mode_request_name(VkModeRequest request);
// The request a --vk-mode word names; InputError (exit code 2) for another word.
VkModeRequest parse_vk_mode_request(const std::string& word);

} // namespace tp
