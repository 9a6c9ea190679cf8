#include "scene/flatten.h"

#include "scene/alias_table.h"
#include "scene/dielectric_interfaces.h"
#include "shared/camera.h"
#include "shared/lights.h"
#include "shared/math.h"
#include "shared/surface.h"
#include "shared/texture.h"
#include "util/error.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_inverse.hpp>

#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace tp {

void apply_overrides(Scene& scene, const SceneOverrides& o) {
    if (o.width) scene.settings.width = *o.width;
    if (o.height) scene.settings.height = *o.height;
    if (o.spp) scene.settings.spp = *o.spp;
    if (o.max_depth) scene.settings.max_depth = *o.max_depth;
    if (o.min_depth) scene.settings.min_depth = *o.min_depth;
    if (o.eye) scene.camera.eye = *o.eye;
    if (o.target) scene.camera.target = *o.target;
    if (o.up) scene.camera.up = *o.up;
    if (o.fov) scene.camera.fov_y_degrees = *o.fov;
    if (o.eye || o.target) scene.camera.given = true;
}

namespace {

void store_rows(const glm::mat4& m, vec4& r0, vec4& r1, vec4& r2) {
    r0 = vec4(m[0][0], m[1][0], m[2][0], m[3][0]);
    r1 = vec4(m[0][1], m[1][1], m[2][1], m[3][1]);
    r2 = vec4(m[0][2], m[1][2], m[2][2], m[3][2]);
}

// The camera and film come from the scene file or from the command-line flags that override
// it (apply_overrides), so the messages name both.
void check_camera(const std::string& path, const CameraDesc& c, const RenderSettings& s) {
    if (s.width == 0 || s.height == 0)
        input_error("{}: film.width and film.height (--width, --height) must be positive", path);
    const auto finite = [](const glm::dvec3& v) {
        return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    };
    if (!finite(c.eye) || !finite(c.target) || !is_finite3(c.up))
        input_error("{}: camera.eye, camera.target and camera.up must be finite", path);
    if (!(c.fov_y_degrees > 0.0f && c.fov_y_degrees < 180.0f))
        input_error("{}: camera.fov (--fov) must lie in (0, 180) degrees, got {}", path,
                    c.fov_y_degrees);
    const glm::dvec3 d = c.target - c.eye;
    if (glm::length(d) == 0.0)
        input_error("{}: camera.eye and camera.target (--eye, --target) coincide", path);
    if (glm::length(d) > kMaxWorldRange)
        input_error("{}: camera.target lies {:.3g} m from camera.eye, beyond the {:.3g} m that "
                    "float32 geometry represents (docs/scene-format.md, \"Range\")",
                    path, glm::length(d), kMaxWorldRange);
    if (glm::length(glm::cross(glm::normalize(d), glm::dvec3(c.up))) < 1e-6)
        input_error("{}: camera.up (--up) is zero or parallel to the viewing direction", path);
}

// A bounding box in double.
struct Box {
    glm::dvec3 lo{std::numeric_limits<double>::max()}, hi{-std::numeric_limits<double>::max()};
    void add(const glm::dvec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void add(const Box& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    bool empty() const { return lo.x > hi.x; }
    // The largest coordinate of a point of the box relative to `from`: a corner's.
    double farthest(const glm::dvec3& from) const {
        const glm::dvec3 m = glm::max(glm::abs(lo - from), glm::abs(hi - from));
        return std::max(m.x, std::max(m.y, m.z));
    }
};

// The float32 range rule (docs/scene-format.md, "Range"), for object i: its mesh's extent in its
// own space (`size`, the largest coordinate of a stored position) and its vertices' largest
// coordinate relative to the camera or, before the camera is framed, the scene's centre (`far`).
void check_range(const Scene& scene, size_t i, double size, double far, const char* from) {
    const Object& o = scene.objects[i];
    if (!(size <= kMaxWorldRange))
        input_error("{}: object {} ('{}') spans {:.3g} m in its own space, beyond the {:.3g} m "
                    "that float32 geometry represents (docs/scene-format.md, \"Range\")",
                    scene.path, i, o.name, size, kMaxWorldRange);
    if (!(far <= kMaxWorldRange))
        input_error("{}: object {} ('{}') has a vertex {:.3g} m from the {}, beyond the {:.3g} m "
                    "that float32 geometry represents (docs/scene-format.md, \"Range\")",
                    scene.path, i, o.name, far, from, kMaxWorldRange);
}

// Places the camera on +Z of the bounding sphere's centre, far enough for the sphere to fit
// the vertical field of view.
void frame_camera(CameraDesc& c, const Box& world, float aspect) {
    const glm::dvec3 centre = 0.5 * (world.lo + world.hi);
    const double radius = std::max(0.5 * glm::length(world.hi - world.lo), 1e-6);
    const double half = glm::radians(0.5 * double(c.fov_y_degrees)) * std::min(double(aspect), 1.0);
    c.target = centre;
    c.eye = centre + glm::dvec3(0.0, 0.0, 1.05 * radius / std::sin(half));
}

} // namespace

vec4 flat_texel_linear(const FlatScene& scene, uint32_t image, size_t i, bool srgb) {
    return scene.images[image].linear(i, srgb);
}

FlatScene flatten(const Scene& input) {
    const std::optional<DielectricInterfaces> merged = merge_dielectric_interfaces(input);
    const Scene& scene = merged ? merged->scene : input;
    FlatScene f;
    f.dielectric_interfaces = merged ? merged->faces : 0;
    f.name = scene.path;
    f.spp = scene.settings.spp;
    f.materials = scene.materials;

    if (scene.objects.empty()) input_error("{}: the scene has no objects", scene.path);

    // Meshes that some object uses, each stored once, relative to the lowest corner of its
    // bounding box (FlatScene::origin).
    std::map<uint32_t, uint32_t> mesh_slot;
    std::vector<glm::dvec3> corner; // per slot
    std::vector<double> extent;     // per slot: the largest stored coordinate
    // The second uv set and the tangents are stored only where some mesh has them, then for
    // every vertex (zero where a mesh has none), like the normals and the first uv set.
    bool any_uv1 = false, any_tangents = false;
    for (const Object& o : scene.objects) {
        any_uv1 |= !scene.meshes[o.mesh].uvs1.empty();
        any_tangents |= !scene.meshes[o.mesh].tangents.empty();
    }
    for (const Object& o : scene.objects) {
        if (mesh_slot.count(o.mesh)) continue;
        const Mesh& m = scene.meshes[o.mesh];
        MeshInfo info{};
        info.first_triangle = uint32_t(f.triangles.size());
        info.first_vertex = uint32_t(f.positions.size());
        info.triangle_count = uint32_t(m.triangles.size());
        info.vertex_count = uint32_t(m.positions.size());
        info.flags = (m.normals.empty() ? 0u : MESH_HAS_NORMALS) |
                     (m.uvs.empty() ? 0u : MESH_HAS_UVS) | (m.uvs1.empty() ? 0u : MESH_HAS_UV1) |
                     (m.tangents.empty() ? 0u : MESH_HAS_TANGENTS);
        info.bvh_root = NO_INDEX;
        Box box;
        for (const glm::dvec3& p : m.positions) box.add(p);
        const glm::dvec3 c = box.empty() ? glm::dvec3(0.0) : box.lo;
        for (const glm::dvec3& p : m.positions) f.positions.push_back(vec3(p - c));
        corner.push_back(c);
        extent.push_back(box.empty() ? 0.0 : box.farthest(c));
        if (m.normals.empty())
            f.normals.resize(f.positions.size(), vec3(0.0f));
        else
            f.normals.insert(f.normals.end(), m.normals.begin(), m.normals.end());
        if (m.uvs.empty())
            f.uvs.resize(f.positions.size(), vec2(0.0f));
        else
            f.uvs.insert(f.uvs.end(), m.uvs.begin(), m.uvs.end());
        if (any_uv1) {
            if (m.uvs1.empty())
                f.uvs1.resize(f.positions.size(), vec2(0.0f));
            else
                f.uvs1.insert(f.uvs1.end(), m.uvs1.begin(), m.uvs1.end());
        }
        if (any_tangents) {
            if (m.tangents.empty())
                f.tangents.resize(f.positions.size(), vec4(0.0f));
            else
                f.tangents.insert(f.tangents.end(), m.tangents.begin(), m.tangents.end());
        }
        f.triangles.insert(f.triangles.end(), m.triangles.begin(), m.triangles.end());
        f.unique_triangles += m.triangles.size();
        mesh_slot[o.mesh] = uint32_t(f.meshes.size());
        f.meshes.push_back(info);
    }

    CameraDesc cam = scene.camera;
    const float aspect = float(scene.settings.width) / float(std::max(scene.settings.height, 1u));
    if (!cam.given) {
        // Framed from the world bounds in the scene's coordinates, in double.
        std::vector<Box> boxes(scene.objects.size());
        Box world;
        for (size_t i = 0; i < scene.objects.size(); ++i) {
            const Object& o = scene.objects[i];
            for (const glm::dvec3& p : scene.meshes[o.mesh].positions)
                boxes[i].add(glm::dvec3(o.transform * glm::dvec4(p, 1.0)));
            world.add(boxes[i]);
        }
        for (size_t i = 0; i < scene.objects.size(); ++i)
            if (!boxes[i].empty())
                check_range(scene, i, extent[mesh_slot.at(scene.objects[i].mesh)],
                            boxes[i].farthest(0.5 * (world.lo + world.hi)), "scene's centre");
        frame_camera(cam, world, aspect);
    }
    check_camera(scene.path, cam, scene.settings);
    f.origin = cam.eye;
    f.params.camera = camera_make(vec3(0.0f), vec3(cam.target - cam.eye), cam.up, cam.fov_y_degrees,
                                  scene.settings.width, scene.settings.height);

    // Instances: the linear part M as it is, the translation M c + (T - origin) for the mesh's
    // corner c. The bounds are those of the float world the engines trace, M q + t.
    Box world;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        const uint32_t slot = mesh_slot.at(o.mesh);
        const glm::dvec3 t =
            glm::dmat3(o.transform) * corner[slot] + (glm::dvec3(o.transform[3]) - f.origin);
        glm::mat4 to_world(o.transform);
        to_world[3] = vec4(vec3(t), 1.0f);
        Instance inst{};
        store_rows(to_world, inst.to_world0, inst.to_world1, inst.to_world2);
        store_rows(glm::affineInverse(to_world), inst.to_object0, inst.to_object1, inst.to_object2);
        inst.mesh = slot;
        inst.material = o.material;
        inst.light_offset = NO_INDEX;
        f.instanced_triangles += scene.meshes[o.mesh].triangles.size();
        f.instances.push_back(inst);
        f.instance_names.push_back(o.name);

        const MeshInfo& mesh = f.meshes[slot];
        const glm::dmat3 linear(to_world);
        const glm::dvec3 translation(to_world[3]);
        Box box;
        for (uint32_t v = 0; v < mesh.vertex_count; ++v)
            box.add(linear * glm::dvec3(f.positions[mesh.first_vertex + v]) + translation);
        if (box.empty()) continue;
        check_range(scene, i, extent[slot], box.farthest(glm::dvec3(0.0)), "camera");
        world.add(box);
    }
    f.bounds_min = vec3(world.lo);
    f.bounds_max = vec3(world.hi);
    f.params.max_depth = scene.settings.max_depth;
    f.params.min_depth = scene.settings.min_depth;

