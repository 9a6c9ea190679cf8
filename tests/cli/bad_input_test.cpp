// Every kind of bad input (docs/design.md, exit codes) through the real command line: one clear
// message that names the file and the line or field, exit code 2, and no output file of any kind
// left behind.
#include "support/gltf_builder.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace fs = std::filesystem;
using tp::test::run;
using tp::test::shell_quote;

namespace {

struct BadInput {
    std::string name;
    std::vector<std::pair<std::string, std::string>> files; // written into a fresh directory
    std::string scene;                                      // the file rendered (or a path)
    std::string args;                                       // further command-line arguments
    std::vector<std::string> expected;                      // substrings of the message
};

// A small valid scene; cases below replace one part of it.
std::string scene_json(const std::string& camera, const std::string& materials,
                       const std::string& meshes, const std::string& objects,
                       const std::string& extra = "") {
    return "{\n  \"camera\": " + camera + ",\n  \"film\": {\"width\": 8, \"height\": 8},\n" +
           "  \"materials\": " + materials + ",\n  \"meshes\": " + meshes + ",\n" +
           "  \"objects\": " + objects + extra + "\n}\n";
}

const std::string kCamera =
    R"({"eye": [0, 0, 3], "target": [0, 0, 0], "up": [0, 1, 0], "fov": 40})";
const std::string kMaterials = R"({"m": {"Kd": [0.5, 0.5, 0.5], "Ke": [1, 1, 1]}})";
const std::string kMeshes = R"({"ball": {"type": "sphere", "subdivisions": 1}})";
const std::string kObjects = R"([{"mesh": "ball", "material": "m"}])";

std::string with_material(const std::string& m) {
    return scene_json(kCamera, "{\"m\": " + m + "}", kMeshes, kObjects);
}
std::string with_camera(const std::string& c) {
    return scene_json(c, kMaterials, kMeshes, kObjects);
}
std::string with_mesh(const std::string& m) {
    return scene_json(kCamera, kMaterials, "{\"t\": " + m + "}",
                      R"([{"mesh": "t", "material": "m"}])");
}
std::string with_extra(const std::string& e) {
    return scene_json(kCamera, kMaterials, kMeshes, kObjects, ",\n  " + e);
}

const std::string kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
const std::string kPngGarbage = "this is not a PNG file\n";

// An OBJ with one triangle that uses the material 'a' of m.mtl.
std::vector<std::pair<std::string, std::string>> with_mtl(const std::string& mtl) {
    return {{"m.mtl", mtl}, {"bad.obj", "mtllib m.mtl\n" + kTriangleObj + "usemtl a\nf 1 2 3\n"}};
}

// A valid glTF asset: the unit cube, emissive, under one node; `edit` changes its JSON or data.
// Written as bad.gltf with its buffer in bad.bin.
template <typename Edit>
std::vector<std::pair<std::string, std::string>> gltf_with(Edit edit) {
    tp::test::GltfBuilder g;
    const tp::test::CubeData c = tp::test::unit_cube();
    g.mesh({{"POSITION", g.vec3s(c.positions)}}, int(g.indices(c.indices)), 0);
    g.add("materials", {{"emissiveFactor", {1, 1, 1}}});
    g.add("nodes", {{"mesh", 0}});
    g.scene({0});
    edit(g);
    return {{"bad.gltf", g.gltf_text("bad.bin")}, {"bad.bin", g.bin}};
}

void check_rejected(const BadInput& c) {
    const std::string dir = tp::test::temp_dir("bad-input");
    for (const auto& [file, text] : c.files) std::ofstream(fs::path(dir) / file) << text;
    const std::string scene =
        c.scene.find('/') == std::string::npos ? (fs::path(dir) / c.scene).string() : c.scene;
    const fs::path out = fs::path(dir) / "out";
    const auto r =
        run(tp::test::twinpath_bin() + " render " + shell_quote(scene) + " -o " +
            shell_quote(out.string() + ".exr") + " --png " + shell_quote(out.string() + ".png") +
            " --stats " + shell_quote(out.string() + ".json") +
            (c.args.find("--spp") == std::string::npos ? " --spp 1 " : " ") + c.args);
    INFO(c.name << "\n" << r.out);
    CHECK(r.exit_code == 2);
    for (const std::string& s : c.expected) CHECK(r.out.find(s) != std::string::npos);
    // One message: a single line, or two for a usage error, where CLI11 adds its "Run with
    // --help" hint.
    size_t lines = 0;
    for (char ch : r.out) lines += ch == '\n' ? 1 : 0;
    CHECK(lines >= 1);
    CHECK(lines <= 2);
    CHECK(r.out.find("internal error") == std::string::npos);
    // Nothing written: neither the outputs nor write_exr's temporary file.
    for (const char* ext : {".exr", ".png", ".json", ".exr.partial"})
        CHECK_FALSE(fs::exists(out.string() + ext));
    fs::remove_all(dir);
}

void check_all(const std::vector<BadInput>& cases) {
    for (const BadInput& c : cases) DYNAMIC_SECTION(c.name) {
            check_rejected(c);
        }
}

} // namespace

