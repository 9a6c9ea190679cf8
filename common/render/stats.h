// Render statistics (`--stats file.json`, DESIGN.md): what ran, how long, how many rays of
// each kind, and how many samples were dropped as NaN/Inf.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace tp {

struct RayCounts {
    uint64_t camera = 0;
    uint64_t extension = 0; // BSDF-sampled continuation rays
    uint64_t shadow = 0;
    uint64_t total() const { return camera + extension + shadow; }
    RayCounts& operator+=(const RayCounts& o) {
        camera += o.camera;
        extension += o.extension;
        shadow += o.shadow;
        return *this;
    }
};

struct RenderStats {
    std::string scene;
    std::string backend; // "cpu" or "vulkan"
    std::string mode;    // vulkan: "compute" or "pipeline"; cpu: "embree"
    std::string device;
    uint32_t width = 0, height = 0;
    uint32_t spp = 0; // samples per pixel completed
    uint32_t seed = 0;
    uint32_t threads = 0;
    double wall_time_s = 0;  // rendering only, scene loading and acceleration build excluded
    double build_time_s = 0; // acceleration structure build
    double gpu_time_s = -1;  // from timestamp queries; < 0 when not measured
    RayCounts rays;
    uint64_t samples = 0;
    uint64_t nan_samples = 0; // NaN/Inf samples, dropped from the film
    uint64_t accel_bytes = 0; // BVH / acceleration structure memory
    // Scene features (scene/features.h): what the scene uses, and the variant of the path loop
    // that rendered it ("scene": specialized to those features; "all": every feature compiled in).
    std::vector<std::string> scene_features;
    std::string feature_variant;
    uint32_t feature_mask = 0;
    std::map<std::string, std::string> extra;

    double rays_per_second() const {
        return wall_time_s > 0 ? double(rays.total()) / wall_time_s : 0.0;
    }
};

void write_stats_json(const std::string& path, const RenderStats& s);

} // namespace tp
