#include "scene/gltf_loader.h"

#include "scene/glb_container.h"
#include "scene/gltf_accessor.h"
#include "scene/gltf_document.h"
#include "scene/gltf_material.h"
#include "scene/gltf_resources.h"
#include "scene/gltf_textures.h"
#include "scene/json_reader.h"
#include "scene/tangents.h"
#include "scene/text_parse.h"
#include "shared/math.h"
#include "util/error.h"

#include <glm/gtc/matrix_access.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <numeric>
#include <set>

namespace tp {
namespace {

constexpr uint32_t kModeTriangles = 4, kModeStrip = 5, kModeFan = 6;

// What a material's texture slots need of the meshes it is on: the uv sets they read and,
// for a normal map, a tangent frame.
struct SlotNeeds {
    std::string uv_field[2];      // a textureInfo that reads TEXCOORD_n; empty: none does
    int normal_slot = NO_TEXTURE; // the normal map's slot
};

std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) input_error("{}: cannot open file", path);
    std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) input_error("{}: cannot read file", path);
    return bytes;
}

std::string element_name(const std::string& name, const char* array, size_t i) {
    return name.empty() ? fmt::format("{}[{}]", array, i) : name;
}

class Builder {
  public:
    Builder(const GltfDocument& d, const GltfResources& res, const GltfOptions& options,
            Scene& scene)
        : d_(d), res_(res), options_(options), s_(scene) {}

    void build() {
        convert_materials();
        traverse(scene_roots());
        choose_camera();
        note_scene_level();
    }

    // Scene-level notes, deduplicated and in a stable order: what is not rendered, and what a
    // path tracer ignores.
    std::set<std::string> notes, ignored;

  private:
    void note(const std::string& n) { notes.insert(n); }

    // ---- materials and textures --------------------------------------------------------------

    void add_material(const GltfMaterial& gm, const std::string& name, const std::string& field) {
        GltfMaterialMapping m = map_gltf_material(gm);
        SlotNeeds needs;
        for (const GltfTextureUse& use : gltf_material_textures(gm)) {
            const int slot = textures_.slot(*use.ref, use.srgb, m.dropped, m.ignored);
            m.material.*use.field = slot;
            if (slot == NO_TEXTURE) continue;
            const bool uv1 = (s_.texture_slots[size_t(slot)].sampling & SLOT_UV1) != 0u;
            if (needs.uv_field[uv1].empty()) needs.uv_field[uv1] = use.ref->field;
        }
        needs.normal_slot = m.material.normal_texture;
        validate_material(m.material, fmt::format("{}: {}", d_.path, field));
        s_.materials.push_back(m.material);
        s_.material_names.push_back(name);
        s_.material_dropped.push_back(std::move(m.dropped));
        s_.material_ignored.push_back(std::move(m.ignored));
        needs_of_material_.push_back(needs);
    }

    void convert_materials() {
        for (size_t i = 0; i < d_.materials.size(); ++i)
            add_material(d_.materials[i], element_name(d_.materials[i].name, "materials", i),
                         fmt::format("materials[{}]", i));
    }

    // glTF's default material (section 3.9.6): white, metallic 1, roughness 1.
    uint32_t default_material() {
        if (default_material_ == NO_INDEX) {
            add_material(GltfMaterial{}, "default (glTF)", "the default material");
            default_material_ = uint32_t(s_.materials.size() - 1);
        }
        return default_material_;
    }

    // ---- meshes ------------------------------------------------------------------------------

    // Accessor `name` of primitive p as `n`-component values, `count` elements (0: any).
    std::vector<double> attribute(const GltfPrimitive& p, const std::string& field,
                                  const std::string& name, uint32_t n, uint32_t count) {
        const uint32_t a = p.attributes.at(name);
        const std::string f = field + ".attributes." + name;
        const GltfAccessor& acc = d_.accessors[a];
        if (acc.components != n || acc.type.rfind("MAT", 0) == 0)
            input_error("{}: {}: accessors[{}] is a {}, {} needs a VEC{}", d_.path, f, a, acc.type,
                        name, n);
        if (count != 0 && acc.count != count)
            input_error("{}: {}: accessors[{}] has {} elements but POSITION has {}", d_.path, f, a,
                        acc.count, count);
        return read_gltf_accessor(d_, res_, a, f);
    }

