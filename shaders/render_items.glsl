// The render invocations' work, for every entry point (render_compute.comp, render_pipeline.rgen):
// the dispatch's work items (interface.h: one sample of one pixel each), taken from a counter by
// whichever invocation is free, so that a subgroup keeps tracing while items are left however
// long its paths are. An invocation whose path has ended takes the next item while the others
// of its subgroup go on with theirs (path regeneration: Aila & Laine 2009, "Understanding the
// efficiency of ray traversal on GPUs", sec. 4, applied to whole paths as in Novák, Havran &
// Dachsbacher 2010, "Path regeneration for interactive path tracing"); the idle invocations of
// a subgroup take their items together, with one atomic add for all of them.
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

void render_items() {
    RayCounts total;
    total.camera = 0u;
    total.extension = 0u;
    total.shadow = 0u;
    RayCounts rays = total; // of the current item
    PathState st;
    uint item = 0u;
    uint taken = 0u;
    bool busy = false;
    for (;;) {
        if (!busy && taken == batch.items_per_invocation) break;
        uvec4 idle = subgroupBallot(!busy);
        uint n_idle = subgroupBallotBitCount(idle);
        uint n_live = subgroupBallotBitCount(subgroupBallot(true));
        if (!busy) {
            if (n_idle < min(REGEN_MIN_IDLE, n_live)) continue;
            ++taken;
            uint first = 0u;
            if (subgroupElect()) first = atomicAdd(counters[COUNTER_NEXT_ITEM], n_idle);
            item = subgroupBroadcastFirst(first) + subgroupBallotExclusiveBitCount(idle);
            if (item >= batch.item_count) break;
            uvec3 pixel = item_pixel(item, params.camera.width, batch.row_begin, batch.row_end);
            // An item without a pixel, or one a cut-short dispatch of this batch traced already.
            if (pixel.x >= params.camera.width ||
                floatBitsToUint(sample_radiance[item].w) == batch.sample_tag)
                continue;
            rays.camera = 0u;
            rays.extension = 0u;
            rays.shadow = 0u;
            uint sample_index = batch.sample_begin + pixel.z;
#ifdef TP_DEBUG_SHADER
            if (debug_header.integrator != INTEGRATOR_PATH) { // a debug view: no path to trace
                st.L = debug_view_radiance(pixel.x, pixel.y, sample_index);
                if (!loop_budget_held()) break;
                sample_radiance[item] = vec4(st.L, uintBitsToFloat(batch.sample_tag));
                continue;
            }
#endif
            st = path_begin(pixel.x, pixel.y, sample_index, rays);
            busy = true;
        }
        if (path_step(st, rays)) continue;
        busy = false;
        if (!loop_budget_held()) break; // the item stays untraced
        total.camera += rays.camera;
        total.extension += rays.extension;
        total.shadow += rays.shadow;
        sample_radiance[item] = vec4(st.L, uintBitsToFloat(batch.sample_tag));
    }
    counters_flush(total.camera, total.extension, total.shadow, 0u, 0u);
}

#endif // TP_SHADERS_RENDER_ITEMS_GLSL
