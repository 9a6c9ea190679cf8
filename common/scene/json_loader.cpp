#include "scene/json_loader.h"

#include "image/texture_io.h"
#include "scene/generators.h"
#include "scene/json_material.h"
#include "scene/json_reader.h"
#include "scene/obj_files.h"
#include "scene/tangents.h"
#include "shared/math.h"
#include "util/error.h"

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <map>

namespace fs = std::filesystem;
using nlohmann::json;

namespace tp {
namespace {

using Reader = JsonReader;

// A texture file named by `field`: a file that exists but cannot be read is reported at the
// field that names it, not only by its own path.
Texture load_texture_at(const Reader& r, const fs::path& file, const std::string& field) {
    try {
        return load_texture(file.string());
    } catch (const InputError& e) {
        r.fail(field, e.what());
    }
}

// In double, as the scene keeps it (scene/scene.h): the translation is a position.
glm::dmat4 read_transform(const Reader& r, const json& j, const std::string& field) {
    if (j.is_array()) { // 16 numbers, row-major
        if (j.size() != 16) r.fail(field, "a matrix needs 16 numbers (row-major 4x4)");
        glm::dmat4 m;
        for (int row = 0; row < 4; ++row)
            for (int col = 0; col < 4; ++col)
                m[col][row] =
                    r.coordinate(j[row * 4 + col], fmt::format("{}[{}]", field, row * 4 + col));
        if (m[0][3] != 0 || m[1][3] != 0 || m[2][3] != 0 || m[3][3] != 1)
            r.fail(field, "the last row must be 0 0 0 1 (affine transforms only)");
        return m;
    }
    r.keys(j, field, {"translate", "rotate", "scale"});
    glm::dmat4 m(1.0);
    if (j.contains("translate"))
        m = glm::translate(m, r.position(j["translate"], field + ".translate"));
    if (j.contains("rotate")) {
        const json& rot = j["rotate"];
        std::vector<const json*> list;
        if (rot.is_array())
            for (const auto& e : rot) list.push_back(&e);
        else
            list.push_back(&rot);
        // Listed rotations apply in order, so the first is innermost: M = R_n ... R_1.
        glm::dmat4 rm(1.0);
        for (size_t i = 0; i < list.size(); ++i) {
            const std::string f =
                rot.is_array() ? fmt::format("{}.rotate[{}]", field, i) : field + ".rotate";
            r.keys(*list[i], f, {"axis", "degrees"});
            const vec3 axis = r.vector3(r.required(*list[i], f, "axis"), f + ".axis");
            // Normalized in double: |axis| overflows float for components beyond ~1.8e19.
            const glm::dvec3 unit = glm::dvec3(axis) / glm::length(glm::dvec3(axis));
            if (!is_finite3(vec3(unit))) r.fail(f + ".axis", "must not be zero");
            const double deg = r.number(r.required(*list[i], f, "degrees"), f + ".degrees");
            rm = glm::rotate(glm::dmat4(1.0), glm::radians(deg), unit) * rm;
        }
        m = m * rm;
    }
    if (j.contains("scale")) {
        const json& s = j["scale"];
        const glm::dvec3 sv = s.is_number() ? glm::dvec3(r.coordinate(s, field + ".scale"))
                                            : r.position(s, field + ".scale");
        m = glm::scale(m, sv);
    }
    return m;
}

Mesh inline_mesh(const Reader& r, const json& j, const std::string& field) {
    Mesh m;
    const json& verts = r.required(j, field, "vertices");
    if (!verts.is_array() || verts.empty())
        r.fail(field + ".vertices", "expected a non-empty array of [x, y, z]");
    for (size_t i = 0; i < verts.size(); ++i)
        m.positions.push_back(r.position(verts[i], fmt::format("{}.vertices[{}]", field, i)));
    auto index = [&](const json& e, const std::string& f) {
        const uint32_t v = r.count(e, f, 0, 0xFFFFFFFEu);
        if (v >= m.positions.size())
            r.fail(f, fmt::format("index {} is out of range: {} vertices", v, m.positions.size()));
        return v;
    };
    if (j.contains("triangles")) {
        const json& t = j["triangles"];
        if (!t.is_array()) r.fail(field + ".triangles", "expected an array of [i, j, k]");
        for (size_t i = 0; i < t.size(); ++i) {
            const std::string f = fmt::format("{}.triangles[{}]", field, i);
            if (!t[i].is_array() || t[i].size() != 3) r.fail(f, "expected 3 vertex indices");
            m.triangles.push_back({index(t[i][0], f), index(t[i][1], f), index(t[i][2], f)});
        }
    }
    if (j.contains("quads")) {
        const json& q = j["quads"];
        if (!q.is_array()) r.fail(field + ".quads", "expected an array of [i, j, k, l]");
        for (size_t i = 0; i < q.size(); ++i) {
            const std::string f = fmt::format("{}.quads[{}]", field, i);
            if (!q[i].is_array() || q[i].size() != 4) r.fail(f, "expected 4 vertex indices");
            const uint32_t a = index(q[i][0], f), b = index(q[i][1], f), c = index(q[i][2], f),
                           d = index(q[i][3], f);
            m.triangles.push_back({a, b, c});
            m.triangles.push_back({a, c, d});
        }
    }
    if (m.triangles.empty()) r.fail(field, "needs \"triangles\" or \"quads\"");
    return m;
}

// The OBJ files that well-formed mesh entries name, to be read at once before the entries are
// read in order; an entry that names none well (no such file, a malformed field) is left to
// read_mesh, which reports it in its turn before it would look the file up.
std::vector<std::string> obj_paths(const Reader& r, const json& meshes) {
    std::vector<std::string> paths;
    for (const auto& [name, j] : meshes.items()) {
        if (!j.is_object() || !j.contains("type") || j["type"] != "obj" || !j.contains("file"))
            continue;
        try {
            paths.push_back(r.file_path(j["file"], "meshes." + name + ".file").string());
        } catch (const InputError&) {
        }
    }
    return paths;
}

// A mesh entry: either one mesh (generated or inline) or the parts of an OBJ file.
struct MeshRef {
    std::vector<ObjPart> parts; // material NO_INDEX: the object must name one
};

MeshRef read_mesh(const Reader& r, const json& j, const std::string& field, Scene& scene,
                  const std::map<std::string, ObjFile>& obj_files,
                  std::vector<std::string>& warnings) {
    const std::string type = r.string(r.required(j, field, "type"), field + ".type");
    MeshRef ref;
    Mesh m;
    if (type == "obj") {
        r.keys(j, field, {"type", "file"});
        const fs::path file = r.file_path(r.required(j, field, "file"), field + ".file");
        // Faces without usemtl get NO_INDEX; the object must then give a material.
        ref.parts = append_obj(obj_files.at(file.string()), scene, NO_INDEX, warnings);
        return ref;
    } else if (type == "sphere") {
        r.keys(j, field, {"type", "subdivisions", "inward", "smooth"});
        const uint32_t sub = j.contains("subdivisions")
                                 ? r.count(j["subdivisions"], field + ".subdivisions", 0, 8)
                                 : 4;
        const bool inward = j.contains("inward") && r.boolean(j["inward"], field + ".inward");
        m = make_icosphere(sub, inward);
        // Flat shading: the faces' own normals, for scenes whose exact answer assumes them.
        if (j.contains("smooth") && !r.boolean(j["smooth"], field + ".smooth")) m.normals.clear();
    } else if (type == "quad") {
        r.keys(j, field, {"type"});
        m = make_quad();
    } else if (type == "box") {
        r.keys(j, field, {"type"});
        m = make_box();
    } else if (type == "triangles") {
        r.keys(j, field, {"type", "vertices", "triangles", "quads"});
        m = inline_mesh(r, j, field);
    } else {
        r.fail(field + ".type",
               fmt::format("unknown mesh type '{}' (expected obj, sphere, quad, box, triangles)",
                           type));
    }
    finalize_mesh(m, fmt::format("{}: {}", r.file(), field), scene.skipped_triangles);
    if (m.triangles.empty()) r.fail(field, "has no triangles left after dropping degenerate ones");
    scene.meshes.push_back(std::move(m));
    ref.parts.push_back(ObjPart{uint32_t(scene.meshes.size() - 1), NO_INDEX});
    return ref;
}

Texture read_texture(const Reader& r, const json& j, const std::string& field) {
    if (j.contains("file")) {
        r.keys(j, field, {"file"});
        return load_texture_at(r, r.file_path(j["file"], field + ".file"), field + ".file");
    }
    const std::string gen = r.string(r.required(j, field, "generator"), field + ".generator");
    const uint32_t size = j.contains("size") ? r.count(j["size"], field + ".size", 1, 8192) : 512;
    vec3 a(0.8f), b(0.2f);
    if (j.contains("colors")) {
        const json& c = j["colors"];
        if (!c.is_array() || c.size() != 2) r.fail(field + ".colors", "expected two colors");
        a = r.color(c[0], field + ".colors[0]");
        b = r.color(c[1], field + ".colors[1]");
    }
    if (gen == "checker") {
        r.keys(j, field, {"generator", "size", "colors", "checks"});
        const uint32_t checks =
            j.contains("checks") ? r.count(j["checks"], field + ".checks", 1, size) : 8;
        return make_checker_texture(size, checks, a, b);
    }
    if (gen == "marble") {
        r.keys(j, field, {"generator", "size", "colors", "scale", "seed"});
        const float scale =
            j.contains("scale") ? r.number(j["scale"], field + ".scale", 0.0f, 1000.0f) : 4.0f;
        const uint32_t seed =
            j.contains("seed") ? r.count(j["seed"], field + ".seed", 0, 0xFFFFFFFFu) : 1;
        return make_marble_texture(size, scale, a, b, seed);
    }
    r.fail(field + ".generator",
           fmt::format("unknown generator '{}' (expected checker or marble)", gen));
}

// What the normal maps of the objects' materials need of their meshes: normals and tangents
// (tangents.h), made once per mesh (the slots all read the first uv set through OBJ's map).
void add_normal_map_frames(Scene& scene) {
    for (const Object& o : scene.objects) {
        const Material& m = scene.materials[o.material];
        if (m.type == MATERIAL_PBR && m.normal_texture != NO_TEXTURE)
            add_tangent_frame(scene.meshes[o.mesh], scene.texture_slots[size_t(m.normal_texture)]);
    }
}

} // namespace

Scene load_json_scene(const std::string& path, std::vector<std::string>& warnings) {
    const json root = parse_json_file(path);
    const Reader r(path);
    r.keys(root, "",
           {"camera", "film", "render", "textures", "materials", "meshes", "objects", "lights",
            "environment"});
    Scene scene;
    scene.path = path;

    if (root.contains("camera")) {
        const json& c = root["camera"];
        r.keys(c, "camera", {"eye", "target", "up", "fov"});
        scene.camera.eye = r.position(r.required(c, "camera", "eye"), "camera.eye");
        scene.camera.target = r.position(r.required(c, "camera", "target"), "camera.target");
        if (c.contains("up")) scene.camera.up = r.vector3(c["up"], "camera.up");
        if (c.contains("fov"))
            scene.camera.fov_y_degrees = r.number(c["fov"], "camera.fov", 1e-3f, 179.0f);
        scene.camera.given = true;
    }
    if (root.contains("film")) {
        const json& f = root["film"];
        r.keys(f, "film", {"width", "height"});
        if (f.contains("width")) scene.settings.width = r.count(f["width"], "film.width", 1, 16384);
        if (f.contains("height"))
            scene.settings.height = r.count(f["height"], "film.height", 1, 16384);
    }
    if (root.contains("render")) {
        const json& s = root["render"];
        r.keys(s, "render", {"spp", "max_depth", "min_depth"});
        if (s.contains("spp")) scene.settings.spp = r.count(s["spp"], "render.spp", 1, 1u << 30);
        if (s.contains("max_depth"))
            scene.settings.max_depth = r.count(s["max_depth"], "render.max_depth", 1, 100000);
        if (s.contains("min_depth"))
            scene.settings.min_depth = r.count(s["min_depth"], "render.min_depth", 0, 100000);
    }

    std::map<std::string, uint32_t> textures;
    if (root.contains("textures") && !root["textures"].is_object())
        r.fail("textures", "expected an object of named textures");
    if (root.contains("textures"))
        for (const auto& [name, j] : root["textures"].items()) {
            Texture t = read_texture(r, j, "textures." + name);
            t.name = name;
            scene.textures.push_back(std::move(t));
            textures[name] = uint32_t(scene.textures.size() - 1);
        }

    std::map<std::string, uint32_t> materials;
    if (root.contains("materials")) {
        if (!root["materials"].is_object())
            r.fail("materials", "expected an object of named materials");
        for (const auto& [name, j] : root["materials"].items()) {
            scene.materials.push_back(
                read_json_material(r, j, "materials." + name, textures, scene));
            scene.material_names.push_back(name);
            materials[name] = uint32_t(scene.materials.size() - 1);
        }
    }

    std::map<std::string, MeshRef> meshes;
    if (root.contains("meshes")) {
        if (!root["meshes"].is_object()) r.fail("meshes", "expected an object of named meshes");
        const std::map<std::string, ObjFile> obj_files =
            read_obj_files(obj_paths(r, root["meshes"]), NO_INDEX);
        for (const auto& [name, j] : root["meshes"].items()) {
            if (!j.is_object()) r.fail("meshes." + name, "expected an object");
            meshes[name] = read_mesh(r, j, "meshes." + name, scene, obj_files, warnings);
        }
    }

    if (!root.contains("objects") || !root["objects"].is_array() || root["objects"].empty())
        r.fail("objects", "expected a non-empty array of objects");
    const json& objects = root["objects"];
    for (size_t i = 0; i < objects.size(); ++i) {
        const std::string f = fmt::format("objects[{}]", i);
        const json& o = objects[i];
        r.keys(o, f, {"name", "mesh", "material", "transform"});
        const std::string mesh_name = r.string(r.required(o, f, "mesh"), f + ".mesh");
        auto mit = meshes.find(mesh_name);
        if (mit == meshes.end()) r.fail(f + ".mesh", fmt::format("no mesh named '{}'", mesh_name));
        uint32_t material = NO_INDEX;
        if (o.contains("material")) {
            const std::string mat = r.string(o["material"], f + ".material");
            auto it = materials.find(mat);
            if (it == materials.end())
                r.fail(f + ".material", fmt::format("no material named '{}'", mat));
            material = it->second;
        }
        const glm::dmat4 xf = o.contains("transform")
                                  ? read_transform(r, o["transform"], f + ".transform")
                                  : glm::dmat4(1.0);
        const double det = glm::determinant(glm::dmat3(xf));
        if (!(std::abs(det) > 1e-30)) r.fail(f + ".transform", "is singular (zero scale?)");
        for (const ObjPart& part : mit->second.parts) {
            Object obj;
            obj.name = o.contains("name") ? r.string(o["name"], f + ".name") : mesh_name;
            obj.mesh = part.mesh;
            obj.material = material != NO_INDEX ? material : part.material;
            if (obj.material == NO_INDEX)
                r.fail(f + ".material",
                       fmt::format("mesh '{}' has no material of its own: name one", mesh_name));
            obj.transform = xf;
            scene.objects.push_back(obj);
        }
    }

    add_normal_map_frames(scene);

    if (root.contains("lights")) {
        const json& lights = root["lights"];
        if (!lights.is_array()) r.fail("lights", "expected an array");
        for (size_t i = 0; i < lights.size(); ++i) {
            const std::string f = fmt::format("lights[{}]", i);
            const json& l = lights[i];
            const std::string type = r.string(r.required(l, f, "type"), f + ".type");
            LightDesc light;
            if (type == "point") {
                r.keys(l, f, {"type", "position", "intensity"});
                light.type = LIGHT_POINT;
                light.position = r.position(r.required(l, f, "position"), f + ".position");
                light.value = r.color(r.required(l, f, "intensity"), f + ".intensity");
            } else if (type == "directional") {
                r.keys(l, f, {"type", "direction", "irradiance"});
                light.type = LIGHT_DIRECTIONAL;
                const vec3 d = r.vector3(r.required(l, f, "direction"), f + ".direction");
                if (glm::length(d) == 0.0f) r.fail(f + ".direction", "must not be zero");
                light.direction = -glm::normalize(d); // towards the light
                light.value = r.color(r.required(l, f, "irradiance"), f + ".irradiance");
            } else {
                r.fail(f + ".type",
                       fmt::format("unknown light type '{}' (expected point, directional)", type));
            }
            scene.lights.push_back(light);
        }
    }

    if (root.contains("environment")) {
        const json& e = root["environment"];
        const std::string type = r.string(r.required(e, "environment", "type"), "environment.type");
        if (type == "constant") {
            r.keys(e, "environment", {"type", "radiance"});
            scene.environment.kind = EnvironmentKind::Constant;
            scene.environment.radiance =
                r.color(r.required(e, "environment", "radiance"), "environment.radiance");
        } else if (type == "map") {
            r.keys(e, "environment", {"type", "file", "texture", "scale", "rotation"});
            scene.environment.kind = EnvironmentKind::Map;
            if (e.contains("file") == e.contains("texture"))
                r.fail("environment", "a map needs exactly one of \"file\" and \"texture\"");
            if (e.contains("file")) {
                Texture t = load_texture_at(r, r.file_path(e["file"], "environment.file"),
                                            "environment.file");
                t.name = "environment";
                scene.textures.push_back(std::move(t));
                scene.environment.texture = int(scene.textures.size() - 1);
            } else {
                const std::string name = r.string(e["texture"], "environment.texture");
                auto it = textures.find(name);
                if (it == textures.end())
                    r.fail("environment.texture", fmt::format("no texture named '{}'", name));
                scene.environment.texture = int(it->second);
            }
            scene.environment.radiance =
                e.contains("scale") ? vec3(r.number(e["scale"], "environment.scale", 0.0f, 1e30f))
                                    : vec3(1.0f);
            if (e.contains("rotation"))
                scene.environment.rotation_degrees =
                    r.number(e["rotation"], "environment.rotation");
        } else {
            r.fail("environment.type",
                   fmt::format("unknown environment type '{}' (expected constant, map)", type));
        }
    }
    return scene;
}

} // namespace tp