    // The primitive's triangles as vertex indices (section 3.7.2.1, "Topology types").
    std::vector<uvec3> triangles(const GltfPrimitive& p, const std::string& field,
                                 uint32_t vertices) {
        std::vector<uint32_t> idx;
        if (p.indices != GLTF_NONE) {
            idx = read_gltf_indices(d_, res_, uint32_t(p.indices), field + ".indices");
        } else {
            idx.resize(vertices);
            std::iota(idx.begin(), idx.end(), 0u);
        }
        const std::string what = p.indices != GLTF_NONE ? field + ".indices" : field;
        std::vector<uvec3> tris;
        if (p.mode == kModeTriangles) {
            if (idx.size() % 3 != 0)
                input_error("{}: {}: {} indices are not a multiple of 3 (mode TRIANGLES)", d_.path,
                            what, idx.size());
            for (size_t i = 0; i + 2 < idx.size(); i += 3)
                tris.push_back({idx[i], idx[i + 1], idx[i + 2]});
        } else if (idx.size() >= 3) {
            for (size_t i = 0; i + 2 < idx.size(); ++i) {
                if (p.mode == kModeStrip) // {v_i, v_i+(1+i%2), v_i+(2-i%2)}: winding kept
                    tris.push_back(i % 2 == 0 ? uvec3{idx[i], idx[i + 1], idx[i + 2]}
                                              : uvec3{idx[i], idx[i + 2], idx[i + 1]});
                else // fan
                    tris.push_back({idx[i + 1], idx[i + 2], idx[0]});
            }
        }
        for (const uvec3& t : tris)
            for (int k = 0; k < 3; ++k)
                if (t[k] >= vertices)
                    input_error("{}: {}: vertex index {} is out of range: POSITION has {} "
                                "elements",
                                d_.path, what, t[k], vertices);
        return tris;
    }

    // Keeps only the vertices the triangles use, in their order (a primitive may index a
    // small part of a shared vertex array, whose other vertices would widen its bounds).
    static void drop_unused_vertices(Mesh& m) {
        std::vector<uint32_t> remap(m.positions.size(), NO_INDEX);
        for (const uvec3& t : m.triangles)
            for (int k = 0; k < 3; ++k) remap[t[k]] = 0;
        if (std::find(remap.begin(), remap.end(), NO_INDEX) == remap.end()) return;
        Mesh out;
        out.name = m.name;
        for (size_t v = 0; v < remap.size(); ++v) {
            if (remap[v] == NO_INDEX) continue;
            remap[v] = uint32_t(out.positions.size());
            out.positions.push_back(m.positions[v]);
            if (!m.normals.empty()) out.normals.push_back(m.normals[v]);
            if (!m.uvs.empty()) out.uvs.push_back(m.uvs[v]);
            if (!m.uvs1.empty()) out.uvs1.push_back(m.uvs1[v]);
            if (!m.tangents.empty()) out.tangents.push_back(m.tangents[v]);
        }
        for (const uvec3& t : m.triangles)
            out.triangles.push_back({remap[t.x], remap[t.y], remap[t.z]});
        m = std::move(out);
    }

