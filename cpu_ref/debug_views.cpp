#include "cpu_ref/debug_views.h"

#include <chrono>

namespace tp {

PixelAov CpuDebugViews::primary_aov(const Ray& ray) const {
    Engine engine(state_, accel_, FEATURES_ALL);
    return engine.primary_aov(ray);
}

vec3 CpuDebugViews::radiance(uint32_t x, uint32_t y, uint32_t sample_index) const {
    const RenderParams& P = state_.params;
    const RngKey key = rng_key(P.sampler_id, P.seed, y * P.camera.width + x, sample_index);
    const Ray ray = camera_ray(P.camera, key, x, y);
    if (integrator_ == INTEGRATOR_COST) {
        const auto t0 = std::chrono::steady_clock::now();
        const Hit hit = accel_.intersect(ray, nullptr);
        const auto t1 = std::chrono::steady_clock::now();
        (void)hit;
        return vec3(float(std::chrono::duration<double, std::nano>(t1 - t0).count()));
    }
    Engine engine(state_, accel_, FEATURES_ALL);
    return engine.debug_view_value(engine.primary_aov(ray), integrator_);
}

} // namespace tp
