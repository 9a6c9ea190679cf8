#include "cpu_ref/integrator.h"

#include "shared/camera.h"
#include "shared/path.h"
#include "shared/path_log.h"
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
    static const std::array<Loop, kFixedCount> loops =
        make_loops(std::make_index_sequence<kFixedCount>{});
    loop_ = loops[0];
    for (uint32_t i = 0; i < kFixedCount; ++i)
        if (fixed_subset(i) == (features & kFixedFeatures)) loop_ = loops[i];
}

template <uint32_t Fixed>
vec3 CpuIntegrator::radiance_for(uint32_t x, uint32_t y, uint32_t sample_index,
                                 RayCounts& rays) const {
    return trace_path<Fixed, false>(x, y, sample_index, rays, nullptr);
}

vec3 CpuIntegrator::record(uint32_t x, uint32_t y, uint32_t sample_index, RayCounts& rays,
                           std::vector<PathVertex>& log) const {
    return trace_path<kFixedFeatures, true>(x, y, sample_index, rays, &log);
}

namespace {
void path_log_emit(std::vector<PathVertex>* log, PathVertex v, uint32_t termination) {
    v.termination = termination;
    log->push_back(v);
}
} // namespace

// Path logs (shared/path_log.h): PATH_LOG(...) holds the recording statements, in step with
// shaders/integrator.glsl; with Record = false they are not compiled.
#define PATH_LOG(x)                                                                                \
    if constexpr (Record) {                                                                        \
        x;                                                                                         \
    }