    // The scene mesh of primitive k of mesh i, or NO_INDEX when it is not rendered. Primitives
    // with the same geometry (accessors, topology, and what their materials' slots read: the uv
    // sets, the tangents and the map they are generated for) share one scene mesh, whichever
    // glTF mesh holds them: assets reuse accessors under meshes that differ only in material.
    uint32_t primitive_mesh(uint32_t mi, uint32_t k) {
        const GltfPrimitive& p = d_.meshes[mi].primitives[k];
        const SlotNeeds& needs = needs_of_material_[material_of(p)];
        auto accessor = [&](const std::string& name) {
            const auto it = p.attributes.find(name);
            return it == p.attributes.end() ? -1.0 : double(it->second);
        };
        std::vector<double> key = {accessor("POSITION"),
                                   accessor("NORMAL"),
                                   double(p.indices),
                                   double(p.mode),
                                   double(p.morph_targets),
                                   needs.uv_field[0].empty() ? -2.0 : accessor("TEXCOORD_0"),
                                   needs.uv_field[1].empty() ? -2.0 : accessor("TEXCOORD_1")};
        if (needs.normal_slot != NO_TEXTURE) {
            const TextureSlot& n = s_.texture_slots[size_t(needs.normal_slot)];
            key.insert(key.end(), {accessor("TANGENT"), double(n.sampling & SLOT_UV1),
                                   n.transform_s.x, n.transform_s.y, n.transform_s.z,
                                   n.transform_t.x, n.transform_t.y, n.transform_t.z});
        }
        auto it = mesh_of_geometry_.find(key);
        if (it != mesh_of_geometry_.end()) return it->second;
        const uint32_t m = convert_primitive(mi, k);
        mesh_of_geometry_.emplace(std::move(key), m);
        return m;
    }

    uint32_t material_of(const GltfPrimitive& p) {
        return p.material != GLTF_NONE ? uint32_t(p.material) : default_material();
    }

    // TEXCOORD_n of primitive p, which `reader` (a textureInfo's field) reads, as given.
    std::vector<vec2> texcoords(const GltfPrimitive& p, const std::string& field, uint32_t n,
                                const std::string& reader, uint32_t vertices) {
        const std::string name = fmt::format("TEXCOORD_{}", n);
        if (!p.attributes.count(name))
            input_error("{}: {}.attributes: has no {}, which {} reads", d_.path, field, name,
                        reader);
        const std::vector<double> t = attribute(p, field, name, 2, vertices);
        std::vector<vec2> uvs(vertices);
        for (uint32_t v = 0; v < vertices; ++v) uvs[v] = vec2(float(t[2 * v]), float(t[2 * v + 1]));
        return uvs;
    }

