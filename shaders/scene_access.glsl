// The GPU engine's scene reads: the storage buffers of bindings.glsl under the names that
// shared/scene_access.h reads, the scene's images, the feature mask as a specialization
// constant (features.glsl), and its hooks.
#ifndef TP_SHADERS_SCENE_ACCESS_GLSL
#define TP_SHADERS_SCENE_ACCESS_GLSL

// texelFetch from a texture without a sampler: no filtering happens in the hardware.
#extension GL_EXT_samplerless_texture_functions : require

#include "bindings.glsl"
#include "features.glsl"
#include "shared/alpha.h"
#include "shared/lights.h"
#include "shared/path.h"
#include "shared/surface.h"
#include "shared/texture.h"
#include "trace_hit.glsl"

// Computed at each hit: a buffer of them would be one more read per hit.
InstanceErrorTerms scene_error_terms(uint instance) {
    return instance_error_terms(instances[instance]);
}

uint scene_env_table_size() {
    return batch.env_table_size;
}

// The scene's images (interface.h, BINDING_IMAGES), each an integer image of its texel words'
// bytes (TEXEL_RGBA8: R8G8B8A8_UINT, TEXEL_RGBA16: R16G16B16A16_UINT, TEXEL_RGBA32F:
// R32G32B32A32_UINT of the float bits; vulkan_rt/render_loop/scene_images.h), so that a fetch
// returns exactly the channels the CPU reads from the words and the shared code decodes both
// alike (shared/texture.h, texel_channels_value): a UNORM or float view would let the device
// convert and, for integers, round its own way.
layout(set = 0, binding = BINDING_IMAGES) uniform utexture2D scene_images[IMAGE_SLOTS];
// How many of the slots hold the scene's images: the cases past it fold away when the pipeline
// is specialized, so a scene with few images compiles few fetches.
layout(constant_id = SPEC_IMAGE_COUNT) const uint scene_image_count = IMAGE_SLOTS;

// The array is indexed by constants only: Vulkan's image arrays need a dynamically uniform index
// (shaderSampledImageArrayDynamicIndexing) or descriptor indexing's non-uniform one, and
// neither is on every device (not on lavapipe); a switch of constant indices runs everywhere,
// and a wave whose invocations read several images takes each of their cases in turn, as a
// non-uniform index would.
#define TP_IMAGE_CASE(k)                                                                         \
    case k:                                                                                      \
        if (k < scene_image_count) c = texelFetch(scene_images[k], p, 0);                        \
        break;
#define TP_IMAGE_CASES_8(k)                                                                      \
    TP_IMAGE_CASE(k) TP_IMAGE_CASE(k + 1u) TP_IMAGE_CASE(k + 2u) TP_IMAGE_CASE(k + 3u)           \
    TP_IMAGE_CASE(k + 4u) TP_IMAGE_CASE(k + 5u) TP_IMAGE_CASE(k + 6u) TP_IMAGE_CASE(k + 7u)

uvec4 scene_texel(uint image, TextureInfo info, uint i) {
    ivec2 p = ivec2(int(i % info.width), int(i / info.width));
    uvec4 c = uvec4(0u);
    switch (image) {
        TP_IMAGE_CASES_8(0u)
        TP_IMAGE_CASES_8(8u)
        TP_IMAGE_CASES_8(16u)
        TP_IMAGE_CASES_8(24u)
        TP_IMAGE_CASES_8(32u)
        TP_IMAGE_CASES_8(40u)
        TP_IMAGE_CASES_8(48u)
        TP_IMAGE_CASES_8(56u)
    }
    return c;
}

#include "shared/scene_access.h"

#endif // TP_SHADERS_SCENE_ACCESS_GLSL