TEST_CASE("bad JSON scenes are rejected with file and field", "[cli][bad-input]") {
    check_all({
        {"malformed JSON names file and line",
         {{"bad.json", "{\n  \"objects\": [\n    1,\n  ]\n}\n"}},
         "bad.json",
         "",
         {"bad.json", "line 4"}},
        {"number overflowing double (1e999) names file and line",
         {{"bad.json", "{\n  \"film\": {\n    \"width\": 1e999\n  }\n}\n"}},
         "bad.json",
         "",
         {"bad.json", "line 3", "1e999"}},
        {"root is not an object",
         {{"bad.json", "[1, 2, 3]\n"}},
         "bad.json",
         "",
         {"bad.json", "object"}},
        {"unknown top-level key",
         {{"bad.json", with_extra(R"("camra": {})")}},
         "bad.json",
         "",
         {"bad.json", "camra", "unknown key"}},
        {"unknown nested key names the field path",
         {{"bad.json", with_material(R"({"Kd": [0.5, 0.5, 0.5], "Kx": 1})")}},
         "bad.json",
         "",
         {"bad.json", "materials.m.Kx", "unknown key"}},
        {"wrong type",
         {{"bad.json", with_extra(R"("render": {"spp": "many"})")}},
         "bad.json",
         "",
         {"bad.json", "render.spp"}},
        {"missing objects",
         {{"bad.json", "{\"materials\": {}}\n"}},
         "bad.json",
         "",
         {"bad.json", "objects"}},
        {"unknown material type",
         {{"bad.json", with_material(R"({"type": "velvet", "Kd": [0.5, 0.5, 0.5]})")}},
         "bad.json",
         "",
         {"bad.json", "materials.m.type", "velvet"}},
        {"pbr roughness above 1",
         {{"bad.json", with_material(R"({"type": "pbr", "roughness": 1.2, "Ke": [1, 1, 1]})")}},
         "bad.json",
         "",
         {"bad.json", "materials.m.roughness", "[0, 1]"}},
        {"pbr alpha mode misspelt",
         {{"bad.json", with_material(R"({"type": "pbr", "alpha_mode": "MASK"})")}},
         "bad.json",
         "",
         {"bad.json", "materials.m.alpha_mode", "MASK"}},
        {"pbr normal texture naming no texture",
         {{"bad.json", with_material(R"({"type": "pbr", "normal_texture": "bumps"})")}},
         "bad.json",
         "",
         {"bad.json", "materials.m.normal_texture", "bumps"}},
        {"negative Kd",
         {{"bad.json", with_material(R"({"Kd": [-0.1, 0.5, 0.5]})")}},
         "bad.json",
         "",
         {"bad.json", "materials.m.Kd", "negative"}},
        {"Kd + Ks > 1",
         {{"bad.json", with_material(R"({"Kd": [0.6, 0.6, 0.6], "Ks": [0.5, 0.3, 0.3]})")}},
         "bad.json",
         "",
         {"bad.json", "materials.m", "Kd + Ks"}},
        {"negative Ns",
         {{"bad.json", with_material(R"({"Kd": [0.5, 0.5, 0.5], "Ns": -2})")}},
         "bad.json",
         "",
         {"bad.json", "materials.m.Ns"}},
        {"index of refraction 0",
         {{"bad.json", with_material(R"({"type": "dielectric", "Ni": 0})")}},
         "bad.json",
         "",
         {"bad.json", "materials.m.Ni"}},
        {"colour beyond float range (1e39)",
         {{"bad.json", with_material(R"({"Kd": [1e39, 0, 0]})")}},
         "bad.json",
         "",
         {"bad.json", "materials.m.Kd[0]", "finite"}},
        {"negative point light intensity",
         {{"bad.json",
           with_extra(
               R"("lights": [{"type": "point", "position": [0, 1, 0], "intensity": [1, -1, 1]}])")}},
         "bad.json",
         "",
         {"bad.json", "lights[0].intensity"}},
        {"directional light without a direction",
         {{"bad.json",
           with_extra(
               R"("lights": [{"type": "directional", "direction": [0, 0, 0], "irradiance": [1, 1, 1]}])")}},
         "bad.json",
         "",
         {"bad.json", "lights[0].direction"}},
        {"negative environment radiance",
         {{"bad.json",
           with_extra(R"("environment": {"type": "constant", "radiance": [0.1, -0.1, 0.1]})")}},
         "bad.json",
         "",
         {"bad.json", "environment.radiance"}},
        {"zero samples per pixel",
         {{"bad.json", with_extra(R"("render": {"spp": 0})")}},
         "bad.json",
         "",
         {"bad.json", "render.spp"}},
        {"unknown mesh type",
         {{"bad.json", with_mesh(R"({"type": "torus"})")}},
         "bad.json",
         "",
         {"bad.json", "meshes.t.type", "torus"}},
        {"vertex beyond float range (a NaN/Inf triangle)",
         {{"bad.json",
           with_mesh(
               R"({"type": "triangles", "vertices": [[0, 0, 0], [1e39, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 2]]})")}},
         "bad.json",
         "",
         {"bad.json", "meshes.t.vertices[1][0]", "finite"}},
        {"triangle index out of range",
         {{"bad.json",
           with_mesh(
               R"({"type": "triangles", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 3]]})")}},
         "bad.json",
         "",
         {"bad.json", "meshes.t.triangles[0]", "out of range"}},
        {"only zero-area triangles",
         {{"bad.json",
           with_mesh(
               R"({"type": "triangles", "vertices": [[0, 0, 0], [1, 0, 0], [2, 0, 0]], "triangles": [[0, 1, 2]]})")}},
         "bad.json",
         "",
         {"bad.json", "meshes.t", "degenerate"}},
        {"unknown mesh name",
         {{"bad.json",
           scene_json(kCamera, kMaterials, kMeshes, R"([{"mesh": "cube", "material": "m"}])")}},
         "bad.json",
         "",
         {"bad.json", "objects[0].mesh", "cube"}},
        {"singular transform",
         {{"bad.json",
           scene_json(kCamera, kMaterials, kMeshes,
                      R"([{"mesh": "ball", "material": "m", "transform": {"scale": 0}}])")}},
         "bad.json",
         "",
         {"bad.json", "objects[0].transform"}},
    });
}

