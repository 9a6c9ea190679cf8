#version 460
// The resolve pass after every render dispatch: each pixel slot of the dispatch's rows (one per
// film batch, interface.h) adds the batch's samples of its residue class to its double-precision
// sums, read from the sample buffer in increasing sample order, so that a slot's samples are
// added in sample order however the render was split into dispatches and whichever invocation
// traced them. NaN/Inf samples are counted and dropped (docs/design.md, "No silent NaN").
// A batch of n samples has samples in min(n, slots) residue classes, sample_begin + k for
// k < n: only those slots have an invocation, the others are left as they are (at one sample
// a frame, the viewer's, that is one slot of the Sobol sampler's eight).
//
// Precision: each sample is added to a double sum and sum of squares, so after n samples the
// relative rounding error of either is below n * 2^-53 (1e-10 at n = 10^6) and the variance
// that the host derives from them (sum_sq - sum * mean) keeps ~6 significant digits even when
// the pixel's mean is 10^3 times its standard deviation.
//
// A sample not yet traced (without the batch's tag: the dispatch was cut short,
// render_items.glsl, loop budget)
// stops its slot there: next_sample records it, the slot counts as cut short, and the repeated
// dispatch's resolve continues from it.
#extension GL_GOOGLE_include_directive : require

#include "bindings.glsl"
#include "counters.glsl"
#include "loop_budget.glsl"
#include "shared/math.h"

layout(local_size_x = RESOLVE_GROUP_SIZE) in;

// Samples read before any is added: independent loads in flight, since one invocation walks a
// whole slot and the sums must wait for each sample in turn.
const uint RESOLVE_CHUNK = 8u;

void main() {
    uint slots = accum_slots(params.sampler_id);
    uint batch_slots = resolve_slots(batch.sample_count, slots);
    uint width = params.camera.width;
    uint i = gl_GlobalInvocationID.x;
    uint nan = 0u;
    uint truncated = 0u;
    if (i < width * (batch.row_end - batch.row_begin) * batch_slots) {
        uint b = (batch.sample_begin + i % batch_slots) % slots;
        uint x = (i / batch_slots) % width;
        uint y = batch.row_begin + (i / batch_slots) / width;
        uint a = (y * width + x) * slots + b;
        // next_sample is 0 in a fresh accumulator, below a --sample-offset render's first
        // sample; then up to the first index of the slot's class.
        uint s = max(accum[a].next_sample, batch.sample_begin);
        s += (b + slots - s % slots) % slots;
        uint end = batch.sample_begin + batch.sample_count;
        dvec3 sum = accum[a].sum;
        dvec3 sum_sq = accum[a].sum_sq;
        uint n = accum[a].count;
        uint first = pixel_item(x, y, 0u, width, batch.row_begin, batch.row_end);
        uint stride = batch_tiled_pixels(width, batch.row_begin, batch.row_end);
        while (s < end && truncated == 0u) {
            vec4 chunk[RESOLVE_CHUNK];
            for (uint k = 0u; k < RESOLVE_CHUNK; ++k) {
                uint sk = min(s + k * slots, end - 1u);
                chunk[k] = sample_radiance[first + (sk - batch.sample_begin) * stride];
            }
            for (uint k = 0u; k < RESOLVE_CHUNK && s < end; ++k) {
                if (floatBitsToUint(chunk[k].w) != batch.sample_tag) {
                    truncated = 1u;
                    break;
                }
                vec3 L = chunk[k].xyz;
                s += slots;
                if (!is_finite3(L)) {
                    ++nan;
                    continue;
                }
                dvec3 d = dvec3(L);
                sum += d;
                sum_sq += d * d;
                ++n;
            }
        }
        // A slot whose loop the budget cut stops where it stopped, as one left untraced.
        if (!loop_budget_held()) truncated = 1u;
        accum[a].sum = sum;
        accum[a].sum_sq = sum_sq;
        accum[a].count = n;
        accum[a].next_sample = s;
    }
    // The render launch before this pass took its items; the next one starts from item 0.
    if (i == 0u) counters[COUNTER_NEXT_ITEM] = 0u;
    counters_flush(0u, 0u, 0u, nan, truncated);
}
