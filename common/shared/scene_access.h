// The scene reads of both engines: the surface at a hit, the material there, the environment
// and light sampling, written once against the scene's arrays, which each engine names the
// same way before including this file:
//   params, instances[], meshes[], triangles[], positions[], normals[], uvs[], uvs1[],
//   tangents[], materials[], texture_slots[], textures[], lights[], light_table[],
//   env_table[]  (FlatScene's arrays; GLSL: the storage buffers of shaders/bindings.glsl)
//   scene_features                        the feature mask the reads are restricted to (what
//                                         the scene cannot use is compiled out)
//   scene_texel(uint image, TextureInfo info, uint i)
//                                         the channels of texel i (row * width + column) of
//                                         image `image` as stored (a uvec4: 8- or 16-bit
//                                         integers, or float bits; texture.h decodes them): the
//                                         CPU reads its texel words, the GPU fetches from the
//                                         image (texelFetch, no hardware filtering), so both
//                                         decode and filter the same values alike
//   scene_error_terms(uint instance)      the instance's InstanceErrorTerms (surface.h)
//   scene_env_table_size()                entries of env_table
//   SCENE_LIGHT_NORMAL_FROM_VERTICES      a constant: how triangle lights' normals are had
//                                         (lights.h, light_normal)
// GLSL includes it after those; C++ includes it inside the engine's class template
// (cpu_ref/cpu_engine.h), so that these functions become its members. It includes nothing
// itself: lights.h, path.h, surface.h, texture.h, alpha.h and features.h come first.
#ifndef TP_SHARED_SCENE_ACCESS_H
#define TP_SHARED_SCENE_ACCESS_H

// World-space point, normals, uv sets and tangent frame of a hit (uv and tangents only where
// textures are on, their one use).
SurfacePoint scene_surface(TraceHit h) {
    Instance inst = instances[h.instance];
    MeshInfo m = meshes[inst.mesh];
    uvec3 t = triangles[m.first_triangle + h.primitive];
    uint base = m.first_vertex;
    SurfacePoint sp = surface_point_with(inst, scene_error_terms(h.instance), positions[base + t.x],
                                         positions[base + t.y], positions[base + t.z], h.bary);
    if ((m.flags & MESH_HAS_NORMALS) != 0u)
        surface_set_shading_normal(sp, inst, normals[base + t.x], normals[base + t.y],
                                   normals[base + t.z], h.bary);
    if (feature_on(scene_features, FEATURE_TEXTURES)) {
        if ((m.flags & MESH_HAS_UVS) != 0u)
            sp.uv = barycentric_mix2(uvs[base + t.x], uvs[base + t.y], uvs[base + t.z], h.bary);
        if ((m.flags & MESH_HAS_UV1) != 0u)
            sp.uv1 = barycentric_mix2(uvs1[base + t.x], uvs1[base + t.y], uvs1[base + t.z], h.bary);
    }
    if (feature_on(scene_features, FEATURE_NORMAL_MAPS) && (m.flags & MESH_HAS_TANGENTS) != 0u &&
        (m.flags & MESH_HAS_NORMALS) != 0u) {
        vec4 tg = barycentric_mix4(tangents[base + t.x], tangents[base + t.y], tangents[base + t.z],
                                   h.bary);
        vec3 n =
            barycentric_mix3(normals[base + t.x], normals[base + t.y], normals[base + t.z], h.bary);
        surface_set_tangent_frame(sp, inst, n, tg);
    }
    return sp;
}

// Texel i of image `image` decoded to linear values: sRGB-encoded integer colour is decoded;
// float images, and integer images read as data, are linear already.
vec4 scene_texel_linear(uint image, TextureInfo info, uint i, bool srgb) {
    vec4 c = texel_channels_value(scene_texel(image, info, i), info.format);
    return srgb && info.format != TEXEL_RGBA32F ? srgb_to_linear4(c) : c;
}

// Texel k (0-3) of a bilinear footprint: i00, i10, i01, i11.
uint footprint_texel(TexelFootprint fp, uint k) {
    return k == 0u ? fp.i00 : k == 1u ? fp.i10 : k == 2u ? fp.i01 : fp.i11;
}

