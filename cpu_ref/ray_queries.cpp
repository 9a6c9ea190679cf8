#include "cpu_ref/ray_queries.h"

#include "cpu_ref/embree_accel.h"

namespace tp {

ClosestHits closest_hits_cpu(const FlatScene& scene, const std::vector<Ray>& rays) {
    const EmbreeAccel embree(scene);
    ClosestHits out{std::vector<float>(rays.size()), std::vector<uint8_t>(rays.size())};
    for (size_t i = 0; i < rays.size(); ++i) {
        const Hit h = embree.intersect(rays[i]);
        out.found[i] = h.found;
        out.t[i] = h.t;
    }
    return out;
}

} // namespace tp