    // Images (their texels shared, not copied: image/texture.h) and the slots that read them.
    for (const Texture& t : scene.textures) {
        TextureInfo info{};
        info.width = t.width;
        info.height = t.height;
        info.format = t.format;
        f.textures.push_back(info);
        f.images.push_back(t);
    }
    f.texture_slots = scene.texture_slots;

    // Lights, with selection weights proportional to an estimate of emitted power; any
    // positive weights give an unbiased estimator, power makes it efficient.
    const double pi = glm::pi<double>();
    // An environment's or directional light's power is the flux it sends into a sphere of the
    // scene's size: the bounding sphere, but no larger than the camera's distance to its target,
    // so that an object far out of view cannot give those lights nearly every light sample (an
    // object at 1e10 would leave a point light a selection probability of 1e-18).
    const double radius =
        std::min(0.5 * glm::length(world.hi - world.lo), glm::length(cam.target - cam.eye));
    const double disk = pi * radius * radius;
    std::vector<double> weights;
    for (const LightDesc& d : scene.lights) {
        Light l{};
        l.type = d.type;
        // A point or spot light's p0 is a position; a directional light's is a direction.
        const bool punctual = d.type == LIGHT_POINT || d.type == LIGHT_SPOT;
        l.p0 = punctual ? vec3(d.position - f.origin) : d.direction;
        l.value = d.value;
        double solid_angle = 4.0 * pi;
        if (d.type == LIGHT_SPOT) {
            // The falloff of lights.h, spot_light_falloff, as a scale and an offset of the
            // cosine to the axis (KHR_lights_punctual, "Spot").
            const double ci = std::cos(double(d.inner_cone)), co = std::cos(double(d.outer_cone));
            const double scale = 1.0 / std::max(1e-3, ci - co);
            l.p1 = d.direction;
            l.p2 = vec3(float(scale), float(-co * scale), 0.0f);
            solid_angle = 2.0 * pi * (1.0 - co); // the outer cone bounds its power
        }
        f.lights.push_back(l);
        const double lum = double(luminance(l.value));
        weights.push_back(punctual ? solid_angle * lum : disk * lum);
    }
    for (uint32_t i = 0; i < f.instances.size(); ++i) {
        Instance& inst = f.instances[i];
        const Material& m = f.materials[inst.material];
        if (is_black(m.ke)) continue;
        const MeshInfo& mesh = f.meshes[inst.mesh];
        inst.light_offset = uint32_t(f.lights.size());
        // An emissive texture scales the radiance where the light is sampled (shared/
        // scene_access.h); its mean stands for it in the selection weights, which need only be
        // positive wherever the light emits.
        vec3 emission_mean(1.0f);
        if (m.type == MATERIAL_PBR && m.emissive_texture != NO_TEXTURE)
            emission_mean = scene.textures[scene.texture_slots[size_t(m.emissive_texture)].image]
                                .mean_linear(true);
        // The front face is the mesh's counter-clockwise side, carried to the world by the
        // normal transform M^-T (surface.h), whose sign does not follow det M. A mirroring
        // transform (det M < 0) makes the world-space winding clockwise, so the light's vertices
        // are stored in reverse order: its normal, formed from them, is then the front's too.
        const bool mirrored = glm::determinant(glm::dmat3(scene.objects[i].transform)) < 0.0;
        for (uint32_t t = 0; t < mesh.triangle_count; ++t) {
            const uvec3 tri = f.triangles[mesh.first_triangle + t];
            Light l{};
            l.type = LIGHT_TRIANGLE;
            l.p0 = instance_point_to_world(inst, f.positions[mesh.first_vertex + tri.x]);
            l.p1 = instance_point_to_world(inst, f.positions[mesh.first_vertex + tri.y]);
            l.p2 = instance_point_to_world(inst, f.positions[mesh.first_vertex + tri.z]);
            if (mirrored) std::swap(l.p1, l.p2);
            l.area = 0.5f * glm::length(glm::cross(l.p1 - l.p0, l.p2 - l.p0));
            l.normal = triangle_light_normal(l.p0, l.p1, l.p2);
            l.instance = i;
            l.primitive = t;
            l.value = m.ke;
            f.lights.push_back(l);
            weights.push_back(pi * double(l.area) * double(luminance(m.ke * emission_mean)));
        }
    }
    f.params.env_light = NO_INDEX;
    f.params.env_texture = NO_TEXTURE;
    f.params.env_rotation = glm::radians(scene.environment.rotation_degrees);
    if (scene.environment.kind != EnvironmentKind::None) {
        Light l{};
        l.type = LIGHT_ENVIRONMENT;
        l.value = scene.environment.radiance;
        double mean_luminance = double(luminance(l.value));
        if (scene.environment.kind == EnvironmentKind::Map) {
            const Texture& t = scene.textures.at(size_t(scene.environment.texture));
            f.params.env_texture = scene.environment.texture;
            // Pixel (x, y) covers solid angle (2 pi / w)(pi / h) sin(theta_y).
            std::vector<double> pixel_w(t.texel_count());
            double integral = 0.0;
            for (uint32_t y = 0; y < t.height; ++y) {
                const double sin_theta = std::sin(pi * (y + 0.5) / t.height);
                for (uint32_t x = 0; x < t.width; ++x) {
                    const size_t i = size_t(y) * t.width + x;
                    pixel_w[i] = double(luminance(vec3(t.linear(i, true)))) * sin_theta;
                    integral += pixel_w[i];
                }
            }
            const double solid_angle_per_weight = 2.0 * pi * pi / (double(t.width) * t.height);
            mean_luminance *= integral * solid_angle_per_weight / (4.0 * pi);
            if (integral > 0.0) f.env_table = build_alias_table(pixel_w);
        }
        if (mean_luminance > 0.0) {
            f.params.env_light = uint32_t(f.lights.size());
            f.lights.push_back(l);
            // Flux into the bounding sphere from a uniform surround of radiance L: 4 pi^2 r^2 L.
            weights.push_back(4.0 * pi * disk * mean_luminance);
        }
    }
    f.params.env_alias_offset = 0;

    double total = 0.0;
    for (double w : weights) total += w;
    if (total > 0.0)
        f.light_table = build_alias_table(weights);
    else
        f.lights.clear(); // nothing emits: no next-event estimation at all
    if (f.lights.empty()) {
        f.params.env_light = NO_INDEX;
        for (Instance& inst : f.instances) inst.light_offset = NO_INDEX;
    }
    f.params.light_count = uint32_t(f.lights.size());
    return f;
}

std::vector<uint32_t> instances_per_mesh(const FlatScene& scene) {
    std::vector<uint32_t> uses(scene.meshes.size(), 0);
    for (const Instance& inst : scene.instances)
        if (inst.mesh < uses.size()) ++uses[inst.mesh];
    return uses;
}

} // namespace tp
