#include "vulkan_rt/device/vk_mode.h"

#include "util/error.h"

namespace tp {

const char* vk_mode_name(VkMode mode) {
    return mode == VkMode::pipeline ? "pipeline" : "compute";
}

std::optional<VkMode> parse_vk_mode(const std::string& word) {
    for (const VkMode m : {VkMode::compute, VkMode::pipeline})
        if (word == vk_mode_name(m)) return m;
    return std::nullopt;
}

const char* vk_mode_request_name(VkModeRequest request) {
    return request ? vk_mode_name(*request) : "auto";
}

VkModeRequest parse_vk_mode_request(const std::string& word) {
    if (word == vk_mode_request_name(std::nullopt)) return std::nullopt;
    if (const std::optional<VkMode> m = parse_vk_mode(word)) return m;
    input_error("--vk-mode {}: expected auto, compute or pipeline", word);
}

} // namespace tp
