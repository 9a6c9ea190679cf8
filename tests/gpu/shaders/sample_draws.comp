#version 460
// Draws samples on the GPU for the chi-square tests: invocation i takes the renderer's own
// random numbers for (seed, i) and calls one sampler of the shared headers, writing the
// direction (xyz, w = 1) or point (xy, w = 1), or w = 0 for a failed draw. Dielectric: x = 1
// for reflection; alias table: x = the chosen index; glTF material: w = 0 also for a Dirac lobe.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require

#include "shared/brdf.h"
#include "shared/lights.h"
#include "shared/pbr.h"
#include "shared/rng.h"
#include "shared/sampling.h"
#include "draw_ids.h"

layout(local_size_x = 64) in;
layout(scalar, set = 0, binding = 0) readonly buffer Params { DrawParams p; };
layout(scalar, set = 0, binding = 1) readonly buffer Table { AliasEntry table[]; };
layout(scalar, set = 0, binding = 2) writeonly buffer Out { vec4 result[]; };
layout(push_constant, scalar) uniform Push { DrawPush push; };

vec3 f3(uint i) { return vec3(p.f[i].x, p.f[i].y, p.f[i].z); }

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.count) return;
    RngKey key = rng_key(SAMPLER_RANDOM, push.seed, i, 0u);
    vec4 u = vec4(rng_get(key, 0u), rng_get(key, 1u), rng_get(key, 2u), rng_get(key, 3u));
    vec4 r = vec4(0.0f);
    switch (push.sampler_id) {
    case DRAW_COSINE:
        r = vec4(sample_cosine_hemisphere(u.xy), 1.0f);
        break;
    case DRAW_PHONG_LOBE:
        r = vec4(sample_phong_lobe(u.xy, p.f[0].x), 1.0f);
        break;
    case DRAW_SPHERE:
        r = vec4(sample_uniform_sphere(u.xy), 1.0f);
        break;
    case DRAW_TRIANGLE:
        r = vec4(sample_uniform_triangle(u.xy), 0.0f, 1.0f);
        break;
    case DRAW_RNG_PAIR: {
        // The direction pair of bounce 3, pixels x samples as in the CPU test.
        RngKey k = rng_key(SAMPLER_RANDOM, 7u, i / 1000u, i % 1000u);
        r = vec4(rng_bounce2(k, 3u, RNG_DIR_U), 0.0f, 1.0f);
        break;
    }
    case DRAW_PHONG_MIXTURE: {
        BsdfSample b = phong_sample(f3(0u), f3(1u), p.f[0].w, f3(2u), f3(3u), u.x, u.yz);
        if (b.lobe != LOBE_NONE) r = vec4(b.wi, 1.0f);
        break;
    }
    case DRAW_DIELECTRIC: {
        BsdfSample b = dielectric_sample(vec3(1.0f), p.f[0].w, f3(2u), f3(3u), u.x);
        r = vec4((b.lobe & LOBE_TRANSMISSION) == 0u ? 1.0f : 0.0f, 0.0f, 0.0f, 1.0f);
        break;
    }
    case DRAW_TRIANGLE_LIGHT: {
        Light l;
        l.p0 = f3(0u);
        l.type = LIGHT_TRIANGLE;
        l.p1 = f3(1u);
        l.area = p.f[0].w;
        l.p2 = f3(2u);
        l.instance = 0u;
        l.value = vec3(1.0f);
        l.primitive = 0u;
        l.normal = triangle_light_normal(l.p0, l.p1, l.p2);
        l.pad0 = 0u;
        LightSample ls = sample_triangle_light(l, f3(3u), u.xy, false);
        if (ls.pdf > 0.0f) r = vec4(ls.wi, 1.0f);
        break;
    }
    case DRAW_ENV_MAP: {
        uint slot = alias_slot_from_bits(rng_get_bits(key, 0u), push.table_size);
        AliasEntry e = table[slot];
        uint pixel = alias_resolve(slot, e.prob, e.alias, u.y);
        LightSample ls = sample_environment_map(pixel, table[pixel].pdf, p.u.x, p.u.y, p.f[0].x,
                                                u.zw);
        if (ls.pdf > 0.0f) r = vec4(ls.wi, 1.0f);
        break;
    }
    case DRAW_ALIAS: {
        uint slot = alias_slot_from_bits(rng_get_bits(key, 0u), push.table_size);
        AliasEntry e = table[slot];
        r = vec4(float(alias_resolve(slot, e.prob, e.alias, u.y)), 0.0f, 0.0f, 1.0f);
        break;
    }
    case DRAW_PBR: {
        Material m;
        m.kd = f3(0u);
        m.kd_texture = NO_TEXTURE;
        m.ks = f3(1u);
        m.ns = 1.0f;
        m.ke = vec3(0.0f);
        m.ior = p.f[4].x;
        m.tf = vec3(1.0f);
        m.type = MATERIAL_PBR;
        m.metallic = p.f[0].w;
        m.roughness = p.f[1].w;
        m.transmission = p.f[2].w;
        m.specular = p.f[3].w;
        m.alpha = 1.0f;
        m.alpha_cutoff = 0.5f;
        m.alpha_mode = ALPHA_OPAQUE;
        m.attenuation_distance = FLOAT_MAX;
        m.metallic_roughness_texture = NO_TEXTURE;
        m.normal_texture = NO_TEXTURE;
        m.emissive_texture = NO_TEXTURE;
        m.transmission_texture = NO_TEXTURE;
        m.specular_texture = NO_TEXTURE;
        m.specular_color_texture = NO_TEXTURE;
        m.normal_scale = 1.0f;
        m.flags = p.u.x;
        BsdfSample b = pbr_sample(m, f3(2u), f3(3u), u.x, u.yz);
        if (b.lobe != LOBE_NONE && (b.lobe & LOBE_SPECULAR) == 0u) r = vec4(b.wi, 1.0f);
        break;
    }
    default:
        break;
    }
    result[i] = r;
}
