// Russian roulette, thesis sec. 2.6.2: after min_depth bounces the path survives with
// probability q = max_rgb(T), eq. 2.42, where T is the throughput so far (which already holds
// the 1/q of earlier survivals), and a survivor is divided by q (eq. 2.41 with c = 0), so the
// estimator stays unbiased. q is capped at 1. The hard maximum depth is the caller's loop bound.
#ifndef TP_SHARED_ROULETTE_H
#define TP_SHARED_ROULETTE_H

#include "math.h"

TP_NAMESPACE_BEGIN

// Survival probability after `bounces` scattering events.
inline float roulette_survival(vec3 throughput, uint bounces, uint min_depth) {
    if (bounces < min_depth) return 1.0f;
    return min(max3(throughput), 1.0f);
}

// Applies the roulette with the uniform number u; returns false when the path is terminated.
inline bool roulette_apply(INOUT(vec3) throughput, uint bounces, uint min_depth, float u) {
    float q = roulette_survival(throughput, bounces, min_depth);
    if (q >= 1.0f) return true;
    if (!(u < q)) return false;
    throughput = throughput / q;
    return true;
}

TP_NAMESPACE_END

#endif // TP_SHARED_ROULETTE_H
