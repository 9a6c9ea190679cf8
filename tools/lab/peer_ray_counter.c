/* Counts the rays Embree's path tracer tutorial traces (twinpath-lab peer, peer_tutorial.h), so
 * that its rays/s is measured instead of inferred from ours. Loaded into the tutorial with LD_PRELOAD
 * for one untimed run: it wraps the only two trace calls the tutorial imports (nm -D
 * /usr/bin/pathtracer: rtcIntersect1 and rtcOccluded1; no packet or stream calls), counts them
 * and forwards to Embree, and at exit writes "<intersect> <occluded>" to the file named by
 * TWINPATH_RAY_COUNT_FILE. The scene, context and ray types are only passed through, so
 * Embree's headers are not needed. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>

typedef void (*TraceFn)(void* scene, void* context, void* ray);

static atomic_ullong intersect_count, occluded_count;
static TraceFn next_intersect, next_occluded; /* Embree's, resolved before main */

static TraceFn next_fn(const char* name) {
    TraceFn f = (TraceFn)dlsym(RTLD_NEXT, name);
    if (!f) {
        fprintf(stderr, "twinpath ray counter: %s not found\n", name);
        abort();
    }
    return f;
}

__attribute__((constructor)) static void resolve(void) {
    next_intersect = next_fn("rtcIntersect1");
    next_occluded = next_fn("rtcOccluded1");
}

void rtcIntersect1(void* scene, void* context, void* rayhit) {
    atomic_fetch_add_explicit(&intersect_count, 1, memory_order_relaxed);
    next_intersect(scene, context, rayhit);
}

void rtcOccluded1(void* scene, void* context, void* ray) {
    atomic_fetch_add_explicit(&occluded_count, 1, memory_order_relaxed);
    next_occluded(scene, context, ray);
}

__attribute__((destructor)) static void write_counts(void) {
    const char* path = getenv("TWINPATH_RAY_COUNT_FILE");
    FILE* f = path ? fopen(path, "w") : NULL;
    if (!f) return;
    fprintf(f, "%llu %llu\n", (unsigned long long)atomic_load(&intersect_count),
            (unsigned long long)atomic_load(&occluded_count));
    fclose(f);
}
