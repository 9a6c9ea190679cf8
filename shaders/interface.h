// The interface between the Vulkan host code and the render shaders: descriptor binding slots,
// the push constants of one batch, the per-pixel accumulator and the ray counters. Written in
// the shared-header dialect (common/shared/lang.h) so that vulkan_rt/ and shaders/ read the
// same numbers. Every binding is a storage buffer in descriptor set 0, except the scene's images
// (an array of sampled images in slot 15) and the pipeline mode's TLAS (an
// acceleration-structure descriptor in slot 16, where compute mode has its BVH).
#ifndef TP_SHADERS_INTERFACE_H
#define TP_SHADERS_INTERFACE_H

#include "shared/lang.h"
#include "shared/rng.h"

TP_NAMESPACE_BEGIN

#ifdef __cplusplus
using dvec3 = glm::dvec3;
#endif

// ---- descriptor set 0 ------------------------------------------------------------------------
const uint BINDING_PARAMS = 0u;         // RenderParams
const uint BINDING_MATERIALS = 1u;      // Material[]
const uint BINDING_INSTANCES = 2u;      // Instance[]
const uint BINDING_MESHES = 3u;         // MeshInfo[] (bvh_root filled in)
const uint BINDING_POSITIONS = 4u;      // vec3[]
const uint BINDING_NORMALS = 5u;        // vec3[], parallel to positions (dummy without normals)
const uint BINDING_UVS = 6u;            // vec2[], parallel to positions (dummy without uvs)
const uint BINDING_TRIANGLES = 7u;      // uvec3[], mesh-local vertex indices
const uint BINDING_LIGHTS = 8u;         // Light[]
const uint BINDING_LIGHT_TABLE = 9u;    // AliasEntry[], light selection
const uint BINDING_TEXTURES = 10u;      // TextureInfo[]: the images' sizes and formats
const uint BINDING_TEXTURE_SLOTS = 11u; // TextureSlot[]: how materials read the images
const uint BINDING_ENV_TABLE = 12u;     // AliasEntry[], environment-map pixels
const uint BINDING_UVS1 = 13u;          // vec2[], the second uv set (dummy without one)
const uint BINDING_TANGENTS = 14u;      // vec4[], normal maps' tangents (dummy without normal maps)
const uint BINDING_SCENE_COUNT = 15u;   // the scene's storage buffers: 0 .. 14
// The scene's images (TextureInfo[i] is image i), IMAGE_SLOTS sampled images of integer formats
// read with texelFetch (shaders/scene_access.glsl); slots past the scene's images hold a
// placeholder (vulkan_rt/render_loop/scene_images.h).
const uint BINDING_IMAGES = 15u;
const uint BINDING_BVH_NODES = 16u; // BvhNode[] (compute mode)
const uint BINDING_BVH_TRIS = 17u;  // BvhTriangle[] (compute mode)
const uint BINDING_TLAS = 16u;      // top-level acceleration structure (pipeline mode; no 17)
const uint BINDING_ACCUM = 18u;     // PixelAccum[width * height]
const uint BINDING_COUNTERS = 19u;  // uint[COUNTER_WORDS]
const uint BINDING_DEBUG = 20u;     // DebugHeader + PathVertex[] (debug variant only)
const uint BINDING_AOV = 21u;       // PixelAov[width * height] (debug variant only)
const uint BINDING_SAMPLES = 22u;   // vec4[]: one batch's sample estimates, by work item
const uint BINDING_COUNT = 23u;

// The images a render binds at most: a fixed-size array read through constant indices (the
// switch of shaders/scene_access.glsl has a case for each), which every Vulkan device supports
// (Mesa lavapipe has neither descriptor indexing nor dynamically indexed image arrays). 64 stays
// within lavapipe's 128 sampled images and 128 resources per stage beside the storage buffers.
const uint IMAGE_SLOTS = 64u;

// ---- specialization constants (shaders/features.glsl, render_items.glsl, scene_access.glsl) --
const uint SPEC_SCENE_FEATURES = 0u; // uint: the FEATURE_* mask the path loop is compiled for
const uint SPEC_ITEM_SCHEDULE = 1u;  // uint: ITEM_SCHEDULE_*, how invocations take work items
const uint SPEC_IMAGE_COUNT = 2u;    // uint: the scene's images, at most IMAGE_SLOTS

// How the render invocations take the dispatch's work items (render_items.glsl).
const uint ITEM_SCHEDULE_COUNTER = 0u; // from a counter, a new one when a path ends (regeneration)
const uint ITEM_SCHEDULE_STRIDED = 1u; // invocation i of n: items i, i + n, i + 2n, ...

// ---- push constants of one dispatch ----------------------------------------------------------
// The dispatch covers rows [row_begin, row_end) of the image, every column, and samples
// [sample_begin, sample_begin + sample_count) of each of those pixels: item_count work items
// (batch_item_count), each one sample of one pixel (item_pixel), which the render shader's
// invocations take in any order (ITEM_SCHEDULE_*) and the resolve pass sums in sample order.
// Each accumulator slot of a pixel continues from max(next_sample, sample_begin) (PixelAccum),
// rounded up to the slot's residue class: next_sample is already the first index of that class
// at or after sample_begin, unless a dispatch of this batch was cut short (render_items.glsl, loop
// budget) and is being repeated (then it is later), or it is still 0 before the first batch of
// a render that starts at a --sample-offset.
struct BatchParams {
    uint sample_begin;
    uint sample_count;
    uint row_begin;
    uint row_end;
    uint bvh_top_root;     // compute mode: the top-level root node
    uint env_table_size;   // entries of the environment-map pixel table (0: none)
    uint probe_iterations; // LOOP_PROBE_ITERATIONS (shaders/render_items.glsl)
    uint item_count;       // batch_item_count of the rows and samples above
    // Marks the batch's estimates in the sample buffer: an item whose slot carries another tag
    // is not traced yet (a batch takes a new tag; its repeated dispatches keep it).
    uint sample_tag;
};

