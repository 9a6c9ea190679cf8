#include "cpu_ref/ray_queries.h"

#include "cpu_ref/embree_accel.h"

namespace tp {

ClosestHits closest_hits_cpu(const FlatScene& scene, const std::vector<Ray>& rays) {
    const EmbreeAccel embree(scene);
    ClosestHits out(rays.size());
    for (size_t i = 0; i < rays.size(); ++i) {
        const Hit h = embree.intersect(rays[i], nullptr);
        out.found[i] = h.found;
        out.t[i] = h.t;
        out.instance[i] = h.instance;
        out.primitive[i] = h.primitive;
        out.bary[i] = h.bary;
        out.occluded[i] = embree.occluded(rays[i], nullptr);
    }
    return out;
}

} // namespace tp
