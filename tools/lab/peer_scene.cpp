#include "tools/lab/peer_scene.h"

#include "shared/math.h"
#include "util/error.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace tp::lab {
namespace {

glm::dvec3 transform_point(const glm::dmat4& m, const glm::dvec3& p) {
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}

// Area and area-weighted centroid and normal of an object's triangles in world space.
struct Emitter {
    double area = 0;
    glm::dvec3 centroid{0.0}, normal{0.0};
};

Emitter measure_emitter(const Scene& scene, const Object& o) {
    Emitter e;
    const Mesh& m = scene.meshes[o.mesh];
    for (const uvec3& t : m.triangles) {
        const glm::dvec3 a = transform_point(o.transform, m.positions[t.x]);
        const glm::dvec3 b = transform_point(o.transform, m.positions[t.y]);
        const glm::dvec3 c = transform_point(o.transform, m.positions[t.z]);
        const glm::dvec3 n = glm::cross(b - a, c - a); // |n| = 2 area, front side (CCW)
        const double area = 0.5 * glm::length(n);
        e.area += area;
        e.centroid += area * (a + b + c) / 3.0;
        e.normal += n;
    }
    if (e.area > 0) e.centroid /= e.area;
    if (glm::length(e.normal) > 0) e.normal = glm::normalize(e.normal);
    return e;
}

std::string triple(const vec3& v) {
    return fmt::format("{} {} {}", v.x, v.y, v.z);
}

} // namespace

std::vector<std::string> make_peer_variant(Scene& scene, std::string& reason) {
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        if (m.type != MATERIAL_PHONG || m.kd_texture != NO_TEXTURE) {
            reason = fmt::format("material '{}' is a mirror, dielectric or textured, which the "
                                 "tutorial's OBJ material does not reproduce",
                                 scene.material_names[i]);
            return {};
        }
    }
    std::vector<std::string> changes;
    std::vector<Object> kept;
    for (const Object& o : scene.objects) {
        const vec3 ke = scene.materials[o.material].ke;
        if (max3(ke) <= 0.0f) {
            kept.push_back(o);
            continue;
        }
        const Emitter e = measure_emitter(scene, o);
        LightDesc l;
        l.type = LIGHT_POINT;
        l.position = e.centroid + 0.25 * std::sqrt(e.area) * e.normal;
        l.value = ke * float(e.area / 4.0);
        scene.lights.push_back(l);
        changes.push_back(fmt::format(
            "emitter '{}' (area {:.4g} m^2, Ke {}) replaced by a point light of the same power at "
            "({}) with intensity ({}) W/sr",
            o.name, e.area, triple(ke), triple(vec3(l.position)), triple(l.value)));
    }
    scene.objects = kept;
    if (scene.environment.kind != EnvironmentKind::None) {
        scene.environment = EnvironmentDesc{};
        changes.push_back("environment removed");
    }
    if (scene.lights.empty()) reason = "no light is left once the environment is removed";
    return changes;
}

void write_obj(const FlatScene& s, const std::string& obj_path) {
    const fs::path mtl_path = fs::path(obj_path).replace_extension(".mtl");
    std::ofstream mtl(mtl_path);
    for (size_t i = 0; i < s.materials.size(); ++i) {
        const Material& m = s.materials[i];
        mtl << fmt::format("newmtl m{}\nKd {}\nKs {}\nNs {}\nillum 2\n\n", i, triple(m.kd),
                           triple(m.ks), m.ns);
    }
    std::ofstream obj(obj_path);
    obj << "# twinpath bench: world-space triangles of " << s.name << "\n";
    obj << "mtllib " << mtl_path.filename().string() << "\n";
    // OBJ indices are 1-based and count each kind of line (v, vt, vn) over the whole file; a
    // mesh without normals or uvs writes none of them.
    struct {
        uint64_t v = 1, vt = 1, vn = 1;
    } base;
    for (size_t i = 0; i < s.instances.size(); ++i) {
        const Instance& inst = s.instances[i];
        const MeshInfo& mesh = s.meshes[inst.mesh];
        const vec4 w[3] = {inst.to_world0, inst.to_world1, inst.to_world2};
        const vec4 o[3] = {inst.to_object0, inst.to_object1, inst.to_object2};
        const bool normals = (mesh.flags & MESH_HAS_NORMALS) != 0u;
        const bool uvs = (mesh.flags & MESH_HAS_UVS) != 0u;
        for (uint32_t v = 0; v < mesh.vertex_count; ++v) {
            const vec3 p = s.positions[mesh.first_vertex + v];
            obj << "v "
                << triple(vec3(dot(vec3(w[0]), p) + w[0].w, dot(vec3(w[1]), p) + w[1].w,
                               dot(vec3(w[2]), p) + w[2].w))
                << "\n";
            if (uvs) {
                const vec2 uv = s.uvs[mesh.first_vertex + v];
                obj << fmt::format("vt {} {}\n", uv.x, uv.y);
            }
            if (!normals) continue;
            // Normals map to world by the inverse transpose: n_j = sum_k to_object[k][j] n_k.
            const vec3 n = s.normals[mesh.first_vertex + v];
            obj << "vn "
                << triple(normalize(n.x * vec3(o[0]) + n.y * vec3(o[1]) + n.z * vec3(o[2])))
                << "\n";
        }
        obj << "usemtl m" << inst.material << "\n";
        for (uint32_t t = 0; t < mesh.triangle_count; ++t) {
            const uvec3 tri = s.triangles[mesh.first_triangle + t];
            obj << "f";
            for (const uint32_t k : {tri.x, tri.y, tri.z}) {
                obj << " " << base.v + k;
                if (uvs || normals) obj << "/";
                if (uvs) obj << base.vt + k;
                if (normals) obj << "/" << base.vn + k;
            }
            obj << "\n";
        }
        base.v += mesh.vertex_count;
        if (uvs) base.vt += mesh.vertex_count;
        if (normals) base.vn += mesh.vertex_count;
    }
    if (!obj || !mtl) runtime_error("cannot write {}", obj_path);
}

std::vector<std::string> peer_scene_arguments(const FlatScene& s) {
    const Camera& c = s.params.camera;
    const auto v = [](const vec3& x) {
        return std::vector<std::string>{fmt::format("{}", x.x), fmt::format("{}", x.y),
                                        fmt::format("{}", x.z)};
    };
    std::vector<std::string> args;
    const auto add = [&](const std::string& flag, const std::vector<std::string>& values) {
        args.push_back(flag);
        args.insert(args.end(), values.begin(), values.end());
    };
    add("--size", {std::to_string(c.width), std::to_string(c.height)});
    add("--vp", v(c.eye));
    add("--vi", v(c.eye + c.forward));
    add("--vu", v(c.up));
    add("--fov", {fmt::format("{}", 2.0 * std::atan(double(c.tan_half_fov_y)) * 180.0 / M_PI)});
    args.push_back("--righthanded");
    for (const Light& l : s.lights) {
        std::vector<std::string> values;
        if (l.type == LIGHT_POINT) {
            values = v(l.p0);
        } else if (l.type == LIGHT_DIRECTIONAL) {
            values = v(-l.p0); // the tutorial wants the direction the light travels
        } else {
            continue; // make_peer_variant leaves no other kind
        }
        const std::vector<std::string> rgb = v(l.value);
        values.insert(values.end(), rgb.begin(), rgb.end());
        add(l.type == LIGHT_POINT ? "--pointlight" : "--directionallight", values);
    }
    return args;
}

} // namespace tp::lab
