// Render statistics (`--stats file.json`, docs/design.md): what ran, how long, how many rays of
// each kind, and how many samples were dropped as NaN/Inf.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <variant>
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

// What the Vulkan driver says about the render pipeline it created (docs/gpu.md, "Pipeline
// statistics"). VK_EXT_pipeline_creation_feedback, for one pipeline or one of its stages:
struct PipelineFeedback {
    std::string stage;      // "pipeline" for the whole pipeline, else "compute", "raygen", ...
    bool valid = false;     // VK_PIPELINE_CREATION_FEEDBACK_VALID_BIT: the rest is filled in
    bool cache_hit = false; // ..._APPLICATION_PIPELINE_CACHE_HIT_BIT: no compilation needed
    bool base_pipeline_acceleration = false; // ..._BASE_PIPELINE_ACCELERATION_BIT
    double duration_ms = 0;                  // the driver's time to create it
};

// VK_KHR_pipeline_executable_properties: one statistic of an executable, in the driver's
// format (VkPipelineExecutableStatisticFormatKHR: bool32, int64, uint64, float64).
struct PipelineStatistic {
    std::string name, description;
    std::variant<bool, int64_t, uint64_t, double> value;
};

// One executable the driver compiled the pipeline into (a shader stage, or several fused).
struct PipelineExecutable {
    std::vector<std::string> stages; // "compute", "raygen", "miss", "closest_hit", ...
    std::string name, description;
    uint32_t subgroup_size = 0;
    std::vector<PipelineStatistic> statistics;
};

struct PipelineReport {
    // The whole pipeline, then each stage; empty when the device lacks the extension.
    std::vector<PipelineFeedback> feedback;
    // `--pipeline-stats`: whether they were asked for, whether the device could give them
    // (when not, `statistics_note` says why), and the executables.
    bool statistics_requested = false;
    bool statistics_available = false;
    std::string statistics_note;
    std::vector<PipelineExecutable> executables;
};

// Sample indices [begin, end) of one seed's sequence (shared/rng.h).
struct SampleRange {
    uint32_t seed = 0;
    uint64_t begin = 0, end = 0;
    bool operator==(const SampleRange& o) const {
        return seed == o.seed && begin == o.begin && end == o.end;
    }
};

// One device's share of a render on several (the Vulkan engine's --device all).
struct DeviceShare {
    std::string device; // its name, with its index: "0: NVIDIA H200"
    uint32_t spp = 0;   // samples per pixel it traced
    std::vector<SampleRange> ranges;
    double wall_time_s = 0, gpu_time_s = -1;
    RayCounts rays;
    uint64_t samples = 0;
};

struct RenderStats {
    std::string scene;
    std::string backend; // "cpu" or "vulkan"
    std::string mode;    // vulkan: "compute" or "pipeline"; cpu: "embree"
    std::string device;
    uint32_t width = 0, height = 0;
    uint32_t spp = 0; // samples per pixel completed
    uint32_t seed = 0;
    std::string sampler; // render/sampler.h
    uint32_t threads = 0;
    double wall_time_s = 0;  // rendering only, scene loading and acceleration build excluded
    double build_time_s = 0; // acceleration structure build
    double gpu_time_s = -1;  // from timestamp queries; < 0 when not measured
    // Vulkan: the scene (and compute mode's BVH) copied to the device; < 0 for the CPU.
    double upload_time_s = -1;
    RayCounts rays;
    uint64_t samples = 0;
    uint64_t nan_samples = 0; // NaN/Inf samples, dropped from the film
    uint64_t accel_bytes = 0; // BVH / acceleration structure memory
    // Vulkan: the most device memory held at once from the mode's set-up to the film's read-back
    // (vulkan_rt/device/memory_tally.h); 0 for the CPU.
    uint64_t device_memory_peak_bytes = 0;
    // The scene's triangles: stored (each mesh once) and rendered (each mesh once per instance).
    uint64_t triangles_unique = 0, triangles_instanced = 0;
    // Scene features (scene/features.h): what the scene uses, and the variant of the path loop
    // that rendered it ("scene": specialized to those features; "all": every feature compiled in).
    std::vector<std::string> scene_features;
    std::string feature_variant;
    uint32_t feature_mask = 0;
    std::map<std::string, std::string> extra;
    std::optional<PipelineReport> pipeline; // Vulkan: the render pipeline
    // The samples traced; empty where the renderer leaves it to render_exr, which then records
    // [sample_offset, sample_offset + spp).
    std::vector<SampleRange> sample_ranges;
    std::vector<DeviceShare> devices; // several devices: each one's share

    double rays_per_second() const {
        return wall_time_s > 0 ? double(rays.total()) / wall_time_s : 0.0;
    }
};

struct FlatScene;
// Sets triangles_unique and triangles_instanced from the scene rendered.
void count_triangles(RenderStats& s, const FlatScene& scene);

// `--stats`: everything above but the pipeline's executables; of the pipeline report only the
// creation feedback (`pipeline_creation`).
void write_stats_json(const std::string& path, const RenderStats& s);

// The render pipeline of a Vulkan render as a JSON object (mode, feature variant and mask,
// creation feedback, executables with their statistics), for `--pipeline-stats` (docs/gpu.md);
// null for a render without one.
nlohmann::json pipeline_stats_json(const RenderStats& s);

// `twinpath render --pipeline-stats FILE`: the device, the scene and pipeline_stats_json.
void write_pipeline_stats_json(const std::string& path, const RenderStats& s);

} // namespace tp