template <uint32_t Fixed, bool Record>
vec3 CpuIntegrator::trace_path(uint32_t x, uint32_t y, uint32_t sample_index, RayCounts& rays,
                               [[maybe_unused]] std::vector<PathVertex>* log) const {
    // Known at compile time for the bits of kFixedFeatures.
    const uint32_t F = Fixed | (features_ & ~kFixedFeatures);
    const FlatScene& s = access_.scene();
    const RenderParams& P = s.params;
    const RngKey key = rng_key(P.seed, y * P.camera.width + x, sample_index);

    Ray ray = camera_ray(P.camera, key, x, y);
    ++rays.camera;

    vec3 L(0.0f), T(1.0f);
    bool prev_specular = true; // the camera ray: emitters seen directly get full weight
    float prev_pdf = 0.0f;
    for (uint32_t bounce = 0;; ++bounce) {
        [[maybe_unused]] PathVertex rec;
        PATH_LOG(rec = path_vertex_begin(sample_index, bounce, ray));
        const Hit hit = accel_.intersect(ray);
        if (!hit.found) {
            if (features_environment(F) && P.env_light != NO_INDEX) {
                const float light_pdf =
                    access_.light_selection_pdf(P.env_light) * access_.environment_pdf(ray.dir, F);
                L += T * access_.environment_radiance(ray.dir, F) *
                     emission_mis_weight(prev_specular, prev_pdf, light_pdf);
                PATH_LOG(rec.emitted = T * access_.environment_radiance(ray.dir, F) *
                                       emission_mis_weight(prev_specular, prev_pdf, light_pdf);
                         rec.mis_emission =
                             emission_mis_weight(prev_specular, prev_pdf, light_pdf));
            }
            PATH_LOG(rec.radiance = L; path_log_emit(log, rec, TERM_ESCAPED));
            break;
        }
        const Instance& inst = s.instances[hit.instance];
        SurfacePoint sp = access_.surface(hit, F);
        surface_snap_to_ray(sp, ray.origin, ray.dir);
        const Material mat = access_.material(hit.instance, sp.uv, F);
        const vec3 wo = -ray.dir;
        PATH_LOG(rec.event = VERTEX_HIT; rec.t = hit.t; rec.instance = hit.instance;
                 rec.primitive = hit.primitive; rec.bary = hit.bary; rec.material = inst.material;
                 rec.position = sp.p);

        // 1. Emission, front face only.
        const float cos_emit = dot(sp.ng, wo);
        PATH_LOG(rec.cos_emit = cos_emit);
        if (feature_on(F, FEATURE_EMISSIVE_TRIANGLES) && !is_black(mat.ke) && cos_emit > 0.0f) {
            float light_pdf = 0.0f;
            if (inst.light_offset != NO_INDEX) {
                const uint32_t li = inst.light_offset + hit.primitive;
                light_pdf = access_.light_selection_pdf(li) *
                            triangle_light_pdf(access_.light(li).area, hit.t, cos_emit);
            }
            L += T * mat.ke * emission_mis_weight(prev_specular, prev_pdf, light_pdf);
            PATH_LOG(rec.emitted =
                         T * mat.ke * emission_mis_weight(prev_specular, prev_pdf, light_pdf);
                     rec.mis_emission = emission_mis_weight(prev_specular, prev_pdf, light_pdf));
        }

        // 2. The maximum number of scattering events.
        PATH_LOG(rec.ng = sp.ng; rec.ns = sp.ns);
        if (bounce >= P.max_depth) {
            PATH_LOG(rec.radiance = L; path_log_emit(log, rec, TERM_MAX_DEPTH));
            break;
        }
        if (!feature_on(F, FEATURE_DIELECTRIC) || mat.type != MATERIAL_DIELECTRIC)
            surface_face_viewer(sp, wo);
        PATH_LOG(rec.ng = sp.ng; rec.ns = sp.ns);

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
            PATH_LOG(rec.light = li; rec.light_wi = ls.wi; rec.light_pdf = sel_pdf * ls.pdf;
                     rec.mis_light = 1.0f; rec.rng[RNG_LIGHT_SLOT] = uint_to_unit_float(
                                               rng_bounce_bits(key, bounce, RNG_LIGHT_SLOT));
                     rec.rng[RNG_LIGHT_COIN] = rng_bounce(key, bounce, RNG_LIGHT_COIN);
                     rec.rng[RNG_LIGHT_U] = u.x; rec.rng[RNG_LIGHT_V] = u.y;
                     rec.rng[RNG_ENV_SLOT] =
                         uint_to_unit_float(rng_bounce_bits(key, bounce, RNG_ENV_SLOT));
                     rec.rng[RNG_ENV_COIN] = rng_bounce(key, bounce, RNG_ENV_COIN));
            if (ls.pdf > 0.0f && dot(ls.wi, sp.ng) > 0.0f) {
                const vec3 f = bsdf_eval_in(F, mat, sp.ns, wo, ls.wi);
                PATH_LOG(rec.light_f = f);
                if (!is_black(f) && !is_black(ls.radiance)) {
                    const float light_pdf = sel_pdf * ls.pdf;
                    vec3 contrib = T * f * (dot(sp.ns, ls.wi) / light_pdf) * ls.radiance;
                    if (features_mis(F) && !ls.delta)
                        contrib *=
                            power_heuristic(light_pdf, bsdf_pdf_in(F, mat, sp.ns, wo, ls.wi));
                    PATH_LOG(rec.light_bsdf_pdf = bsdf_pdf_in(F, mat, sp.ns, wo, ls.wi);
                             rec.mis_light =
                                 ls.delta ? 1.0f : power_heuristic(light_pdf, rec.light_bsdf_pdf);
                             rec.nee = contrib);
                    ++rays.shadow;
                    const bool occluded =
                        accel_.occluded(shadow_ray(sp.p, sp.p_error, sp.ng, ls, access_.light(li)));
                    if (!occluded) L += contrib;
                    PATH_LOG(rec.shadow = occluded ? SHADOW_OCCLUDED : SHADOW_UNOCCLUDED);
                }
            }
        }

        // 4. Scattering.
        const BsdfSample bs = bsdf_sample_in(
            F, mat, sp.ns, wo, rng_bounce(key, bounce, RNG_LOBE),
            vec2(rng_bounce(key, bounce, RNG_DIR_U), rng_bounce(key, bounce, RNG_DIR_V)));
        PATH_LOG(rec.rng[RNG_LOBE] = rng_bounce(key, bounce, RNG_LOBE);
                 rec.rng[RNG_DIR_U] = rng_bounce(key, bounce, RNG_DIR_U);
                 rec.rng[RNG_DIR_V] = rng_bounce(key, bounce, RNG_DIR_V); rec.lobe = bs.lobe;
                 rec.wi = bs.wi; rec.bsdf_pdf = bs.pdf; rec.bsdf_weight = bs.weight;
                 rec.radiance = L; rec.throughput = T);
        if (bs.lobe == LOBE_NONE || !scatter_is_consistent(sp.ng, wo, bs.wi, bs.lobe)) {
            PATH_LOG(path_log_emit(log, rec,
                                   bs.lobe == LOBE_NONE ? TERM_NO_SCATTER : TERM_INCONSISTENT));
            break;
        }
        T *= bs.weight;
        prev_specular = (bs.lobe & LOBE_SPECULAR) != 0u;
        prev_pdf = bs.pdf;
        PATH_LOG(rec.rng[RNG_ROULETTE] = rng_bounce(key, bounce, RNG_ROULETTE);
                 rec.roulette_q = roulette_survival(T, bounce + 1, P.min_depth));
        if (!roulette_apply(T, bounce + 1, P.min_depth, rng_bounce(key, bounce, RNG_ROULETTE))) {
            PATH_LOG(rec.throughput = T; path_log_emit(log, rec, TERM_ROULETTE));
            break;
        }
        ray = spawn_ray(sp.p, sp.p_error, sp.ng, bs.wi);
        ++rays.extension;
        PATH_LOG(rec.throughput = T; path_log_emit(log, rec, TERM_CONTINUE));
    }
    return L;
}

} // namespace tp
