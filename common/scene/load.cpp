#include "scene/load.h"

#include "scene/gltf_loader.h"
#include "scene/json_loader.h"
#include "scene/obj_loader.h"
#include "shared/math.h"
#include "util/error.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;

namespace tp {

std::string bundled_scenes_dir() {
    if (const char* env = std::getenv("TWINPATH_SCENES")) return env;
    // Installed layouts: <prefix>/bin/twinpath with <prefix>/scenes (the GPU bundle), or the
    // build tree, whose CMake configuration records the source directory.
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        for (const fs::path& p :
             {exe.parent_path() / "scenes", exe.parent_path().parent_path() / "scenes"})
            if (fs::is_directory(p)) return p.string();
    }
    return TWINPATH_SOURCE_SCENES_DIR;
}

std::optional<std::string> find_bundled_scene(const std::string& name) {
    if (name.empty() || name.find('/') != std::string::npos) return std::nullopt;
    for (const char* ext : {".json", ".gltf", ".glb"}) {
        const fs::path bundled = fs::path(bundled_scenes_dir()) / (name + ext);
        if (fs::exists(bundled)) return bundled.string();
    }
    return std::nullopt;
}

std::string resolve_scene_path(const std::string& arg) {
    std::error_code ec;
    if (fs::is_directory(arg, ec)) input_error("{}: is a directory, not a scene file", arg);
    if (fs::exists(arg)) return arg;
    if (const std::optional<std::string> bundled = find_bundled_scene(arg)) return *bundled;
    input_error("{}: no such scene file or bundled scene (bundled scenes are in {})", arg,
                bundled_scenes_dir());
}

namespace {

Scene load_obj_scene(const std::string& path, std::vector<std::string>& warnings) {
    Scene scene;
    scene.path = path;
    Material grey = default_material();
    grey.kd = vec3(0.8f);
    scene.materials.push_back(grey);
    scene.material_names.push_back("default");
    for (const ObjPart& part : load_obj(path, scene, 0, warnings)) {
        Object o;
        o.name = scene.meshes[part.mesh].name;
        o.mesh = part.mesh;
        o.material = part.material;
        scene.objects.push_back(o);
    }
    light_if_unlit(scene, warnings);
    return scene; // camera.given stays false: flatten() frames the scene
}

} // namespace

Scene load_scene(const std::string& path_or_name, std::vector<std::string>& warnings,
                 const LoadOptions& options) {
    const std::string path = resolve_scene_path(path_or_name);
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    const bool gltf = ext == ".gltf" || ext == ".glb";
    if (options.camera && !gltf)
        input_error("{}: --camera picks a camera of a glTF file (.gltf, .glb)", path);
    Scene scene;
    if (ext == ".json")
        scene = load_json_scene(path, warnings);
    else if (ext == ".obj")
        scene = load_obj_scene(path, warnings);
    else if (gltf)
        scene = load_gltf_scene(path, GltfOptions{options.camera}, warnings);
    else
        input_error("{}: unknown scene format '{}' (expected .json, .obj, .gltf or .glb)", path,
                    ext);
    if (scene.skipped_triangles > 0)
        warnings.push_back(fmt::format("{}: skipped {} degenerate (zero-area) triangle(s)", path,
                                       scene.skipped_triangles));
    return scene;
}

} // namespace tp
