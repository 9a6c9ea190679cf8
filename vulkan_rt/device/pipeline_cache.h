// Pipelines compiled once per feature set (scene features: docs/gpu.md, "Specialization to the
// scene's features", "Pipeline cache"): a VkPipelineCache kept on disk, one file per shader
// module set, so that the second render of a scene (or of another scene with the same features)
// skips the driver's compilation of the specialized pipeline.
//
// Where: pipelines/ in the cache directory (util/cache_dir.h, shared with the bench references);
// none without a cache directory. File name: a hash of the
// key below. The file is our header (magic, format version, the key, the data's size and hash)
// followed by the driver's vkGetPipelineCacheData bytes. The key is the shaders' hash (FNV-1a of
// the SPIR-V words) and the driver: vendorID, deviceID, driverVersion and pipelineCacheUUID.
// A file that is unreadable, truncated, corrupt or written by another driver or for other
// shaders is ignored with a note on stderr and replaced; it never fails a render. The cache is
// written atomically (temporary file + rename), so concurrent renders cannot tear it.
#pragma once

#include "vulkan_rt/device/context.h"

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace tp {

struct PipelineCacheKey {
    uint32_t vendor_id = 0;
    uint32_t device_id = 0;
    uint32_t driver_version = 0;
    std::array<uint8_t, VK_UUID_SIZE> uuid{};
    uint64_t shader_hash = 0;

    uint64_t hash() const;
};

// The cache directory (see above); "" when there is none.
std::string pipeline_cache_dir();

// The file bytes for `data` under `key`, and back: decode returns false with a reason for
// anything but an intact file written for exactly this key.
std::vector<uint8_t> encode_pipeline_cache(const PipelineCacheKey& key,
                                           const std::vector<uint8_t>& data);
bool decode_pipeline_cache(const std::vector<uint8_t>& file, const PipelineCacheKey& key,
                           std::vector<uint8_t>& data, std::string& reason);

// What happened with the cache for one pipeline (RenderStats extra: pipeline_cache*).
struct PipelineCacheUse {
    std::string file;     // "" when there is no cache directory
    bool hit = false;     // a valid file for this key was found and handed to the driver
    std::string note;     // why a file was ignored or not written
    double create_s = 0;  // vkCreate*Pipelines wall time
    size_t bytes_in = 0;  // driver data loaded
    size_t bytes_out = 0; // driver data written
};

// RenderStats::extra entries: pipeline_cache (hit, miss, off), pipeline_cache_file,
// pipeline_create_ms, pipeline_cache_note.
void add_cache_stats(const PipelineCacheUse& use, std::map<std::string, std::string>& extra);

// One VkPipelineCache, loaded from its file on construction; save() writes it back.
class PipelineCache {
  public:
    PipelineCache(const VulkanContext& ctx, uint64_t shader_hash);
    ~PipelineCache();
    PipelineCache(const PipelineCache&) = delete;
    PipelineCache& operator=(const PipelineCache&) = delete;

    VkPipelineCache handle() const { return cache_; }
    void save();
    PipelineCacheUse& use() { return use_; }

  private:
    VkDevice device_;
    PipelineCacheKey key_;
    VkPipelineCache cache_ = VK_NULL_HANDLE;
    PipelineCacheUse use_;
};

} // namespace tp
