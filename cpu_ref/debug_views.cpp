#include "cpu_ref/debug_views.h"

#include "shared/camera.h"
#include "shared/rng.h"

#include <chrono>

namespace tp {

PixelAov CpuDebugViews::primary_aov(const Ray& ray) const {
    PixelAov a{};
    a.depth = FLOAT_MAX;
    a.instance = NO_INDEX;
    a.material = NO_INDEX;
    const Hit hit = accel_.intersect(ray);
    if (!hit.found) return a;
    const SurfacePoint sp = access_.surface(hit);
    const Material m = access_.material(hit.instance, sp.uv);
    a.albedo = material_albedo(m);
    a.depth = hit.t;
    a.normal = sp.ns;
    a.instance = hit.instance;
    a.material = access_.scene().instances[hit.instance].material;
    return a;
}

vec3 CpuDebugViews::radiance(uint32_t x, uint32_t y, uint32_t sample_index) const {
    const RenderParams& P = access_.scene().params;
    const RngKey key = rng_key(P.seed, y * P.camera.width + x, sample_index);
    const Ray ray = camera_ray(P.camera, key, x, y);
    if (integrator_ == INTEGRATOR_COST) {
        const auto t0 = std::chrono::steady_clock::now();
        const Hit hit = accel_.intersect(ray);
        const auto t1 = std::chrono::steady_clock::now();
        (void)hit;
        return vec3(float(std::chrono::duration<double, std::nano>(t1 - t0).count()));
    }
    const PixelAov a = primary_aov(ray);
    if (a.instance == NO_INDEX) return vec3(0.0f);
    if (integrator_ == INTEGRATOR_NORMALS) return 0.5f * a.normal + 0.5f;
    if (integrator_ == INTEGRATOR_ALBEDO) return a.albedo;
    return vec3(a.depth);
}

} // namespace tp
