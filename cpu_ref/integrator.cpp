#include "cpu_ref/integrator.h"

#include "shared/camera.h"
#include "shared/path.h"
#include "shared/rng.h"
#include "shared/roulette.h"

#include <array>
#include <utility>

namespace tp {
namespace {

// The feature bits the path loop is instantiated for (2^5 = 32 loops): the material and
// emission bits, which decide the per-vertex work. The light and environment bits stay run-time
// flags on the CPU, where a well-predicted branch costs next to nothing against Embree's query
// (BENCHMARKS.md, specialization).
constexpr uint32_t kFixedFeatures = FEATURE_TEXTURES | FEATURE_PHONG_SPECULAR | FEATURE_MIRROR |
                                    FEATURE_DIELECTRIC | FEATURE_EMISSIVE_TRIANGLES;

// The i-th subset of kFixedFeatures (bit j of i selects its j-th set bit).
constexpr uint32_t fixed_subset(uint32_t i) {
    uint32_t out = 0, j = 0;
    for (uint32_t bit = 1; bit <= kFixedFeatures; bit <<= 1)
        if (kFixedFeatures & bit) {
            if (i & (1u << j)) out |= bit;
            ++j;
        }
    return out;
}

constexpr uint32_t kFixedCount = 1u << 5;
static_assert(fixed_subset(kFixedCount - 1) == kFixedFeatures, "five fixed bits");

} // namespace

template <size_t... I>
std::array<CpuIntegrator::Loop, sizeof...(I)> CpuIntegrator::make_loops(std::index_sequence<I...>) {
    return {&CpuIntegrator::radiance_for<fixed_subset(uint32_t(I))>...};
}

CpuIntegrator::CpuIntegrator(const FlatScene& scene, const EmbreeAccel& accel, uint32_t features)
    : access_(scene), accel_(accel), features_(features) {
    static const std::array<Loop, kFixedCount> loops = make_loops(std::make_index_sequence<kFixedCount>{});
    loop_ = loops[0];
    for (uint32_t i = 0; i < kFixedCount; ++i)
        if (fixed_subset(i) == (features & kFixedFeatures)) loop_ = loops[i];
}

template <uint32_t Fixed>
vec3 CpuIntegrator::radiance_for(uint32_t x, uint32_t y, uint32_t sample_index,
                                 RayCounts& rays) const {
    // Known at compile time for the bits of kFixedFeatures.
    const uint32_t F = Fixed | (features_ & ~kFixedFeatures);
    const FlatScene& s = access_.scene();
    const RenderParams& P = s.params;
    const RngKey key = rng_key(P.seed, y * P.camera.width + x, sample_index);

    Ray ray;
    ray.origin = P.camera.eye;
    ray.dir = camera_direction(P.camera, float(x) + rng_get(key, RNG_PIXEL_X),
                               float(y) + rng_get(key, RNG_PIXEL_Y));
    ray.tmax = FLOAT_MAX;
    ++rays.camera;

    vec3 L(0.0f), T(1.0f);
    bool prev_specular = true; // the camera ray: emitters seen directly get full weight
    float prev_pdf = 0.0f;
    for (uint32_t bounce = 0;; ++bounce) {
        const Hit hit = accel_.intersect(ray);
        if (!hit.found) {
            if (features_environment(F) && P.env_light != NO_INDEX) {
                const float light_pdf = access_.light_selection_pdf(P.env_light) *
                                        access_.environment_pdf(ray.dir, F);
                L += T * access_.environment_radiance(ray.dir, F) *
                     emission_mis_weight(prev_specular, prev_pdf, light_pdf);
            }
            break;
        }
        const Instance& inst = s.instances[hit.instance];
        SurfacePoint sp = access_.surface(hit, F);
        const Material mat = access_.material(hit.instance, sp.uv, F);
        const vec3 wo = -ray.dir;

        // 1. Emission, front face only.
        const float cos_emit = dot(sp.ng, wo);
        if (feature_on(F, FEATURE_EMISSIVE_TRIANGLES) && !is_black(mat.ke) && cos_emit > 0.0f) {
            float light_pdf = 0.0f;
            if (inst.light_offset != NO_INDEX) {
                const uint32_t li = inst.light_offset + hit.primitive;
                light_pdf = access_.light_selection_pdf(li) *
                            triangle_light_pdf(access_.light(li).area, hit.t, cos_emit);
            }
            L += T * mat.ke * emission_mis_weight(prev_specular, prev_pdf, light_pdf);
        }

        // 2. The maximum number of scattering events.
        if (bounce >= P.max_depth) break;
        if (!feature_on(F, FEATURE_DIELECTRIC) || mat.type != MATERIAL_DIELECTRIC)
            surface_face_viewer(sp, wo);

        // 3. Next-event estimation.
        if (features_sample_lights(F) && !material_is_delta_in(F, mat) && P.light_count > 0) {
            const uint32_t slot =
                alias_slot_from_bits(rng_bounce_bits(key, bounce, RNG_LIGHT_SLOT), P.light_count);
            const AliasEntry& e = s.light_table[slot];
            const uint32_t li =
                alias_resolve(slot, e.prob, e.alias, rng_bounce(key, bounce, RNG_LIGHT_COIN));
            const float sel_pdf = access_.light_selection_pdf(li);
            const vec2 u(rng_bounce(key, bounce, RNG_LIGHT_U),
                         rng_bounce(key, bounce, RNG_LIGHT_V));
            const LightSample ls =
                access_.sample(li, sp.p, u, rng_bounce_bits(key, bounce, RNG_ENV_SLOT),
                               rng_bounce(key, bounce, RNG_ENV_COIN), F);
            if (ls.pdf > 0.0f && dot(ls.wi, sp.ng) > 0.0f) {
                const vec3 f = bsdf_eval_in(F, mat, sp.ns, wo, ls.wi);
                if (!is_black(f) && !is_black(ls.radiance)) {
                    const float light_pdf = sel_pdf * ls.pdf;
                    vec3 contrib = T * f * (dot(sp.ns, ls.wi) / light_pdf) * ls.radiance;
                    if (features_mis(F) && !ls.delta)
                        contrib *=
                            power_heuristic(light_pdf, bsdf_pdf_in(F, mat, sp.ns, wo, ls.wi));
                    ++rays.shadow;
                    if (!accel_.occluded(shadow_ray(sp.p, sp.ng, ls, access_.light(li))))
                        L += contrib;
                }
            }
        }

        // 4. Scattering.
        const BsdfSample bs = bsdf_sample_in(
            F, mat, sp.ns, wo, rng_bounce(key, bounce, RNG_LOBE),
            vec2(rng_bounce(key, bounce, RNG_DIR_U), rng_bounce(key, bounce, RNG_DIR_V)));
        if (bs.lobe == LOBE_NONE || !scatter_is_consistent(sp.ng, wo, bs.wi, bs.lobe)) break;
        T *= bs.weight;
        prev_specular = (bs.lobe & LOBE_SPECULAR) != 0u;
        prev_pdf = bs.pdf;
        if (!roulette_apply(T, bounce + 1, P.min_depth, rng_bounce(key, bounce, RNG_ROULETTE)))
            break;
        ray = spawn_ray(sp.p, sp.ng, bs.wi);
        ++rays.extension;
    }
    return L;
}

} // namespace tp