// Image `image` at image coordinates st under the wrap modes of s and t: bilinear, or its
// nearest texel. The texels are read at one call of scene_texel in a loop: a shader compiler
// that inlines every call before it folds the specialization constants (Mesa's, which then
// removes the switch over the scene's images of shaders/scene_access.glsl) copies that switch
// once per call site, so each site costs compile time whether or not the scene has images.
vec4 scene_image_lookup(uint image, vec2 st, uint wrap_s, uint wrap_t, bool srgb, bool nearest) {
    TextureInfo info = textures[image];
    TexelFootprint fp = texture_footprint(st, info.width, info.height, wrap_s, wrap_t);
    if (nearest) fp.i00 = texture_nearest(st, info.width, info.height, wrap_s, wrap_t);
    vec4 t[4];
    uint n = nearest ? 1u : 4u;
    for (uint k = 0u; k < n; ++k)
        t[k] = scene_texel_linear(image, info, footprint_texel(fp, k), srgb);
    return nearest ? t[0] : texture_bilerp(t[0], t[1], t[2], t[3], fp.f);
}

// Texture slot `slot` (TextureSlot) at a surface with uv sets uv0 and uv1, in linear RGBA.
vec4 scene_texture(int slot, vec2 uv0, vec2 uv1) {
    TextureSlot ts = texture_slots[slot];
    vec3 uv = vec3((ts.sampling & SLOT_UV1) != 0u ? uv1 : uv0, 1.0f);
    vec2 st = vec2(dot(ts.transform_s, uv), dot(ts.transform_t, uv));
    return scene_image_lookup(ts.image, st, ts.sampling & 3u,
                              (ts.sampling >> SLOT_WRAP_T_SHIFT) & 3u,
                              (ts.sampling & SLOT_SRGB) != 0u, (ts.sampling & SLOT_NEAREST) != 0u);
}

// A material's texture slot k (MATERIAL_TEXTURE_SLOTS, types.h).
int material_texture(Material m, uint k) {
    if (k == 0u) return m.kd_texture;
    if (k == 1u) return m.metallic_roughness_texture;
    if (k == 2u) return m.emissive_texture;
    if (k == 3u) return m.transmission_texture;
    if (k == 4u) return m.specular_texture;
    if (k == 5u) return m.specular_color_texture;
    return m.normal_texture;
}

// The instance's material at surface point sp with its textures applied, and sp's shading
// normal bent by the material's normal map (surface.h, surface_apply_normal_map). Only the base
// colour applies to a material that is not glTF's. One lookup in a loop over the slots, for
// the reason scene_image_lookup gives.
Material scene_material(uint instance, INOUT(SurfacePoint) sp) {
    Material m = materials[instances[instance].material];
    if (!feature_on(scene_features, FEATURE_TEXTURES)) return m;
    bool pbr = feature_on(scene_features, FEATURE_PBR) && m.type == MATERIAL_PBR;
    for (uint k = 0u; k < MATERIAL_TEXTURE_SLOTS; ++k) {
        int slot = material_texture(m, k);
        if (slot == NO_TEXTURE || (k > 0u && !pbr)) continue;
        if (k == 6u && !feature_on(scene_features, FEATURE_NORMAL_MAPS)) continue;
        vec4 c = scene_texture(slot, sp.uv, sp.uv1);
        if (k == 0u) {
            m.kd *= vec3(c.x, c.y, c.z);
            m.alpha *= c.w;
        } else if (k == 1u) {
            m.roughness *= c.y;
            m.metallic *= c.z;
        } else if (k == 2u) {
            m.ke *= vec3(c.x, c.y, c.z);
        } else if (k == 3u) {
            m.transmission *= c.x;
        } else if (k == 4u) {
            m.specular *= c.w;
        } else if (k == 5u) {
            m.ks *= vec3(c.x, c.y, c.z);
        } else {
            surface_apply_normal_map(sp, vec3(c.x, c.y, c.z), m.normal_scale);
        }
    }
    return m;
}

// The uv sets of `instance`'s triangle `primitive` at barycentric weights bary (zero where the
// mesh has none).
void scene_uvs_at(uint instance, uint primitive, vec2 bary, OUT(vec2) uv0, OUT(vec2) uv1) {
    MeshInfo mesh = meshes[instances[instance].mesh];
    uvec3 t = triangles[mesh.first_triangle + primitive];
    uint base = mesh.first_vertex;
    uv0 = vec2(0.0f);
    uv1 = vec2(0.0f);
    if ((mesh.flags & MESH_HAS_UVS) != 0u)
        uv0 = barycentric_mix2(uvs[base + t.x], uvs[base + t.y], uvs[base + t.z], bary);
    if ((mesh.flags & MESH_HAS_UV1) != 0u)
        uv1 = barycentric_mix2(uvs1[base + t.x], uvs1[base + t.y], uvs1[base + t.z], bary);
}