    uint32_t convert_primitive(uint32_t mi, uint32_t k) {
        const GltfMesh& gm = d_.meshes[mi];
        const GltfPrimitive& p = gm.primitives[k];
        const std::string field = fmt::format("meshes[{}].primitives[{}]", mi, k);
        if (p.mode != kModeTriangles && p.mode != kModeStrip && p.mode != kModeFan) {
            note(fmt::format("{}: mode {} (points or lines) is not rendered", field, p.mode));
            return NO_INDEX;
        }
        if (!p.attributes.count("POSITION")) {
            note(fmt::format("{}: no POSITION attribute, not rendered", field));
            return NO_INDEX;
        }
        if (p.morph_targets) note(fmt::format("{}: morph targets are not applied", field));
        // Attributes twinpath never reads (colours, joints, weights, custom ones); the uv sets
        // and tangents are read where a material's slots need them.
        for (const auto& [name, accessor] : p.attributes)
            if (name != "POSITION" && name != "NORMAL" && name != "TANGENT" &&
                name.rfind("TEXCOORD_", 0) != 0)
                dropped_attributes_.insert(clip(name));
        const SlotNeeds& needs = needs_of_material_[material_of(p)];

        Mesh m;
        m.name = gm.primitives.size() == 1
                     ? element_name(gm.name, "meshes", mi)
                     : fmt::format("{}/{}", element_name(gm.name, "meshes", mi), k);
        const std::vector<double> pos = attribute(p, field, "POSITION", 3, 0);
        const uint32_t nv = uint32_t(pos.size() / 3);
        m.positions.resize(nv);
        for (uint32_t v = 0; v < nv; ++v)
            m.positions[v] = glm::dvec3(pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]);
        const bool has_normals = p.attributes.count("NORMAL") != 0;
        if (has_normals) {
            const std::vector<double> n = attribute(p, field, "NORMAL", 3, nv);
            m.normals.resize(nv);
            for (uint32_t v = 0; v < nv; ++v)
                m.normals[v] = vec3(float(n[3 * v]), float(n[3 * v + 1]), float(n[3 * v + 2]));
        }
        if (!needs.uv_field[0].empty()) m.uvs = texcoords(p, field, 0, needs.uv_field[0], nv);
        if (!needs.uv_field[1].empty()) m.uvs1 = texcoords(p, field, 1, needs.uv_field[1], nv);
        // Tangents only with the normals they were made for (section 3.7.2.1: without NORMAL,
        // flat normals, and the tangents are ignored).
        if (needs.normal_slot != NO_TEXTURE && has_normals && p.attributes.count("TANGENT")) {
            const std::vector<double> t = attribute(p, field, "TANGENT", 4, nv);
            m.tangents.resize(nv);
            for (uint32_t v = 0; v < nv; ++v)
                m.tangents[v] = vec4(float(t[4 * v]), float(t[4 * v + 1]), float(t[4 * v + 2]),
                                     float(t[4 * v + 3]));
        }
        m.triangles = triangles(p, field, nv);
        drop_unused_vertices(m);
        const std::string where = fmt::format("{}: {}", d_.path, field);
        finalize_mesh(m, where, s_.skipped_triangles);
        check_finite(m.uvs1, where, "TEXCOORD_1");
        check_finite(m.tangents, where, "TANGENT");
        if (m.triangles.empty()) {
            note(fmt::format("{}: no triangle with an area, not rendered", field));
            return NO_INDEX;
        }
        if (needs.normal_slot != NO_TEXTURE)
            add_tangent_frame(m, s_.texture_slots[size_t(needs.normal_slot)]);
        s_.meshes.push_back(std::move(m));
        return uint32_t(s_.meshes.size() - 1);
    }

    template <typename V>
    static void check_finite(const std::vector<V>& values, const std::string& where,
                             const char* attribute) {
        for (size_t i = 0; i < values.size(); ++i)
            for (int c = 0; c < V::length(); ++c)
                if (!std::isfinite(values[i][c]))
                    input_error("{}.attributes.{}: element {} is not finite", where, attribute, i);
    }

    // ---- the node hierarchy ------------------------------------------------------------------

    std::vector<uint32_t> scene_roots() {
        if (d_.scenes.empty()) {
            // No scene: every node that is nobody's child is a root.
            std::vector<bool> child(d_.nodes.size(), false);
            for (const GltfNode& n : d_.nodes)
                for (uint32_t c : n.children) child[c] = true;
            std::vector<uint32_t> roots;
            for (uint32_t i = 0; i < d_.nodes.size(); ++i)
                if (!child[i]) roots.push_back(i);
            return roots;
        }
        const size_t chosen = d_.scene != GLTF_NONE ? size_t(d_.scene) : 0;
        if (d_.scenes.size() > 1)
            note(fmt::format("scenes: renders scene {} of {}", chosen, d_.scenes.size()));
        return d_.scenes[chosen];
    }

    static bool finite(const glm::dmat4& m) {
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(m[c][r]) || std::abs(m[c][r]) > 3.4e38) return false;
        return true;
    }

    void traverse(const std::vector<uint32_t>& roots) {
        // Depth first with an explicit stack (a hierarchy may be deeper than the call stack),
        // children in their order.
        std::vector<std::pair<uint32_t, glm::dmat4>> stack;
        for (auto r = roots.rbegin(); r != roots.rend(); ++r)
            stack.push_back({*r, glm::dmat4(1.0)});
        while (!stack.empty()) {
            const auto [i, parent] = stack.back();
            stack.pop_back();
            const GltfNode& n = d_.nodes[i];
            const glm::dmat4 world = parent * n.local;
            if (!finite(world))
                input_error("{}: nodes[{}]: its world transform (its ancestors' transforms times "
                            "its own) is not finite within float's range",
                            d_.path, i);
            if (n.mesh != GLTF_NONE) add_objects(i, world);
            if (n.camera != GLTF_NONE && !camera_node_.count(uint32_t(n.camera)))
                camera_node_.emplace(uint32_t(n.camera), std::make_pair(i, world));
            if (n.camera != GLTF_NONE && first_camera_ == GLTF_NONE &&
                d_.cameras[size_t(n.camera)].perspective)
                first_camera_ = n.camera;
            if (n.light != GLTF_NONE) add_light(i, world);
            if (n.skin)
                note(fmt::format("nodes[{}]: its skin is not applied: the mesh is drawn in its "
                                 "bind pose",
                                 i));
            for (auto c = n.children.rbegin(); c != n.children.rend(); ++c)
                stack.push_back({*c, world});
        }
    }

    void add_objects(uint32_t node, const glm::dmat4& world) {
        const GltfNode& n = d_.nodes[node];
        const double det = glm::determinant(glm::dmat3(world));
        if (!(std::abs(det) > 1e-30)) {
            note(fmt::format("nodes[{}]: scaled to zero, its mesh is not rendered", node));
            return;
        }
        const GltfMesh& gm = d_.meshes[size_t(n.mesh)];
        for (uint32_t k = 0; k < gm.primitives.size(); ++k) {
            const uint32_t mesh = primitive_mesh(uint32_t(n.mesh), k);
            if (mesh == NO_INDEX) continue;
            Object o;
            o.name = element_name(n.name, "nodes", node);
            o.mesh = mesh;
            o.material = material_of(gm.primitives[k]);
            o.transform = world;
            s_.objects.push_back(o);
        }
    }

    // The unit direction `world` maps the node's -Z to, along which directional and spot
    // lights shine (KHR_lights_punctual, "Directional", "Spot").
    glm::dvec3 light_axis(uint32_t node, const glm::dmat4& world, const std::string& field) {
        const glm::dvec3 axis = glm::dvec3(world * glm::dvec4(0.0, 0.0, -1.0, 0.0));
        const double len = glm::length(axis);
        if (!(len > 0.0) || !std::isfinite(len))
            input_error("{}: nodes[{}]: the transform of {} has no -Z direction", d_.path, node,
                        field);
        return axis / len;
    }

    void add_light(uint32_t node, const glm::dmat4& world) {
        const uint32_t li = uint32_t(d_.nodes[node].light);
        const GltfLight& l = d_.lights[li];
        const std::string field = fmt::format("extensions.KHR_lights_punctual.lights[{}]", li);
        if (l.has_range)
            ignored.insert(fmt::format("{}.range: ignored (the light falls off with the inverse "
                                       "square at every distance, as the extension asks within "
                                       "the range)",
                                       field));
        LightDesc desc;
        desc.value = gltf_light_value(l.color, l.intensity);
        if (l.type == "directional") {
            desc.type = LIGHT_DIRECTIONAL;
            desc.direction = vec3(-light_axis(node, world, field)); // towards the light
        } else {
            desc.type = l.type == "spot" ? LIGHT_SPOT : LIGHT_POINT;
            desc.position = glm::dvec3(world[3]);
            if (desc.type == LIGHT_SPOT) {
                desc.direction = vec3(light_axis(node, world, field));
                desc.inner_cone = l.inner_cone;
                desc.outer_cone = l.outer_cone;
            }
        }
        s_.lights.push_back(desc);
    }

    // ---- camera ------------------------------------------------------------------------------

    void choose_camera() {
        int chosen = first_camera_;
        if (options_.camera) {
            const uint32_t c = *options_.camera;
            if (c >= d_.cameras.size())
                input_error("{}: --camera {}: the asset has {} camera(s)", d_.path, c,
                            d_.cameras.size());
            if (!d_.cameras[c].perspective)
                input_error("{}: --camera {}: cameras[{}] is orthographic; twinpath renders "
                            "perspective cameras",
                            d_.path, c, c);
            if (!camera_node_.count(c))
                input_error("{}: --camera {}: no node of the rendered scene places cameras[{}]",
                            d_.path, c, c);
            chosen = int(c);
        }
        if (chosen == GLTF_NONE) {
            if (!camera_node_.empty())
                note("cameras: only orthographic cameras, framed automatically instead");
            return; // camera.given stays false: flatten() frames the scene
        }
        const auto& [node, world] = camera_node_.at(uint32_t(chosen));
        const GltfCamera& c = d_.cameras[size_t(chosen)];
        // The camera looks along its node's -Z with +Y up (section 3.10.1).
        const glm::dvec3 forward(world * glm::dvec4(0.0, 0.0, -1.0, 0.0));
        const glm::dvec3 up(world * glm::dvec4(0.0, 1.0, 0.0, 0.0));
        if (!(glm::length(forward) > 0.0) || !(glm::length(up) > 0.0))
            input_error("{}: nodes[{}]: the transform of cameras[{}] is scaled to zero", d_.path,
                        node, chosen);
        s_.camera.eye = glm::dvec3(world[3]);
        s_.camera.target = s_.camera.eye + glm::normalize(forward);
        s_.camera.up = vec3(glm::normalize(up));
        s_.camera.fov_y_degrees = float(glm::degrees(c.yfov));
        s_.camera.given = true;
        if (c.aspect_ratio > 0.0)
            s_.settings.width =
                uint32_t(std::clamp(std::round(s_.settings.height * c.aspect_ratio), 1.0, 16384.0));
    }

    void note_scene_level() {
        if (!dropped_attributes_.empty()) {
            std::string list;
            for (const std::string& a : dropped_attributes_) list += (list.empty() ? "" : ", ") + a;
            note("vertex attributes " + list);
        }
        if (d_.animations > 0)
            note(fmt::format("animations: {} not played (the scene is rendered at rest)",
                             d_.animations));
        const std::vector<std::string>& supported = gltf_supported_extensions();
        for (const std::string& e : d_.extensions_used)
            if (std::find(supported.begin(), supported.end(), e) == supported.end())
                note(fmt::format("extension {}: not supported, ignored", clip(e)));
    }

    const GltfDocument& d_;
    const GltfResources& res_;
    const GltfOptions& options_;
    Scene& s_;
    GltfTextures textures_{d_, res_, s_};
    std::vector<SlotNeeds> needs_of_material_; // per scene material
    uint32_t default_material_ = NO_INDEX;
    std::map<std::vector<double>, uint32_t> mesh_of_geometry_;        // primitive_mesh()
    std::map<uint32_t, std::pair<uint32_t, glm::dmat4>> camera_node_; // camera -> first node
    int first_camera_ = GLTF_NONE;
    std::set<std::string> dropped_attributes_;
};

} // namespace

