// The CPU engine's reads of the flat scene arrays: everything the GLSL engine does with buffer
// loads, done here with vector indexing, and then handed to the same shared functions.
#pragma once

#include "cpu_ref/embree_accel.h"
#include "scene/flatten.h"
#include "shared/features.h"
#include "shared/lights.h"
#include "shared/surface.h"
#include "shared/texture.h"

#include <vector>

namespace tp {

class SceneAccess {
  public:
    explicit SceneAccess(const FlatScene& s) : s_(s) {
        error_terms_.reserve(s.instances.size());
        for (const Instance& inst : s.instances) error_terms_.push_back(instance_error_terms(inst));
    }

    const FlatScene& scene() const { return s_; }

    // Every method takes the render's feature mask (shared/features.h): what the scene cannot
    // use is not read.

    // World-space point, normals and uv of a hit (uv only with textures, its one use).
    SurfacePoint surface(const Hit& h, uint32_t features = FEATURES_ALL) const {
        const Instance& inst = s_.instances[h.instance];
        const MeshInfo& m = s_.meshes[inst.mesh];
        const uvec3 t = s_.triangles[m.first_triangle + h.primitive];
        const uint32_t base = m.first_vertex;
        SurfacePoint sp =
            surface_point_with(inst, error_terms_[h.instance], s_.positions[base + t.x],
                               s_.positions[base + t.y], s_.positions[base + t.z], h.bary);
        if (m.flags & MESH_HAS_NORMALS)
            surface_set_shading_normal(sp, inst, s_.normals[base + t.x], s_.normals[base + t.y],
                                       s_.normals[base + t.z], h.bary);
        if (feature_on(features, FEATURE_TEXTURES) && (m.flags & MESH_HAS_UVS))
            sp.uv = barycentric_mix2(s_.uvs[base + t.x], s_.uvs[base + t.y], s_.uvs[base + t.z],
                                     h.bary);
        return sp;
    }

    vec3 texture(int index, vec2 st, bool clamp_t) const {
        const TextureInfo& info = s_.textures[size_t(index)];
        const TexelFootprint fp = texture_footprint(st, info.width, info.height, clamp_t);
        const vec3* t = &s_.texels[info.offset];
        return texture_bilerp(t[fp.i00], t[fp.i10], t[fp.i01], t[fp.i11], fp.f);
    }

    // The instance's material with its diffuse texture applied at uv.
    Material material(uint32_t instance, vec2 uv, uint32_t features = FEATURES_ALL) const {
        Material m = s_.material_of(instance);
        if (feature_on(features, FEATURE_TEXTURES) && m.kd_texture != NO_TEXTURE)
            m.kd *= texture(m.kd_texture, uv_to_image(uv), false);
        return m;
    }

    const Light& light(uint32_t i) const { return s_.lights[i]; }
    float light_selection_pdf(uint32_t i) const { return s_.light_table[i].pdf; }

    // Radiance arriving from the environment along direction d (unit, world space).
    vec3 environment_radiance(vec3 d, uint32_t features = FEATURES_ALL) const {
        const Light& env = s_.lights[s_.params.env_light];
        if (!feature_on(features, FEATURE_ENV_MAP) || s_.params.env_texture == NO_TEXTURE)
            return env.value;
        return env.value * texture(s_.params.env_texture,
                                   environment_map_coords(d, s_.params.env_rotation), true);
    }

    // Solid-angle density with which light sampling picks direction d from the environment,
    // given that the environment was chosen.
    float environment_pdf(vec3 d, uint32_t features = FEATURES_ALL) const {
        if (!feature_on(features, FEATURE_ENV_MAP) || s_.params.env_texture == NO_TEXTURE)
            return INV_FOUR_PI;
        if (s_.env_table.empty()) return 0.0f;
        const TextureInfo& info = s_.textures[size_t(s_.params.env_texture)];
        const vec2 st = environment_map_coords(d, s_.params.env_rotation);
        const uint32_t pixel = environment_map_pixel(st, info.width, info.height);
        return environment_map_pdf(s_.env_table[pixel].pdf, info.width, info.height,
                                   sin(st.y * PI));
    }

    // Samples light `i` from point p; the environment map's pixel is drawn with the 32 random
    // bits env_slot_bits and the number env_coin.
    LightSample sample(uint32_t i, vec3 p, vec2 u, uint32_t env_slot_bits, float env_coin,
                       uint32_t features = FEATURES_ALL) const {
        const Light& l = s_.lights[i];
        if (!feature_on(features, FEATURE_ENV_MAP) || l.type != LIGHT_ENVIRONMENT ||
            s_.params.env_texture == NO_TEXTURE)
            return sample_light_in(features, l, p, u);
        if (s_.env_table.empty()) return light_sample_none();
        const TextureInfo& info = s_.textures[size_t(s_.params.env_texture)];
        const uint32_t slot = alias_slot_from_bits(env_slot_bits, uint32_t(s_.env_table.size()));
        const AliasEntry& e = s_.env_table[slot];
        const uint32_t pixel = alias_resolve(slot, e.prob, e.alias, env_coin);
        LightSample ls = sample_environment_map(pixel, s_.env_table[pixel].pdf, info.width,
                                                info.height, s_.params.env_rotation, u);
        if (ls.pdf > 0.0f) ls.radiance = environment_radiance(ls.wi, features);
        return ls;
    }

  private:
    const FlatScene& s_;
    // Per instance, what each hit's error bound needs from it (shared/surface.h): computed
    // once here instead of at every hit, 5 % of the path loop's instructions on cornell.
    std::vector<InstanceErrorTerms> error_terms_;
};

} // namespace tp