TEST_CASE("missing and unreadable files are rejected with the referencing file and field",
          "[cli][bad-input]") {
    check_all({
        {"missing scene file", {}, "nosuch.json", "", {"nosuch.json"}},
        {"unknown scene format",
         {{"scene.txt", "hello\n"}},
         "scene.txt",
         "",
         {"scene.txt", ".txt"}},
        {"missing OBJ mesh",
         {{"bad.json", with_mesh(R"({"type": "obj", "file": "gone.obj"})")}},
         "bad.json",
         "",
         {"bad.json", "meshes.t.file", "gone.obj"}},
        {"missing texture",
         {{"bad.json", with_extra(R"("textures": {"t": {"file": "gone.png"}})")}},
         "bad.json",
         "",
         {"bad.json", "textures.t.file", "gone.png"}},
        {"unreadable texture",
         {{"bad.json", with_extra(R"("textures": {"t": {"file": "bad.png"}})")},
          {"bad.png", kPngGarbage}},
         "bad.json",
         "",
         {"bad.json", "textures.t.file", "bad.png"}},
        {"missing environment map",
         {{"bad.json", with_extra(R"("environment": {"type": "map", "file": "sky.exr"})")}},
         "bad.json",
         "",
         {"bad.json", "environment.file", "sky.exr"}},
        {"texture name not defined",
         {{"bad.json", with_material(R"({"Kd": [0.5, 0.5, 0.5], "map_Kd": "wood"})")}},
         "bad.json",
         "",
         {"bad.json", "materials.m.map_Kd", "wood"}},
        {"missing MTL library",
         {{"bad.obj", "mtllib gone.mtl\n" + kTriangleObj + "f 1 2 3\n"}},
         "bad.obj",
         "",
         {"bad.obj:1", "gone.mtl"}},
        {"missing map_Kd texture",
         with_mtl("newmtl a\nKd 0.5 0.5 0.5\nmap_Kd gone.png\n"),
         "bad.obj",
         "",
         {"m.mtl:3", "gone.png"}},
        {"unreadable map_Kd texture",
         [] {
             auto f = with_mtl("newmtl a\nKd 0.5 0.5 0.5\nmap_Kd bad.png\n");
             f.emplace_back("bad.png", kPngGarbage);
             return f;
         }(),
         "bad.obj",
         "",
         {"m.mtl:3", "bad.png"}},
    });
}