const uint LOOP_PROBE_ITERATIONS = 2u;

// ---- accumulation ----------------------------------------------------------------------------
// Per pixel, in double precision: the sum and the sum of squares of its finite samples and how
// many there were, and the index of the next sample to trace. The host merges them into the
// Film with Film::add_batch (Chan et al.). With the Sobol sampler a pixel has one PixelAccum
// per batch (sample s in slot s mod SOBOL_BATCHES, pixel-major), for the batch estimator of the
// variance (render/film.h); every slot keeps the next sample of its own class.
struct PixelAccum {
    dvec3 sum;
    dvec3 sum_sq;
    uint count;
    uint next_sample;
};

inline uint accum_slots(uint sampler_id) {
    return sampler_id == SAMPLER_SOBOL ? SOBOL_BATCHES : 1u;
}

// The slots of a pixel that a batch of `sample_count` samples adds to: one per residue class
// its samples fall in (resolve.comp).
inline uint resolve_slots(uint sample_count, uint slots) {
    return min(sample_count, slots);
}

// ---- work items -------------------------------------------------------------------------------
// A dispatch's items, in order: sample by sample, and within a sample the rows' pixels in tiles
// of ITEM_TILE_X x ITEM_TILE_Y (one 32-wide subgroup's camera rays stay as coherent as an 8 x 4
// block of pixels), tiles in row-major order. Tiles that overhang the image or the rows give
// items without a pixel, which the render shader skips.
const uint ITEM_TILE_X = 8u;
const uint ITEM_TILE_Y = 4u;
const uint ITEM_TILE_PIXELS = ITEM_TILE_X * ITEM_TILE_Y;

// The items of one sample of rows [row_begin, row_end) of an image `width` pixels wide.
inline uint batch_tiled_pixels(uint width, uint row_begin, uint row_end) {
    uint tiles_x = (width + ITEM_TILE_X - 1u) / ITEM_TILE_X;
    uint tiles_y = (row_end - row_begin + ITEM_TILE_Y - 1u) / ITEM_TILE_Y;
    return tiles_x * tiles_y * ITEM_TILE_PIXELS;
}

inline uint batch_item_count(uint width, uint row_begin, uint row_end, uint sample_count) {
    return batch_tiled_pixels(width, row_begin, row_end) * sample_count;
}

// Item `item` of a dispatch: its pixel (x, y) in .xy and its sample (sample_begin + .z); .x is
// `width` or more for an item without a pixel.
inline uvec3 item_pixel(uint item, uint width, uint row_begin, uint row_end) {
    uint per_sample = batch_tiled_pixels(width, row_begin, row_end);
    uint i = item % per_sample;
    uint tile = i / ITEM_TILE_PIXELS;
    uint lane = i % ITEM_TILE_PIXELS;
    uint tiles_x = (width + ITEM_TILE_X - 1u) / ITEM_TILE_X;
    uint x = (tile % tiles_x) * ITEM_TILE_X + lane % ITEM_TILE_X;
    uint y = row_begin + (tile / tiles_x) * ITEM_TILE_Y + lane / ITEM_TILE_X;
    return uvec3(y < row_end ? x : width, y, item / per_sample);
}

// The item of pixel (x, y) and sample sample_begin + j: the inverse of item_pixel.
inline uint pixel_item(uint x, uint y, uint j, uint width, uint row_begin, uint row_end) {
    uint tiles_x = (width + ITEM_TILE_X - 1u) / ITEM_TILE_X;
    uint r = y - row_begin;
    uint tile = (r / ITEM_TILE_Y) * tiles_x + x / ITEM_TILE_X;
    uint lane = (r % ITEM_TILE_Y) * ITEM_TILE_X + x % ITEM_TILE_X;
    return j * batch_tiled_pixels(width, row_begin, row_end) + tile * ITEM_TILE_PIXELS + lane;
}

// An item's slot in the BINDING_SAMPLES array: its sample's radiance in .xyz and, in .w, the
// bits of the batch's sample_tag once it is traced.

// Ray and sample counters, each a 64-bit value as (low, high) 32-bit words so that any Vulkan
// device can add to them with 32-bit atomics and an explicit carry. COUNTER_TRUNCATED counts
// the pixel slots that the last dispatch's resolve pass left before their last sample; the
// render launch before that pass clears it. COUNTER_NEXT_ITEM (one word) is the next item a
// render invocation takes; the resolve pass after the launch clears it for the next one. The
// host clears all of them when an accumulation starts.
const uint COUNTER_CAMERA = 0u;
const uint COUNTER_EXTENSION = 2u;
const uint COUNTER_SHADOW = 4u;
const uint COUNTER_NAN = 6u;
const uint COUNTER_TRUNCATED = 8u;
const uint COUNTER_NEXT_ITEM = 10u;
const uint COUNTER_WORDS = 11u;

const uint RENDER_GROUP_SIZE = 64u; // render invocations per workgroup (compute mode)
const uint RESOLVE_GROUP_SIZE = 64u;

#ifdef __cplusplus
static_assert(sizeof(BatchParams) == 36, "BatchParams layout");
static_assert(sizeof(PixelAccum) == 56 && offsetof(PixelAccum, next_sample) == 52,
              "PixelAccum layout");
#endif

TP_NAMESPACE_END

#endif // TP_SHADERS_INTERFACE_H
