#include "cpu_ref/ray_queries.h"

#include "cpu_ref/cpu_engine.h"
#include "cpu_ref/embree_accel.h"

namespace tp {

ClosestHits closest_hits_cpu(const FlatScene& scene, const std::vector<Ray>& rays,
                             uint32_t features) {
    const EmbreeAccel embree(scene);
    const CpuSceneState state(scene, 0, SAMPLER_RANDOM);
    // The engine's trace hooks: Embree with the alpha test where the features ask for it.
    const CpuEngine<0, false> engine(state, embree, features);
    ClosestHits out(rays.size());
    for (size_t i = 0; i < rays.size(); ++i) {
        Hit h;
        engine.trace_closest(rays[i], h);
        out.found[i] = h.found;
        out.t[i] = h.t;
        out.instance[i] = h.instance;
        out.primitive[i] = h.primitive;
        out.bary[i] = h.bary;
        out.occluded[i] = engine.trace_occluded(rays[i]);
    }
    return out;
}

} // namespace tp
