#include "scene/scene.h"

#include "shared/math.h"
#include "util/error.h"

#include <cmath>
#include <utility>

namespace tp {

Material default_material() {
    Material m{};
    m.kd = vec3(0.0f);
    m.kd_texture = NO_TEXTURE;
    m.ks = vec3(0.0f);
    m.ns = 1.0f;
    m.ke = vec3(0.0f);
    m.ior = 1.5f;
    m.tf = vec3(1.0f);
    m.type = MATERIAL_PHONG;
    m.metallic = 0.0f;
    m.roughness = 1.0f;
    m.transmission = 0.0f;
    m.specular = 1.0f;
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
    m.flags = 0u;
    return m;
}

Material default_pbr_material() {
    Material m = default_material();
    m.type = MATERIAL_PBR;
    m.kd = vec3(1.0f);
    m.ks = vec3(1.0f);
    m.metallic = 1.0f;
    return m;
}

TextureSlot make_texture_slot(uint32_t image, vec3 transform_s, vec3 transform_t,
                              uint32_t sampling) {
    TextureSlot t{};
    t.image = image;
    t.transform_s = transform_s;
    t.transform_t = transform_t;
    t.sampling = sampling;
    return t;
}

TextureSlot obj_texture_slot(uint32_t image, bool srgb) {
    return make_texture_slot(image, vec3(1.0f, 0.0f, 0.0f), vec3(0.0f, -1.0f, 1.0f),
                             srgb ? SLOT_SRGB : 0u);
}

namespace {
void check_color(const vec3& c, const std::string& where, const char* field) {
    if (!is_finite3(c))
        input_error("{}: {} must be finite, got ({}, {}, {})", where, field, c.x, c.y, c.z);
    if (c.x < 0.0f || c.y < 0.0f || c.z < 0.0f)
        input_error("{}: {} must not be negative, got ({}, {}, {})", where, field, c.x, c.y, c.z);
}
} // namespace

void validate_material(const Material& m, const std::string& where) {
    check_color(m.kd, where, "Kd");
    check_color(m.ks, where, "Ks");
    check_color(m.ke, where, "Ke");
    check_color(m.tf, where, "Tf");
    if (!std::isfinite(m.ns) || m.ns < 0.0f)
        input_error("{}: Ns must be finite and >= 0, got {}", where, m.ns);
    if (!std::isfinite(m.ior) || m.ior <= 0.0f)
        input_error("{}: Ni must be finite and > 0, got {}", where, m.ior);
    if (m.type == MATERIAL_PHONG) {
        // Energy conservation of the modified Phong BRDF needs kd + ks <= 1 per channel
        // (Lafortune & Willems 1994). A tolerance of 1e-6 absorbs decimal round-off in files.
        for (int c = 0; c < 3; ++c)
            if (m.kd[c] + m.ks[c] > 1.0f + 1e-6f)
                input_error("{}: Kd + Ks must be <= 1 per channel for energy conservation, "
                            "channel {} has {} + {}",
                            where, "RGB"[c], m.kd[c], m.ks[c]);
    }
    if (m.type == MATERIAL_MIRROR && max3(m.ks) > 1.0f + 1e-6f)
        input_error("{}: a mirror's Ks must be <= 1, got {}", where, max3(m.ks));
    if (m.type == MATERIAL_PBR) {
        // glTF's ranges (its schema, KHR_materials_*): the BSDF of shared/pbr.h is defined for
        // these and no others. The specular colour may exceed 1 (its f0 is clamped).
        if (max3(m.kd) > 1.0f)
            input_error("{}: base_color must be in [0, 1], got ({}, {}, {})", where, m.kd.x,
                        m.kd.y, m.kd.z);
        const std::pair<const char*, float> unit[] = {{"metallic", m.metallic},
                                                      {"roughness", m.roughness},
                                                      {"transmission", m.transmission},
                                                      {"specular", m.specular},
                                                      {"alpha", m.alpha},
                                                      {"alpha_cutoff", m.alpha_cutoff}};
        for (const auto& [name, v] : unit)
            if (!(v >= 0.0f && v <= 1.0f))
                input_error("{}: {} must be in [0, 1], got {}", where, name, v);
        if (max3(m.tf) > 1.0f)
            input_error("{}: attenuation_color must be in [0, 1], got ({}, {}, {})", where, m.tf.x,
                        m.tf.y, m.tf.z);
        if (!(m.attenuation_distance > 0.0f))
            input_error("{}: attenuation_distance must be > 0, got {}", where,
                        m.attenuation_distance);
        if (!std::isfinite(m.normal_scale))
            input_error("{}: normal_scale must be finite, got {}", where, m.normal_scale);
    }
}

void light_if_unlit(Scene& scene, std::vector<std::string>& warnings) {
    if (!scene.lights.empty() || scene.environment.kind != EnvironmentKind::None) return;
    for (const Object& o : scene.objects)
        if (max3(scene.materials[o.material].ke) > 0.0f) return;
    scene.environment.kind = EnvironmentKind::Constant;
    scene.environment.radiance = vec3(1.0f);
    warnings.push_back(fmt::format(
        "{}: no emissive material: lighting it with a constant white environment of radiance 1",
        scene.path));
}

void finalize_mesh(Mesh& mesh, const std::string& where, uint64_t& skipped_triangles) {
    const size_t nv = mesh.positions.size();
    if (!mesh.normals.empty() && mesh.normals.size() != nv)
        input_error("{}: {} normals for {} positions", where, mesh.normals.size(), nv);
    if (!mesh.uvs.empty() && mesh.uvs.size() != nv)
        input_error("{}: {} uvs for {} positions", where, mesh.uvs.size(), nv);
    for (size_t i = 0; i < nv; ++i) {
        const glm::dvec3 p = mesh.positions[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            input_error("{}: vertex {} is not finite ({}, {}, {})", where, i, p.x, p.y, p.z);
    }
    for (size_t i = 0; i < mesh.normals.size(); ++i)
        if (!is_finite3(mesh.normals[i])) input_error("{}: normal {} is not finite", where, i);
    for (size_t i = 0; i < mesh.uvs.size(); ++i)
        if (!std::isfinite(mesh.uvs[i].x) || !std::isfinite(mesh.uvs[i].y))
            input_error("{}: uv {} is not finite", where, i);

    std::vector<uvec3> kept;
    kept.reserve(mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const uvec3 tri = mesh.triangles[t];
        for (int k = 0; k < 3; ++k)
            if (tri[k] >= nv)
                input_error("{}: triangle {} uses vertex {} but there are {}", where, t, tri[k],
                            nv);
        // Zero area in double precision: the triangle can never be hit, so it is skipped.
        const glm::dvec3 a = mesh.positions[tri.x], b = mesh.positions[tri.y],
                         c = mesh.positions[tri.z];
        const glm::dvec3 n = glm::cross(b - a, c - a);
        if (n.x == 0.0 && n.y == 0.0 && n.z == 0.0) {
            ++skipped_triangles;
            continue;
        }
        kept.push_back(tri);
    }
    mesh.triangles.swap(kept);
}

} // namespace tp
