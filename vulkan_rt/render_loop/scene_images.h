// The scene's images on the device: each image (FlatScene::images, TextureInfo i is image i) a
// VkImage of its own in device-local memory, optimal tiling, of the integer format whose bytes
// are its texel words (TEXEL_RGBA8: R8G8B8A8_UINT, TEXEL_RGBA16: R16G16B16A16_UINT,
// TEXEL_RGBA32F: R32G32B32A32_UINT of the float bits), bound as the IMAGE_SLOTS sampled images
// of BINDING_IMAGES (shaders/interface.h) and read with texelFetch (shaders/scene_access.glsl):
// the shared code fetches, decodes and filters on both engines alike. The environment map is
// one of them. Slots past the scene's images hold a 1 x 1 placeholder, as does every slot of a
// render that reads no image (no textures or environment map in its feature mask).
//
// Before anything is built or uploaded, every image is checked against what the device and the
// engine can hold (ImageLimits): a texture that cannot fit is a RuntimeError (exit code 3: the
// device cannot run this scene; the CPU engine can) naming the texture, its size and the limit.
#pragma once

#include "scene/flatten.h"
#include "shaders/interface.h"
#include "vulkan_rt/device/context.h"
#include "vulkan_rt/device/image.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tp {

// What a device holds of the scene's images.
struct ImageLimits {
    std::string device;               // its name, for the messages
    uint32_t max_images = 0;          // images one render binds: IMAGE_SLOTS
    uint32_t max_dimension = 0;       // maxImageDimension2D, and the formats' maxExtent
    uint64_t max_image_bytes = 0;     // maxMemoryAllocationSize, the formats' maxResourceSize
    uint64_t memory_budget = 0;       // the device-local heap: its budget (VK_EXT_memory_budget),
                                      // or its size
    std::string memory_budget_source; // "budget" or "size" of the heap
};

// The device's limits (the sampled-image descriptor limits are compute mode's requirement:
// device_info.h, compute_mode_missing).
ImageLimits image_limits(const VulkanContext& ctx);

// The device memory an image takes: its texels' bytes (an optimal-tiling image may take a
// little more; the device's own figure is Image::memory_bytes).
uint64_t image_bytes(const TextureInfo& info);

// Throws RuntimeError naming the first image of `images` that does not fit `limits`: one image
// too many, too wide or tall, too large for one allocation, or the one with which the images
// outgrow the memory budget. Pure: tests give it limits of their own.
void check_images(const std::vector<Texture>& images, const ImageLimits& limits);

// Whether a render with feature mask `features` reads the scene's images: textures or an
// environment map.
bool reads_images(uint32_t features);

struct SceneImages {
    std::vector<Image> images;      // the scene's, in TextureInfo order, then the placeholder
    std::vector<VkImageView> views; // IMAGE_SLOTS views: the scene's images, then the placeholder
    uint32_t count = 0;             // the scene's images bound (SPEC_IMAGE_COUNT)
    uint64_t bytes = 0;             // device memory of the scene's images
};

// Checks (check_images) and uploads the scene's images where `features` reads them.
SceneImages upload_scene_images(const VulkanContext& ctx, const FlatScene& scene,
                                uint32_t features);

// Checks the scene's images against the device where `features` reads them: what a render does
// before any other work (the BVH build, the uploads).
void check_scene_images(const VulkanContext& ctx, const FlatScene& scene, uint32_t features);

} // namespace tp