vec3 gltf_light_value(vec3 color, double intensity) {
    return vec3(glm::dvec3(color) * (intensity / kGltfLumensPerWatt));
}

Scene load_gltf_scene(const std::string& path, const GltfOptions& options,
                      std::vector<std::string>& warnings) {
    const std::string bytes = read_bytes(path);
    const bool glb = is_glb(bytes);
    GlbChunks chunks;
    if (glb) chunks = split_glb(path, bytes);
    const nlohmann::json root = parse_json_text(path, glb ? std::string(chunks.json) : bytes);
    const GltfDocument doc = read_gltf_document(path, root, glb);
    const GltfResources res(doc, chunks.bin, chunks.has_bin);

    Scene scene;
    scene.path = path;
    Builder b(doc, res, options, scene);
    b.build();
    if (scene.objects.empty()) input_error("{}: the scene has no triangles to render", path);
    scene.dropped.assign(b.notes.begin(), b.notes.end());
    scene.ignored.assign(b.ignored.begin(), b.ignored.end());
    size_t material_notes = 0;
    for (const auto& m : scene.material_dropped) material_notes += m.size();
    if (!scene.dropped.empty() || material_notes > 0)
        warnings.push_back(fmt::format("{}: {} thing(s) in the asset and {} in its materials are "
                                       "not rendered as given; `twinpath info {}` lists them",
                                       path, scene.dropped.size(), material_notes, path));
    light_if_unlit(scene, warnings);
    return scene;
}

} // namespace tp