// Whether the surface of `instance` is there at a candidate hit of `ray` (alpha as coverage,
// alpha.h): what every traversal of both engines asks before it accepts a hit, where the
// scene has alpha (FEATURE_ALPHA).
bool scene_alpha_covers(uint instance, uint primitive, vec2 bary, Ray ray) {
    Material m = materials[instances[instance].material];
    if (m.alpha_mode == ALPHA_OPAQUE) return true;
    float a = m.alpha;
    if (feature_on(scene_features, FEATURE_TEXTURES) && m.kd_texture != NO_TEXTURE) {
        vec2 uv0;
        vec2 uv1;
        scene_uvs_at(instance, primitive, bary, uv0, uv1);
        a *= scene_texture(m.kd_texture, uv0, uv1).w;
    }
    return alpha_covers(m.alpha_mode, a, m.alpha_cutoff, ray.tag, instance, primitive);
}

// What the emissive texture of triangle light l's material makes of its radiance at
// barycentric weights bary: the light stores the material's emissive factor (Light::value).
vec3 scene_emission_texture(Light l, vec2 bary) {
    Material m = materials[instances[l.instance].material];
    if (m.type != MATERIAL_PBR || m.emissive_texture == NO_TEXTURE) return vec3(1.0f);
    vec2 uv0;
    vec2 uv1;
    scene_uvs_at(l.instance, l.primitive, bary, uv0, uv1);
    vec4 c = scene_texture(m.emissive_texture, uv0, uv1);
    return vec3(c.x, c.y, c.z);
}

float scene_light_selection_pdf(uint i) {
    return light_table[i].pdf;
}

// Radiance arriving from the environment along direction d (unit, world space).
vec3 scene_environment_radiance(vec3 d) {
    Light env = lights[params.env_light];
    if (!feature_on(scene_features, FEATURE_ENV_MAP) || params.env_texture == NO_TEXTURE)
        return env.value;
    vec4 c =
        scene_image_lookup(uint(params.env_texture), environment_map_coords(d, params.env_rotation),
                           SLOT_WRAP_REPEAT, SLOT_WRAP_CLAMP, true, false);
    return env.value * vec3(c.x, c.y, c.z);
}

// Solid-angle density with which light sampling picks direction d from the environment,
// given that the environment was chosen.
float scene_environment_pdf(vec3 d) {
    if (!feature_on(scene_features, FEATURE_ENV_MAP) || params.env_texture == NO_TEXTURE)
        return INV_FOUR_PI;
    if (scene_env_table_size() == 0u) return 0.0f;
    TextureInfo info = textures[params.env_texture];
    vec2 st = environment_map_coords(d, params.env_rotation);
    uint pixel = environment_map_pixel(st, info.width, info.height);
    return environment_map_pdf(env_table[pixel].pdf, info.width, info.height, sin(st.y * PI));
}

// Samples light i from point p; the environment map's pixel is drawn with the 32 random bits
// env_slot_bits and the number env_coin.
LightSample scene_sample_light(uint i, vec3 p, vec2 u, uint env_slot_bits, float env_coin) {
    Light l = lights[i];
    if (!feature_on(scene_features, FEATURE_ENV_MAP) || l.type != LIGHT_ENVIRONMENT ||
        params.env_texture == NO_TEXTURE) {
        LightSample ls = sample_light_in(scene_features, l, p, u, SCENE_LIGHT_NORMAL_FROM_VERTICES);
        // The sampled point's barycentrics are sample_triangle_light's (lights.h).
        if (feature_on(scene_features, FEATURE_PBR) &&
            feature_on(scene_features, FEATURE_TEXTURES) && l.type == LIGHT_TRIANGLE &&
            ls.pdf > 0.0f)
            ls.radiance *= scene_emission_texture(l, sample_uniform_triangle(u));
        return ls;
    }
    if (scene_env_table_size() == 0u) return light_sample_none();
    TextureInfo info = textures[params.env_texture];
    uint slot = alias_slot_from_bits(env_slot_bits, scene_env_table_size());
    AliasEntry e = env_table[slot];
    uint pixel = alias_resolve(slot, e.prob, e.alias, env_coin);
    LightSample ls = sample_environment_map(pixel, env_table[pixel].pdf, info.width, info.height,
                                            params.env_rotation, u);
    if (ls.pdf > 0.0f) ls.radiance = scene_environment_radiance(ls.wi);
    return ls;
}

#endif // TP_SHARED_SCENE_ACCESS_H
