// The CPU engine's side of the shared path loop (shared/integrator.h), scene reads
// (shared/scene_access.h) and debug views (shared/debug_views.h): a class template whose members
// are the hooks those bodies call (Embree's ray queries, the flat scene's arrays under the names
// the shaders give their buffers) and which includes those bodies, so that they become its member
// functions.
//
// Template parameters: `Fixed`, the feature bits of kCpuFixedFeatures that this copy of the
// loop is compiled for (the other bits stay run-time flags), and `Record`, whether the path
// log records (shared/path_log.h). An engine is made per path: it holds references only.
#pragma once

#include "cpu_ref/embree_accel.h"
#include "cpu_ref/rng_lanes.h"
#include "render/stats.h"
#include "scene/flatten.h"
#include "shared/alpha.h"
#include "shared/camera.h"
#include "shared/features.h"
#include "shared/lights.h"
#include "shared/path.h"
#include "shared/path_log.h"
#include "shared/rng.h"
#include "shared/roulette.h"
#include "shared/surface.h"
#include "shared/texture.h"

#include <vector>

namespace tp {

// The feature bits the CPU path loop is compiled for (2^5 = 32 copies): the material and
// emission bits, which decide the per-vertex work. The light and environment bits stay
// run-time flags on the CPU, where a well-predicted branch costs next to nothing against
// Embree's query (BENCHMARKS.md, h200-cpu-specialization).
constexpr uint32_t kCpuFixedFeatures = FEATURE_TEXTURES | FEATURE_PHONG_SPECULAR | FEATURE_MIRROR |
                                       FEATURE_DIELECTRIC | FEATURE_EMISSIVE_TRIANGLES;

// What the CPU engine reads besides the flat scene: the render's parameters with its seed, and
// per instance the terms of its hits' error bounds (shared/surface.h), computed once rather
// than at every hit.
struct CpuSceneState {
    CpuSceneState(const FlatScene& s, uint32_t seed, uint32_t sampler)
        : scene(s), params(s.params) {
        params.seed = seed;
        params.sampler_id = sampler;
        error_terms.reserve(s.instances.size());
        for (const Instance& inst : s.instances) error_terms.push_back(instance_error_terms(inst));
        for (const Texture& t : s.images) image_words.push_back(t.words.data());
    }
    const FlatScene& scene;
    RenderParams params;
    std::vector<InstanceErrorTerms> error_terms;
    std::vector<const uint32_t*> image_words; // each image's texel words (scene_texel)
};

template <uint32_t Fixed, bool Record>
class CpuEngine {
  public:
    CpuEngine(const CpuSceneState& state, const EmbreeAccel& accel, uint32_t features,
              std::vector<PathVertex>* log = nullptr)
        : params(state.params), instances(state.scene.instances), meshes(state.scene.meshes),
          triangles(state.scene.triangles), positions(state.scene.positions),
          normals(state.scene.normals), uvs(state.scene.uvs), uvs1(state.scene.uvs1),
          tangents(state.scene.tangents), materials(state.scene.materials),
          texture_slots(state.scene.texture_slots), textures(state.scene.textures),
          lights(state.scene.lights), light_table(state.scene.light_table),
          env_table(state.scene.env_table), scene_features{features}, state_(state), accel_(accel),
          log_(log) {}

    // ---- hooks (the names the shared bodies call) ----------------------------------------
    using TraceHit = Hit;
    static constexpr bool TRACE_SHADOW_AFTER_SCATTER = false;
    static constexpr float TRACE_OFFSET_SLACK = 1.0f; // Embree with the exact-triangle filter
    // The stored normal: cheaper here than forming it (docs/gpu.md, "Stored light normal").
    static constexpr bool SCENE_LIGHT_NORMAL_FROM_VERTICES = false;
    static constexpr bool path_log_recording = Record;

    // The feature mask: the bits of kCpuFixedFeatures are `Fixed`, known at compile time (each
    // feature_on() of one of them folds to a constant); the others are the render's.
    struct FeatureMask {
        uint32_t runtime;
        operator uint32_t() const { return Fixed | (runtime & ~kCpuFixedFeatures); }
    };

