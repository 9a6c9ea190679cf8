// The scene reads of both engines: the surface at a hit, the material there, the environment
// and light sampling, written once against the scene's arrays, which each engine names the
// same way before including this file:
//   params, instances[], meshes[], triangles[], positions[], normals[], uvs[], materials[],
//   textures[], texels[], lights[], light_table[], env_table[]  (FlatScene's arrays; GLSL:
//   the storage buffers of shaders/bindings.glsl)
//   scene_features                        the feature mask the reads are restricted to (what
//                                         the scene cannot use is compiled out)
//   scene_error_terms(uint instance)      the instance's InstanceErrorTerms (surface.h)
//   scene_env_table_size()                entries of env_table
//   SCENE_LIGHT_NORMAL_FROM_VERTICES      a constant: how triangle lights' normals are had
//                                         (lights.h, light_normal)
// GLSL includes it after those; C++ includes it inside the engine's class template
// (cpu_ref/cpu_engine.h), so that these functions become its members. It includes nothing
// itself: lights.h, surface.h, texture.h and features.h come first.
#ifndef TP_SHARED_SCENE_ACCESS_H
#define TP_SHARED_SCENE_ACCESS_H

// World-space point, normals and uv of a hit (uv only with textures, its one use).
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
    if (feature_on(scene_features, FEATURE_TEXTURES) && (m.flags & MESH_HAS_UVS) != 0u)
        sp.uv = barycentric_mix2(uvs[base + t.x], uvs[base + t.y], uvs[base + t.z], h.bary);
    return sp;
}

vec3 scene_texture(int index, vec2 st, bool clamp_t) {
    TextureInfo info = textures[index];
    TexelFootprint fp = texture_footprint(st, info.width, info.height, clamp_t);
    uint o = info.offset;
    return texture_bilerp(texels[o + fp.i00], texels[o + fp.i10], texels[o + fp.i01],
                          texels[o + fp.i11], fp.f);
}

// The instance's material with its diffuse texture applied at uv.
Material scene_material(uint instance, vec2 uv) {
    Material m = materials[instances[instance].material];
    if (feature_on(scene_features, FEATURE_TEXTURES) && m.kd_texture != NO_TEXTURE)
        m.kd *= scene_texture(m.kd_texture, uv_to_image(uv), false);
    return m;
}

float scene_light_selection_pdf(uint i) {
    return light_table[i].pdf;
}

// Radiance arriving from the environment along direction d (unit, world space).
vec3 scene_environment_radiance(vec3 d) {
    Light env = lights[params.env_light];
    if (!feature_on(scene_features, FEATURE_ENV_MAP) || params.env_texture == NO_TEXTURE)
        return env.value;
    return env.value *
           scene_texture(params.env_texture, environment_map_coords(d, params.env_rotation), true);
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
        params.env_texture == NO_TEXTURE)
        return sample_light_in(scene_features, l, p, u, SCENE_LIGHT_NORMAL_FROM_VERTICES);
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