TEST_CASE("bad OBJ files are rejected with file and line", "[cli][bad-input]") {
    check_all({
        {"malformed number",
         {{"bad.obj", "v 0 0 0\nv 1 zz 0\nv 0 1 0\nf 1 2 3\n"}},
         "bad.obj",
         "",
         {"bad.obj:2", "zz"}},
        {"NaN vertex",
         {{"bad.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"}},
         "bad.obj",
         "",
         {"bad.obj:2", "finite"}},
        {"infinite vertex",
         {{"bad.obj", "v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n"}},
         "bad.obj",
         "",
         {"bad.obj:3", "finite"}},
        {"vertex beyond float range",
         {{"bad.obj", "v 1e39 0 0\n" + kTriangleObj + "f 2 3 4\n"}},
         "bad.obj",
         "",
         {"bad.obj:1", "1e39"}},
        {"too few coordinates",
         {{"bad.obj", "v 0 0\n" + kTriangleObj + "f 2 3 4\n"}},
         "bad.obj",
         "",
         {"bad.obj:1", "'v'"}},
        {"NaN texture coordinate",
         {{"bad.obj", kTriangleObj + "vt 0.5 nan\nf 1/1 2/1 3/1\n"}},
         "bad.obj",
         "",
         {"bad.obj:4", "finite"}},
        {"normal with two coordinates",
         {{"bad.obj", kTriangleObj + "vn 0 1\nf 1//1 2//1 3//1\n"}},
         "bad.obj",
         "",
         {"bad.obj:4", "'vn'"}},
        {"face index 0",
         {{"bad.obj", kTriangleObj + "f 0 1 2\n"}},
         "bad.obj",
         "",
         {"bad.obj:4", "index 0"}},
        {"face index out of range",
         {{"bad.obj", kTriangleObj + "f 1 2 9\n"}},
         "bad.obj",
         "",
         {"bad.obj:4", "out of range"}},
        {"negative face index out of range",
         {{"bad.obj", kTriangleObj + "f -1 -2 -4\n"}},
         "bad.obj",
         "",
         {"bad.obj:4", "out of range"}},
        {"texture index out of range",
         {{"bad.obj", kTriangleObj + "vt 0 0\nf 1/1 2/2 3/1\n"}},
         "bad.obj",
         "",
         {"bad.obj:5", "out of range"}},
        {"face with two vertices",
         {{"bad.obj", kTriangleObj + "f 1 2\n"}},
         "bad.obj",
         "",
         {"bad.obj:4", "at least 3"}},
        {"face index not an integer",
         {{"bad.obj", kTriangleObj + "f 1 2 3.5\n"}},
         "bad.obj",
         "",
         {"bad.obj:4", "3.5"}},
        {"unknown statement",
         {{"bad.obj", kTriangleObj + "frobnicate 1\nf 1 2 3\n"}},
         "bad.obj",
         "",
         {"bad.obj:4", "frobnicate"}},
        {"undefined material",
         {{"bad.obj", kTriangleObj + "usemtl ghost\nf 1 2 3\n"}},
         "bad.obj",
         "",
         {"bad.obj:4", "ghost"}},
        {"no faces", {{"bad.obj", kTriangleObj}}, "bad.obj", "", {"bad.obj", "no triangles"}},
    });
}

TEST_CASE("bad MTL files are rejected with file and line", "[cli][bad-input]") {
    check_all({
        {"malformed number", with_mtl("newmtl a\nKd 1 zz 0\n"), "bad.obj", "", {"m.mtl:2", "zz"}},
        {"two values for a colour",
         with_mtl("newmtl a\nKd 0.5 0.5\n"),
         "bad.obj",
         "",
         {"m.mtl:2", "Kd"}},
        {"Kd + Ks > 1",
         with_mtl("newmtl a\nKd 0.8 0.8 0.8\nKs 0.5\n"),
         "bad.obj",
         "",
         {"m.mtl:1", "'a'", "Kd + Ks"}},
        {"negative Kd",
         with_mtl("newmtl a\nKd -0.5 0 0\n"),
         "bad.obj",
         "",
         {"m.mtl:1", "Kd", "negative"}},
        {"NaN Ks", with_mtl("newmtl a\nKs nan 0 0\n"), "bad.obj", "", {"m.mtl:2", "finite"}},
        {"negative Ns",
         with_mtl("newmtl a\nKd 0.5 0.5 0.5\nNs -1\n"),
         "bad.obj",
         "",
         {"m.mtl:1", "Ns"}},
        {"index of refraction 0",
         with_mtl("newmtl a\nillum 7\nNi 0\n"),
         "bad.obj",
         "",
         {"m.mtl:1", "Ni"}},
        {"statement before newmtl",
         with_mtl("Kd 0.5 0.5 0.5\nnewmtl a\n"),
         "bad.obj",
         "",
         {"m.mtl:1", "newmtl"}},
        {"unknown statement",
         with_mtl("newmtl a\nKd 0.5 0.5 0.5\nsheen 1\n"),
         "bad.obj",
         "",
         {"m.mtl:3", "sheen"}},
        {"illum not an integer",
         with_mtl("newmtl a\nillum x\n"),
         "bad.obj",
         "",
         {"m.mtl:2", "'x'"}},
    });
}