    const RenderParams& params;
    const std::vector<Instance>& instances;
    const std::vector<MeshInfo>& meshes;
    const std::vector<uvec3>& triangles;
    const std::vector<vec3>& positions;
    const std::vector<vec3>& normals;
    const std::vector<vec2>& uvs;
    const std::vector<vec2>& uvs1;
    const std::vector<vec4>& tangents;
    const std::vector<Material>& materials;
    const std::vector<TextureSlot>& texture_slots;
    const std::vector<TextureInfo>& textures;
    const std::vector<Light>& lights;
    const std::vector<AliasEntry>& light_table;
    const std::vector<AliasEntry>& env_table;
    const FeatureMask scene_features;

    bool trace_closest(const Ray& ray, Hit& hit) const {
        if (feature_on(scene_features, FEATURE_ALPHA)) {
            const CoverageTest c{&CpuEngine::alpha_covers_thunk, this, ray};
            hit = accel_.intersect(ray, &c);
        } else {
            hit = accel_.intersect(ray, nullptr);
        }
        return hit.found;
    }
    // The closest hits of up to EmbreeAccel::kPacket rays: one packet where the scene is opaque,
    // else one query each (the alpha test is made with each ray's own tag).
    void trace_closest_group(const Ray* rays, uint32_t count, Hit* hits) const {
        if (feature_on(scene_features, FEATURE_ALPHA)) {
            for (uint32_t i = 0; i < count; ++i) trace_closest(rays[i], hits[i]);
            return;
        }
        accel_.intersect_packet(rays, count, hits);
    }
    bool trace_occluded(const Ray& ray) const {
        if (!feature_on(scene_features, FEATURE_ALPHA)) return accel_.occluded(ray, nullptr);
        const CoverageTest c{&CpuEngine::alpha_covers_thunk, this, ray};
        return accel_.occluded(ray, &c);
    }
    InstanceErrorTerms scene_error_terms(uint32_t instance) const {
        return state_.error_terms[instance];
    }
    uint32_t scene_env_table_size() const { return uint32_t(env_table.size()); }
    // Texel i of an image, its channels as stored, from the image's words (image/texture.h).
    uvec4 scene_texel(uint32_t image, const TextureInfo& info, uint32_t i) const {
        return words_texel_channels(state_.image_words[image], info.format, i);
    }
    void path_log_emit(PathVertex v, uint32_t termination) const {
        v.termination = termination;
        log_->push_back(v);
    }

    // rng.h's pair draws of a bounce, under the names the path loop calls: as members they hide
    // the namespace's functions inside the shared bodies. The first draw of a bounce computes
    // all of its pairs in lanes (rng_lanes.h), the others read them; the words are rng.h's.
    uvec2 rng_bounce2_bits(const RngKey& key, uint32_t bounce, uint32_t k) {
        if (bounce != words_bounce_) {
            bounce_words(key, bounce, words_);
            words_bounce_ = bounce;
        }
        const uint32_t lane = bounce_pair_lane(k);
        return uvec2(words_.first[lane], words_.second[lane]);
    }
    vec2 rng_bounce2(const RngKey& key, uint32_t bounce, uint32_t k) {
        const uvec2 w = rng_bounce2_bits(key, bounce, k);
        return vec2(uint_to_unit_float(w.x), uint_to_unit_float(w.y));
    }

    // ---- the shared bodies ---------------------------------------------------------------
#include "shared/debug_views.h"
#include "shared/integrator.h"
#include "shared/scene_access.h"

  private:
    // scene_alpha_covers (shared/scene_access.h) for Embree's filter; it reads the scene only.
    static bool alpha_covers_thunk(const void* engine, uint32_t instance, uint32_t primitive,
                                   vec2 bary, const Ray& ray) {
        return const_cast<CpuEngine*>(static_cast<const CpuEngine*>(engine))
            ->scene_alpha_covers(instance, primitive, bary, ray);
    }

    const CpuSceneState& state_;
    const EmbreeAccel& accel_;
    std::vector<PathVertex>* log_;
    BounceWords words_;                    // the pairs of bounce words_bounce_ (one path's key)
    uint32_t words_bounce_ = ~uint32_t(0); // none yet
};

} // namespace tp
