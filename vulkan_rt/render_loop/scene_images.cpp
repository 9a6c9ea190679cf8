#include "vulkan_rt/render_loop/scene_images.h"

#include "shared/features.h"
#include "util/error.h"

#include <algorithm>

namespace tp {
namespace {

static_assert(IMAGE_SLOTS == 64, "shaders/scene_access.glsl's switch has a case for each of 64 "
                                 "image slots (TP_IMAGE_CASES_8, eight times)");

VkFormat image_format(uint32_t format) {
    return format == TEXEL_RGBA8    ? VK_FORMAT_R8G8B8A8_UINT
           : format == TEXEL_RGBA16 ? VK_FORMAT_R16G16B16A16_UINT
                                    : VK_FORMAT_R32G32B32A32_UINT;
}

double mib(uint64_t bytes) {
    return double(bytes) / 1048576.0;
}

} // namespace

ImageLimits image_limits(const VulkanContext& ctx) {
    ImageLimits l;
    l.device = ctx.info().name;
    l.max_images = IMAGE_SLOTS;
    l.max_dimension = ctx.limits().maxImageDimension2D;
    VkPhysicalDeviceMaintenance3Properties m3{};
    m3.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES;
    VkPhysicalDeviceProperties2 p2{};
    p2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
    p2.pNext = &m3;
    vkGetPhysicalDeviceProperties2(ctx.physical(), &p2);
    l.max_image_bytes = m3.maxMemoryAllocationSize;
    for (uint32_t format : {TEXEL_RGBA8, TEXEL_RGBA16, TEXEL_RGBA32F}) {
        VkImageFormatProperties fp{};
        const VkResult r = vkGetPhysicalDeviceImageFormatProperties(
            ctx.physical(), image_format(format), VK_IMAGE_TYPE_2D, VK_IMAGE_TILING_OPTIMAL,
            VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, 0, &fp);
        // Every device samples these formats (Vulkan's mandatory format support).
        if (r != VK_SUCCESS) continue;
        l.max_dimension = std::min({l.max_dimension, fp.maxExtent.width, fp.maxExtent.height});
        l.max_image_bytes = std::min<uint64_t>(l.max_image_bytes, fp.maxResourceSize);
    }
    // The largest device-local heap, where images go (Image prefers device-local memory).
    VkPhysicalDeviceMemoryBudgetPropertiesEXT budget{};
    budget.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_BUDGET_PROPERTIES_EXT;
    VkPhysicalDeviceMemoryProperties2 mp{};
    mp.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MEMORY_PROPERTIES_2;
    const bool has_budget = ctx.info().caps.has(VK_EXT_MEMORY_BUDGET_EXTENSION_NAME);
    if (has_budget) mp.pNext = &budget;
    vkGetPhysicalDeviceMemoryProperties2(ctx.physical(), &mp);
    for (uint32_t i = 0; i < mp.memoryProperties.memoryHeapCount; ++i) {
        const VkMemoryHeap& h = mp.memoryProperties.memoryHeaps[i];
        if (!(h.flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)) continue;
        const uint64_t b = has_budget ? budget.heapBudget[i] : h.size;
        if (b > l.memory_budget) l.memory_budget = b;
    }
    l.memory_budget_source = has_budget ? "budget" : "size";
    return l;
}

uint64_t image_bytes(const TextureInfo& info) {
    return uint64_t(info.width) * info.height * words_per_texel(info.format) * 4;
}

void check_images(const std::vector<Texture>& images, const ImageLimits& l) {
    if (images.size() > l.max_images) {
        const Texture& t = images[l.max_images];
        runtime_error("texture {} is image {} of the scene's {}: the Vulkan engine binds at most "
                      "{} images (IMAGE_SLOTS, shaders/interface.h; docs/gpu.md, \"Textures\"); "
                      "render with --backend cpu, or use fewer images",
                      t.describe(), l.max_images + 1, images.size(), l.max_images);
    }
    uint64_t total = 0;
    for (const Texture& t : images) {
        const uint32_t side = std::max(t.width, t.height);
        if (side > l.max_dimension)
            runtime_error("texture {} is {} texels {}, more than the largest 2D image {} holds "
                          "(maxImageDimension2D {}); scale it down to {} or render with "
                          "--backend cpu",
                          t.describe(), side, t.width >= t.height ? "wide" : "tall", l.device,
                          l.max_dimension, l.max_dimension);
        const uint64_t bytes = image_bytes({t.width, t.height, t.format, 0});
        if (bytes > l.max_image_bytes)
            runtime_error("texture {} takes {:.1f} MiB, more than one image of {} holds "
                          "({:.1f} MiB: maxMemoryAllocationSize and the format's "
                          "maxResourceSize); scale it down or render with --backend cpu",
                          t.describe(), mib(bytes), l.device, mib(l.max_image_bytes));
        total += bytes;
        if (total > l.memory_budget)
            runtime_error("texture {} ({:.1f} MiB) brings the scene's images to {:.1f} MiB, more "
                          "than the {:.1f} MiB of device memory {} has (its device-local heap's "
                          "{}); use smaller images or render with --backend cpu",
                          t.describe(), mib(bytes), mib(total), mib(l.memory_budget), l.device,
                          l.memory_budget_source);
    }
}

bool reads_images(uint32_t features) {
    return feature_on(features, FEATURE_TEXTURES) || feature_on(features, FEATURE_ENV_MAP);
}

void check_scene_images(const VulkanContext& ctx, const FlatScene& scene, uint32_t features) {
    if (reads_images(features) && !scene.images.empty())
        check_images(scene.images, image_limits(ctx));
}

SceneImages upload_scene_images(const VulkanContext& ctx, const FlatScene& scene,
                                uint32_t features) {
    check_scene_images(ctx, scene, features);
    SceneImages si;
    const bool used = reads_images(features);
    std::vector<ImageTexels> texels;
    si.images.reserve(scene.images.size() + 1);
    if (used)
        for (const Texture& t : scene.images) {
            si.images.emplace_back(ctx, t.width, t.height, image_format(t.format));
            si.bytes += si.images.back().memory_bytes();
            texels.push_back({&si.images.back(), t.words.data(), words_per_texel(t.format) * 4});
        }
    si.count = uint32_t(si.images.size());
    const uint32_t zero = 0;
    si.images.emplace_back(ctx, 1, 1, VK_FORMAT_R8G8B8A8_UINT); // the placeholder
    texels.push_back({&si.images.back(), &zero, 4});
    upload_images(ctx, texels);
    for (const Image& im : si.images) si.views.push_back(im.view());
    si.views.resize(IMAGE_SLOTS, si.images.back().view());
    return si;
}

} // namespace tp