TEST_CASE("bad glTF files are rejected with file and field", "[cli][bad-input][gltf]") {
    using json = nlohmann::json;
    const auto textured = [](const std::string& uri) {
        return [uri](tp::test::GltfBuilder& g) {
            g.add("images", {{"uri", uri}});
            g.add("textures", {{"source", 0}});
            g.doc["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}}};
            g.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] =
                g.vec2s(std::vector<glm::vec2>(24, glm::vec2(0.5f)));
        };
    };
    auto with_two_scaled_nodes = [](tp::test::GltfBuilder& g) {
        // 1e30 * 1e30 is beyond float: the world matrix of node 1 is out of range.
        const json big = {1e30, 0, 0, 0, 0, 1e30, 0, 0, 0, 0, 1e30, 0, 0, 0, 0, 1};
        g.doc["nodes"] = {{{"matrix", big}, {"children", {1}}}, {{"matrix", big}, {"mesh", 0}}};
    };
    std::string glb;
    {
        tp::test::GltfBuilder g;
        const tp::test::CubeData c = tp::test::unit_cube();
        g.mesh({{"POSITION", g.vec3s(c.positions)}}, int(g.indices(c.indices)));
        g.add("nodes", {{"mesh", 0}});
        g.scene({0});
        glb = g.glb_bytes();
    }
    auto python_nan = gltf_with([](tp::test::GltfBuilder& g) {
        g.doc["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 12345, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    });
    const size_t at = python_nan[0].second.find("12345");
    python_nan[0].second.replace(at, 5, "NaN"); // as Python's json.dump writes it
    check_all({
        {"a buffer view past the end of its buffer",
         gltf_with([](tp::test::GltfBuilder& g) { g.doc["bufferViews"][0]["byteLength"] = 4096; }),
         "bad.gltf",
         "",
         {"bad.gltf", "bufferViews[0]", "runs past the end of buffers[0]"}},
        {"an accessor past the end of its buffer view",
         gltf_with([](tp::test::GltfBuilder& g) { g.doc["accessors"][0]["count"] = 1000; }),
         "bad.gltf",
         "",
         {"bad.gltf", "accessors[0]", "bufferViews[0]"}},
        {"an attribute naming an accessor that does not exist",
         gltf_with([](tp::test::GltfBuilder& g) {
             g.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 99;
         }),
         "bad.gltf",
         "",
         {"bad.gltf", "meshes[0].primitives[0].attributes.POSITION", "accessors"}},
        {"a vertex index out of range in the index data",
         gltf_with([](tp::test::GltfBuilder& g) {
             const uint32_t bad = 99;
             const json& a =
                 g.doc["accessors"][g.doc["meshes"][0]["primitives"][0]["indices"].get<size_t>()];
             const json& v = g.doc["bufferViews"][a["bufferView"].get<size_t>()];
             std::memcpy(&g.bin[v["byteOffset"].get<size_t>()], &bad, 4);
         }),
         "bad.gltf",
         "",
         {"bad.gltf", "meshes[0].primitives[0].indices", "99", "out of range"}},
        {"a missing image",
         gltf_with(textured("missing.png")),
         "bad.gltf",
         "",
         {"bad.gltf", "images[0].uri", "missing.png", "does not exist"}},
        {"an image that cannot be decoded",
         [&] {
             auto files = gltf_with(textured("garbage.png"));
             files.push_back({"garbage.png", kPngGarbage});
             return files;
         }(),
         "bad.gltf",
         "",
         {"bad.gltf", "images[0]", "baseColorTexture", "cannot decode"}},
        {"a missing buffer file",
         {gltf_with([](tp::test::GltfBuilder&) {})[0]},
         "bad.gltf",
         "",
         {"bad.gltf", "buffers[0].uri", "bad.bin", "does not exist"}},
        {"a buffer file shorter than its byteLength",
         [&] {
             auto files = gltf_with([](tp::test::GltfBuilder&) {});
             files[1].second.resize(16);
             return files;
         }(),
         "bad.gltf",
         "",
         {"bad.gltf", "buffers[0].byteLength"}},
        {"an unsupported required extension",
         gltf_with([](tp::test::GltfBuilder& g) {
             g.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
             g.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
         }),
         "bad.gltf",
         "",
         {"bad.gltf", "extensionsRequired[0]", "KHR_draco_mesh_compression", "not support"}},
        {"a NaN in a matrix (Python's json.dump)",
         python_nan,
         "bad.gltf",
         "",
         {"bad.gltf", "nodes[0].matrix[5]", "malformed JSON"}},
        {"a world matrix that overflows",
         gltf_with(with_two_scaled_nodes),
         "bad.gltf",
         "",
         {"bad.gltf", "nodes[1]", "not finite"}},
        {"a rotation that is not a unit quaternion",
         gltf_with([](tp::test::GltfBuilder& g) {
             g.doc["nodes"][0]["rotation"] = {0, 0, 0, 0.5};
         }),
         "bad.gltf",
         "",
         {"bad.gltf", "nodes[0].rotation", "unit quaternion"}},
        {"a property of the wrong type",
         gltf_with([](tp::test::GltfBuilder& g) { g.doc["nodes"][0]["mesh"] = "0"; }),
         "bad.gltf",
         "",
         {"bad.gltf", "nodes[0].mesh", "not an index into 'meshes'"}},
        {"a cycle of children",
         gltf_with([](tp::test::GltfBuilder& g) {
             g.doc["nodes"][0]["children"] = {1};
             g.add("nodes", {{"children", {0}}});
         }),
         "bad.gltf",
         "",
         {"bad.gltf", "nodes[0]", "cycle"}},
        {"a spot light whose inner cone is not inside its outer cone",
         gltf_with([](tp::test::GltfBuilder& g) {
             g.doc["extensions"]["KHR_lights_punctual"]["lights"] = {
                 {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.6}, {"outerConeAngle", 0.4}}}}};
             g.doc["nodes"][0]["extensions"]["KHR_lights_punctual"]["light"] = 0;
         }),
         "bad.gltf",
         "",
         {"bad.gltf", "KHR_lights_punctual.lights[0].spot.innerConeAngle", "outerConeAngle"}},
        {"a roughness above 1",
         gltf_with([](tp::test::GltfBuilder& g) {
             g.doc["materials"][0]["pbrMetallicRoughness"] = {{"roughnessFactor", 1.5}};
         }),
         "bad.gltf",
         "",
         {"bad.gltf", "materials[0].pbrMetallicRoughness.roughnessFactor", "[0, 1]"}},
        {"a texture index naming no texture",
         gltf_with([](tp::test::GltfBuilder& g) {
             g.doc["materials"][0]["normalTexture"] = {{"index", 3}};
         }),
         "bad.gltf",
         "",
         {"bad.gltf", "materials[0].normalTexture.index", "textures"}},
        {"glTF 1.0",
         gltf_with([](tp::test::GltfBuilder& g) { g.doc["asset"]["version"] = "1.0"; }),
         "bad.gltf",
         "",
         {"bad.gltf", "asset.version"}},
        {"a truncated GLB file",
         {{"bad.glb", glb.substr(0, glb.size() - 8)}},
         "bad.glb",
         "",
         {"bad.glb", "GLB", "length"}},
        {"a GLB whose BIN chunk is shorter than buffer 0",
         [&] {
             std::string b = glb;
             // The BIN chunk's length field: 8 bytes before its data, which ends the file.
             const uint32_t json_len = uint32_t(uint8_t(b[12])) | uint32_t(uint8_t(b[13])) << 8;
             const size_t bin_header = 20 + json_len;
             const uint32_t shorter = 16;
             std::memcpy(&b[bin_header], &shorter, 4);
             b.resize(bin_header + 8 + shorter);
             const uint32_t total = uint32_t(b.size());
             std::memcpy(&b[8], &total, 4);
             return std::vector<std::pair<std::string, std::string>>{{"bad.glb", b}};
         }(),
         "bad.glb",
         "",
         {"bad.glb", "buffers[0].byteLength"}},
        {"--camera beyond the asset's cameras",
         gltf_with([](tp::test::GltfBuilder&) {}),
         "bad.gltf",
         "--camera 3",
         {"bad.gltf", "--camera 3", "0 camera(s)"}},
        {"--camera on an OBJ file",
         {{"bad.obj", kTriangleObj + "f 1 2 3\n"}},
         "bad.obj",
         "--camera 0",
         {"bad.obj", "--camera"}},
    });
}

