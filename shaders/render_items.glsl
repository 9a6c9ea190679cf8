// The render invocations' work, for every entry point (render_compute.comp, render_pipeline.rgen):
// the dispatch's work items (interface.h: one sample of one pixel each), taken from a counter by
// whichever invocation is free, so that a subgroup keeps tracing while items are left however
// long its paths are. An invocation whose path has ended takes the next item while the others
// of its subgroup go on with theirs (path regeneration: Aila & Laine 2009, "Understanding the
// efficiency of ray traversal on GPUs", sec. 4, applied to whole paths as in Novák, Havran &
// Dachsbacher 2010, "Path regeneration for interactive path tracing"); the idle invocations of
// a subgroup take their items together, with one atomic add for all of them. That is the
// schedule where the launch is sized to what the device keeps resident (ITEM_SCHEDULE_COUNTER).
// Where the device does not say (lavapipe, which runs invocations one after another), a launch
// has one invocation per item, so there is nothing to regenerate and the subgroup votes and the
// atomic add would only cost: invocation i of n traces items i, i + n, ... to the end
// (ITEM_SCHEDULE_STRIDED). The host picks the schedule at pipeline creation, a specialization
// constant, so each device's compiler sees only its loop (vulkan_rt/render_loop/item_schedule.h).
//
// Each item's estimate goes to its slot in the sample buffer, in whatever order the items are
// traced; the resolve pass (resolve.comp) then sums every pixel's samples in sample order, so
// the film's bits do not depend on which invocation traced what, nor on how the render was cut
// into dispatches.
//
// Loop budget (loop_budget.glsl): when a path has ended, the probe checks that lavapipe's loop
// budget held while it ran; only then is its estimate written. Otherwise the invocation stops;
// the items it and the others left stay untraced (without the batch's tag), the resolve pass
// stops those pixels there, and the host repeats the dispatch, which traces just the items
// still untraced. Elsewhere the probe always passes.
#ifndef TP_SHADERS_RENDER_ITEMS_GLSL
#define TP_SHADERS_RENDER_ITEMS_GLSL

#extension GL_KHR_shader_subgroup_ballot : require

#include "counters.glsl"
#include "integrator.glsl"
#include "loop_budget.glsl"

// Idle invocations of a subgroup wait until at least this many of them (or all that are still
// in the loop) can take items together: taking items one lane at a time costs the open scenes
// more in fetches and divergent path starts than it saves, and waiting for a whole 32-wide
// subgroup keeps the closed scenes' long paths holding the rest (BENCHMARKS.md, `h200-fill`).
const uint REGEN_MIN_IDLE = 16u;

layout(constant_id = SPEC_ITEM_SCHEDULE) const uint item_schedule = ITEM_SCHEDULE_COUNTER;

// The item's estimate `L` with its tag, and its rays added to the invocation's.
void item_write(uint item, vec3 L, RayCounts rays, inout RayCounts total) {
    total.camera += rays.camera;
    total.extension += rays.extension;
    total.shadow += rays.shadow;
    sample_radiance[item] = vec4(L, uintBitsToFloat(batch.sample_tag));
}

// What item_start found.
const uint ITEM_SKIP = 0u; // nothing to trace: no pixel, traced already, or a debug view written
const uint ITEM_PATH = 1u; // a path to trace from `pixel`, sample `sample_index`
const uint ITEM_STOP = 2u; // the loop budget broke: the invocation stops

// Whether `item` has a path to trace (it has a pixel, and no cut-short dispatch of this batch
// traced it already), and its pixel and sample index. The path state stays with the caller:
// copied through a parameter, it made the loop slower on the H200 (docs/learnt.md, "Loop shapes
// for the item schedule").
uint item_start(uint item, out uvec3 pixel, out uint sample_index, inout RayCounts total) {
    pixel = item_pixel(item, params.camera.width, batch.row_begin, batch.row_end);
    sample_index = batch.sample_begin + pixel.z;
    if (pixel.x >= params.camera.width ||
        floatBitsToUint(sample_radiance[item].w) == batch.sample_tag)
        return ITEM_SKIP;
#ifdef TP_DEBUG_SHADER
    if (debug_header.integrator != INTEGRATOR_PATH) { // a debug view: no path to trace
        vec3 L = debug_view_radiance(pixel.x, pixel.y, sample_index);
        if (!loop_budget_held()) return ITEM_STOP;
        item_write(item, L, RayCounts(0u, 0u, 0u), total);
        return ITEM_SKIP;
    }
#endif
    return ITEM_PATH;
}

// `invocation` of `invocations`: the invocation's index in the one-dimensional launch and the
// launch's size.
void render_items(uint invocation, uint invocations) {
    // The cut-short count is the resolve pass's, which runs after this launch: it starts again
    // here, so that the host records no clear (and no barrier for it) before each launch.
    if (invocation == 0u) {
        counters[COUNTER_TRUNCATED] = 0u;
        counters[COUNTER_TRUNCATED + 1u] = 0u;
    }
    const RayCounts none = RayCounts(0u, 0u, 0u);
    RayCounts total = none;
    RayCounts rays = none; // of the current item
    PathState st;
    uvec3 pixel;
    uint sample_index;
    if (item_schedule == ITEM_SCHEDULE_STRIDED) {
        for (uint item = invocation; item < batch.item_count; item += invocations) {
            uint start = item_start(item, pixel, sample_index, total);
            if (start == ITEM_STOP) break;
            if (start == ITEM_SKIP) continue;
            rays = none;
            st = path_begin(pixel.x, pixel.y, sample_index, rays);
            while (path_step(st, rays)) {}
            if (!loop_budget_held()) break; // the item stays untraced
            item_write(item, st.L, rays, total);
        }
    } else {
        uint item = 0u;
        bool busy = false;
        for (;;) {
            uvec4 idle = subgroupBallot(!busy);
            uint n_idle = subgroupBallotBitCount(idle);
            uint n_live = subgroupBallotBitCount(subgroupBallot(true));
            if (!busy) {
                if (n_idle < min(REGEN_MIN_IDLE, n_live)) continue;
                uint first = 0u;
                if (subgroupElect()) first = atomicAdd(counters[COUNTER_NEXT_ITEM], n_idle);
                item = subgroupBroadcastFirst(first) + subgroupBallotExclusiveBitCount(idle);
                if (item >= batch.item_count) break;
                uint start = item_start(item, pixel, sample_index, total);
                if (start == ITEM_STOP) break;
                if (start == ITEM_SKIP) continue;
                rays = none;
                st = path_begin(pixel.x, pixel.y, sample_index, rays);
                busy = true;
            }
            if (path_step(st, rays)) continue;
            busy = false;
            if (!loop_budget_held()) break; // the item stays untraced
            item_write(item, st.L, rays, total);
        }
    }
    counters_flush(total.camera, total.extension, total.shadow, 0u, 0u);
}

#endif // TP_SHADERS_RENDER_ITEMS_GLSL
