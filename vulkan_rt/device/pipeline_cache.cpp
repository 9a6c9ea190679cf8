#include "vulkan_rt/device/pipeline_cache.h"

#include "util/cache_dir.h"
#include "util/fnv1a.h"
#include "vulkan_rt/device/vk_error.h"

#include <fmt/core.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace fs = std::filesystem;

namespace tp {
namespace {

constexpr char kMagic[8] = {'T', 'P', 'P', 'C', 'A', 'C', 'H', 'E'};
constexpr uint32_t kFormat = 1;

// The file header, written field by field in host byte order (the file never leaves the
// machine whose driver wrote it).
struct FileHeader {
    char magic[8];
    uint32_t format;
    uint32_t vendor_id;
    uint32_t device_id;
    uint32_t driver_version;
    uint8_t uuid[VK_UUID_SIZE];
    uint64_t shader_hash;
    uint64_t data_bytes;
    uint64_t data_hash;
};
static_assert(sizeof(FileHeader) == 64, "no padding in the file header");

std::vector<uint8_t> read_file(const std::string& path, bool& exists) {
    std::ifstream in(path, std::ios::binary);
    exists = bool(in);
    if (!in) return {};
    return std::vector<uint8_t>((std::istreambuf_iterator<char>(in)),
                                std::istreambuf_iterator<char>());
}

} // namespace

uint64_t PipelineCacheKey::hash() const {
    uint64_t h = fnv1a64(&vendor_id, sizeof(vendor_id));
    h = fnv1a64(&device_id, sizeof(device_id), h);
    h = fnv1a64(&driver_version, sizeof(driver_version), h);
    h = fnv1a64(uuid.data(), uuid.size(), h);
    return fnv1a64(&shader_hash, sizeof(shader_hash), h);
}

std::string pipeline_cache_dir() {
    const std::string root = cache_dir();
    return root.empty() ? "" : (fs::path(root) / "pipelines").string();
}

std::vector<uint8_t> encode_pipeline_cache(const PipelineCacheKey& key,
                                           const std::vector<uint8_t>& data) {
    FileHeader h{};
    std::memcpy(h.magic, kMagic, sizeof(kMagic));
    h.format = kFormat;
    h.vendor_id = key.vendor_id;
    h.device_id = key.device_id;
    h.driver_version = key.driver_version;
    std::memcpy(h.uuid, key.uuid.data(), VK_UUID_SIZE);
    h.shader_hash = key.shader_hash;
    h.data_bytes = data.size();
    h.data_hash = fnv1a64(data.data(), data.size());
    std::vector<uint8_t> out(sizeof(h) + data.size());
    std::memcpy(out.data(), &h, sizeof(h));
    if (!data.empty()) std::memcpy(out.data() + sizeof(h), data.data(), data.size());
    return out;
}

bool decode_pipeline_cache(const std::vector<uint8_t>& file, const PipelineCacheKey& key,
                           std::vector<uint8_t>& data, std::string& reason) {
    data.clear();
    FileHeader h{};
    if (file.size() < sizeof(h)) {
        reason = "truncated header";
        return false;
    }
    std::memcpy(&h, file.data(), sizeof(h));
    if (std::memcmp(h.magic, kMagic, sizeof(kMagic)) != 0) {
        reason = "not a twinpath pipeline cache";
        return false;
    }
    if (h.format != kFormat) {
        reason = fmt::format("format {} (expected {})", h.format, kFormat);
        return false;
    }
    if (h.vendor_id != key.vendor_id || h.device_id != key.device_id ||
        h.driver_version != key.driver_version ||
        std::memcmp(h.uuid, key.uuid.data(), VK_UUID_SIZE) != 0) {
        reason = "written by another device or driver version";
        return false;
    }
    if (h.shader_hash != key.shader_hash) {
        reason = "written for other shaders";
        return false;
    }
    if (h.data_bytes != file.size() - sizeof(h)) {
        reason =
            fmt::format("{} data bytes, header says {}", file.size() - sizeof(h), h.data_bytes);
        return false;
    }
    if (fnv1a64(file.data() + sizeof(h), size_t(h.data_bytes)) != h.data_hash) {
        reason = "data does not match its hash (corrupt)";
        return false;
    }
    // The driver's own header (VkPipelineCacheHeaderVersionOne), checked as the driver would.
    if (h.data_bytes >= 32) {
        uint32_t words[4];
        std::memcpy(words, file.data() + sizeof(h), sizeof(words));
        if (words[1] != VK_PIPELINE_CACHE_HEADER_VERSION_ONE || words[2] != key.vendor_id ||
            words[3] != key.device_id ||
            std::memcmp(file.data() + sizeof(h) + 16, key.uuid.data(), VK_UUID_SIZE) != 0) {
            reason = "the driver's header names another device";
            return false;
        }
    }
    data.assign(file.begin() + sizeof(h), file.end());
    return true;
}

void add_cache_stats(const PipelineCacheUse& use, std::map<std::string, std::string>& extra) {
    extra["pipeline_cache"] = use.file.empty() ? "off" : use.hit ? "hit" : "miss";
    extra["pipeline_cache_file"] = use.file;
    extra["pipeline_create_ms"] = fmt::format("{:.3f}", use.create_s * 1e3);
    if (!use.note.empty()) extra["pipeline_cache_note"] = use.note;
}

PipelineCache::PipelineCache(const VulkanContext& ctx, uint64_t shader_hash)
    : device_(ctx.device()) {
    VkPhysicalDeviceProperties props{};
    vkGetPhysicalDeviceProperties(ctx.physical(), &props);
    key_.vendor_id = props.vendorID;
    key_.device_id = props.deviceID;
    key_.driver_version = props.driverVersion;
    std::memcpy(key_.uuid.data(), props.pipelineCacheUUID, VK_UUID_SIZE);
    key_.shader_hash = shader_hash;

    std::vector<uint8_t> data;
    const std::string dir = pipeline_cache_dir();
    if (!dir.empty()) {
        use_.file = (fs::path(dir) / fmt::format("{:016x}.bin", key_.hash())).string();
        bool exists = false;
        const std::vector<uint8_t> file = read_file(use_.file, exists);
        std::string reason;
        bool valid = false;
        if (exists && !(valid = decode_pipeline_cache(file, key_, data, reason))) {
            use_.note = fmt::format("ignored {}: {}", use_.file, reason);
            fmt::print(stderr, "twinpath: note: pipeline cache {}; it will be rewritten\n",
                       use_.note);
        }
        use_.hit = valid;
        use_.bytes_in = data.size();
    }
    VkPipelineCacheCreateInfo ci{};
    ci.sType = VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO;
    ci.initialDataSize = data.size();
    ci.pInitialData = data.empty() ? nullptr : data.data();
    vk_check(vkCreatePipelineCache(device_, &ci, nullptr, &cache_), "creating a pipeline cache");
}

PipelineCache::~PipelineCache() {
    if (cache_) vkDestroyPipelineCache(device_, cache_, nullptr);
}

void PipelineCache::save() {
    if (use_.file.empty()) return;
    size_t size = 0;
    std::vector<uint8_t> data;
    if (vkGetPipelineCacheData(device_, cache_, &size, nullptr) == VK_SUCCESS && size > 0) {
        data.resize(size);
        if (vkGetPipelineCacheData(device_, cache_, &size, data.data()) != VK_SUCCESS) data.clear();
        data.resize(std::min(size, data.size()));
    }
    use_.bytes_out = data.size();
    const std::vector<uint8_t> bytes = encode_pipeline_cache(key_, data);
    std::error_code ec;
    const fs::path path(use_.file);
    fs::create_directories(path.parent_path(), ec);
    const fs::path tmp = path.string() + fmt::format(".{}.tmp", getpid());
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        if (!out) {
            use_.note = fmt::format("cannot write {}", tmp.string());
            fmt::print(stderr, "twinpath: note: pipeline cache not saved: {}\n", use_.note);
            fs::remove(tmp, ec);
            return;
        }
    }
    fs::rename(tmp, path, ec);
    if (ec) {
        use_.note =
            fmt::format("cannot rename {} to {}: {}", tmp.string(), path.string(), ec.message());
        fmt::print(stderr, "twinpath: note: pipeline cache not saved: {}\n", use_.note);
        fs::remove(tmp, ec);
    }
}

} // namespace tp