TEST_CASE("impossible cameras are rejected with the file and field or flag", "[cli][bad-input]") {
    const std::string ok = with_camera(kCamera);
    check_all({
        {"eye equals target in the scene",
         {{"bad.json", with_camera(R"({"eye": [1, 2, 3], "target": [1, 2, 3]})")}},
         "bad.json",
         "",
         {"bad.json", "camera.eye", "camera.target"}},
        {"up parallel to the view in the scene",
         {{"bad.json", with_camera(R"({"eye": [0, 0, 3], "target": [0, 0, 0], "up": [0, 0, 2]})")}},
         "bad.json",
         "",
         {"bad.json", "camera.up"}},
        {"field of view 0 in the scene",
         {{"bad.json", with_camera(R"({"eye": [0, 0, 3], "target": [0, 0, 0], "fov": 0})")}},
         "bad.json",
         "",
         {"bad.json", "camera.fov"}},
        {"field of view 180 in the scene",
         {{"bad.json", with_camera(R"({"eye": [0, 0, 3], "target": [0, 0, 0], "fov": 180})")}},
         "bad.json",
         "",
         {"bad.json", "camera.fov"}},
        {"width 0 in the scene",
         {{"bad.json", "{\"film\": {\"width\": 0}, \"meshes\": " + kMeshes + ", \"materials\": " +
                           kMaterials + ", \"objects\": " + kObjects + "}\n"}},
         "bad.json",
         "",
         {"bad.json", "film.width"}},
        {"--eye equal to --target",
         {{"ok.json", ok}},
         "ok.json",
         "--eye 1,1,1 --target 1,1,1",
         {"ok.json", "--eye", "--target"}},
        {"--up parallel to the view",
         {{"ok.json", ok}},
         "ok.json",
         "--up 0,0,-1",
         {"ok.json", "--up"}},
        {"--fov 0", {{"ok.json", ok}}, "ok.json", "--fov 0", {"--fov"}},
        {"--fov 180", {{"ok.json", ok}}, "ok.json", "--fov 180", {"--fov"}},
        {"--width 0", {{"ok.json", ok}}, "ok.json", "--width 0", {"--width"}},
        {"--height 0", {{"ok.json", ok}}, "ok.json", "--height 0", {"--height"}},
        {"--eye with two numbers", {{"ok.json", ok}}, "ok.json", "--eye 1,2", {"--eye"}},
        {"--eye with a NaN", {{"ok.json", ok}}, "ok.json", "--eye nan,0,1", {"--eye"}},
        {"--spp 0", {{"ok.json", ok}}, "ok.json", "--spp 0", {"--spp"}},
    });
}

TEST_CASE("an unwritable output path is rejected before rendering and nothing is written",
          "[cli][bad-input]") {
    // Every output is checked before the render starts: a --png or --stats path in a missing
    // directory used to fail only after the render, leaving the EXR behind.
    const fs::path dir = tp::test::temp_dir("bad-output");
    std::ofstream(dir / "ok.json") << with_camera(kCamera);
    const std::string exr = (dir / "out.exr").string(), png = (dir / "out.png").string(),
                      json = (dir / "out.json").string(), missing = (dir / "no" / "x").string();
    fs::create_directory(dir / "taken.png");
    const struct {
        const char* name;
        std::string args, option;
    } cases[] = {
        {"-o in a missing directory", " -o " + shell_quote(missing + ".exr"), "-o"},
        {"--png in a missing directory",
         " -o " + shell_quote(exr) + " --png " + shell_quote(missing + ".png"), "--png"},
        {"--stats in a missing directory",
         " -o " + shell_quote(exr) + " --png " + shell_quote(png) + " --stats " +
             shell_quote(missing + ".json"),
         "--stats"},
        {"--png naming a directory",
         " -o " + shell_quote(exr) + " --png " + shell_quote((dir / "taken.png").string()),
         "--png"},
    };
    for (const auto& c : cases) {
        const auto r = run(tp::test::twinpath_bin() + " render " +
                           shell_quote((dir / "ok.json").string()) + " --spp 1" + c.args);
        INFO(c.name << "\n" << r.out);
        CHECK(r.exit_code == 2);
        CHECK(r.out.find(c.option + " ") != std::string::npos);
        CHECK(r.out.find("internal error") == std::string::npos);
        for (const std::string& f : {exr, png, json, exr + ".partial"}) CHECK_FALSE(fs::exists(f));
    }
    fs::remove_all(dir);
}

// Messages that name the real cause (not "up parallel to the viewing direction", "camera.eye
// must be finite", "got -1" or "read error"), geometry beyond the float32 range rule (which
// would render black on the CPU), a bounded quote of the offending text, and repeated JSON keys
// (refused, where a JSON parser would keep the last value silently).
TEST_CASE("far geometry, huge values and repeated keys name their real cause", "[cli][bad-input]") {
    const std::string far_object = scene_json(kCamera, kMaterials, kMeshes,
                                              R"([{"mesh": "ball", "material": "m"},
            {"name": "far", "mesh": "ball", "material": "m", "transform": {"translate": [1e30, 0, 0]}}])");
    check_all({
        {"an object at 1e30 names the object and the range rule",
         {{"bad.json", far_object}},
         "bad.json",
         "",
         {"bad.json", "object 1 ('far')", "float32"}},
        {"a camera eye at 3e38 names the distance",
         {{"bad.json", with_camera(R"({"eye": [3e38, 0, 0], "target": [0, 0, 0]})")}},
         "bad.json",
         "",
         {"bad.json", "camera.target", "3e+38", "float32"}},
        {"an OBJ with vertices at +-3e38 and no camera names the object",
         {{"bad.obj", "v -3e38 0 0\nv 3e38 0 0\nv 0 1 0\nf 1 2 3\n"}},
         "bad.obj",
         "",
         {"bad.obj", "object 0", "float32"}},
        {"--spp 2^64 - 1 quotes the number",
         {{"ok.json", with_camera(kCamera)}},
         "ok.json",
         "--spp 18446744073709551615",
         {"--spp", "18446744073709551615"}},
        {"render.spp 2^64 - 1 quotes the number",
         {{"bad.json", with_extra(R"("render": {"spp": 18446744073709551615})")}},
         "bad.json",
         "",
         {"bad.json", "render.spp", "got 18446744073709551615"}},
        {"a repeated JSON key names the key and both lines",
         {{"bad.json", "{\n  \"camera\": " + kCamera +
                           ",\n  \"materials\": {\"m\": {\n    \"Kd\": [-1, 0, 0],\n    \"Kd\": "
                           "[0.5, 0.5, 0.5]}},\n  \"meshes\": " +
                           kMeshes + ",\n  \"objects\": " + kObjects + "\n}\n"}},
         "bad.json",
         "",
         {"bad.json", "'Kd'", "lines 4 and 5"}},
    });
}

TEST_CASE("a scene or MTL path that is a directory says so", "[cli][bad-input]") {
    const fs::path dir = tp::test::temp_dir("directory-path");
    fs::create_directory(dir / "x.obj");
    fs::create_directory(dir / "m.mtl");
    std::ofstream(dir / "ok.obj") << "mtllib m.mtl\n" << kTriangleObj << "f 1 2 3\n";
    for (const char* scene : {"x.obj", "ok.obj"}) {
        const auto r = run(tp::test::twinpath("render " + shell_quote((dir / scene).string()) +
                                              " -o " + shell_quote((dir / "out.exr").string())));
        INFO(scene << "\n" << r.out);
        CHECK(r.exit_code == 2);
        CHECK(r.out.find("is a directory") != std::string::npos); // before: "read error"
    }
    fs::remove_all(dir);
}

TEST_CASE("a huge token is quoted by at most 80 characters", "[cli][bad-input]") {
    const fs::path dir = tp::test::temp_dir("huge-token");
    std::ofstream(dir / "bad.obj") << "v 0 0 0\nv " << std::string(1 << 20, '7') << "x 0 0\n";
    const auto r = run(tp::test::twinpath("render " + shell_quote((dir / "bad.obj").string()) +
                                          " -o " + shell_quote((dir / "out.exr").string())));
    INFO(r.out.substr(0, 400));
    CHECK(r.exit_code == 2);
    CHECK(r.out.find("bad.obj:2") != std::string::npos);
    CHECK(r.out.find("more bytes") != std::string::npos);
    CHECK(r.out.size() < 400); // before: the whole megabyte
    fs::remove_all(dir);
}

TEST_CASE("what looked wrong and is not: a huge rotation axis, a BOM in an OBJ",
          "[cli][bad-input]") {
    const fs::path dir = tp::test::temp_dir("accepted");
    // The axis is a direction: its length does not matter (before: "singular (zero scale?)").
    std::ofstream(dir / "axis.json") << scene_json(
        kCamera, kMaterials, kMeshes,
        R"([{"mesh": "ball", "material": "m", "transform": {"rotate": {"axis": [3e38, 0, 0], "degrees": 30}}}])");
    // A UTF-8 byte order mark, accepted in JSON, was "unknown OBJ statement" in an OBJ.
    std::ofstream(dir / "bom.obj") << "\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    for (const char* scene : {"axis.json", "bom.obj"}) {
        const auto r = run(tp::test::twinpath("render " + shell_quote((dir / scene).string()) +
                                              " --spp 1 --width 8 --height 8 -o " +
                                              shell_quote((dir / "out.exr").string())));
        INFO(scene << "\n" << r.out);
        CHECK(r.exit_code == 0);
    }
    fs::remove_all(dir);
}

TEST_CASE("an unknown subcommand is named and the subcommands listed", "[cli][bad-input]") {
    const auto r = run(tp::test::twinpath("rendr cornell"));
    INFO(r.out);
    CHECK(r.exit_code == 2);
    CHECK(r.out.find("'rendr' is not a subcommand") != std::string::npos);
    CHECK(r.out.find("render, compare") != std::string::npos);
}

TEST_CASE("a malformed Vulkan driver manifest is named as a possible cause", "[cli][bad-input]") {
    const fs::path dir = tp::test::temp_dir("bad-icd");
    std::ofstream(dir / "icd.json") << "{ \"file_format_version\": \"1.0.0\", \"ICD\": {";
    const auto r =
        run("VK_DRIVER_FILES=" + shell_quote((dir / "icd.json").string()) +
            " VK_ICD_FILENAMES=" + shell_quote((dir / "icd.json").string()) + " " +
            tp::test::twinpath("render furnace --backend vulkan --spp 1 --width 8 --height 8 -o " +
                               shell_quote((dir / "out.exr").string())));
    INFO(r.out);
    CHECK(r.exit_code == 3);
    CHECK(r.out.find("icd.json") != std::string::npos);
    fs::remove_all(dir);
}
