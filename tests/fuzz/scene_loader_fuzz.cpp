#include "scene_loader_fuzz.h"

#include "scene/flatten.h"
#include "scene/load.h"
#include "util/error.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// One directory per process for the files the loaders read (they take paths).
const fs::path& work_dir() {
    static const fs::path dir = [] {
        const fs::path d =
            fs::temp_directory_path() / ("twinpath-fuzz-" + std::to_string(::getpid()));
        fs::create_directories(d);
        return d;
    }();
    return dir;
}

void write(const fs::path& p, const uint8_t* data, size_t size) {
    std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char*>(data), long(size));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    const char kind = char(data[0]);
    const fs::path& dir = work_dir();
    // Each input alone: no file of an earlier one for this one to name.
    for (const char* f : {"in.obj", "in.mtl", "in.json", "uses_mtl.obj", "in.gltf", "in.glb"})
        fs::remove(dir / f);
    fs::path scene;
    if (kind == 'g' || kind == 'b') { // glTF: the JSON form or the binary container
        scene = dir / (kind == 'g' ? "in.gltf" : "in.glb");
        write(scene, data + 1, size - 1);
    } else if (kind == 'o') {
        scene = dir / "in.obj";
        write(scene, data + 1, size - 1);
    } else if (kind == 'm') {
        write(dir / "in.mtl", data + 1, size - 1);
        scene = dir / "uses_mtl.obj";
        const std::string obj = "mtllib in.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n";
        write(scene, reinterpret_cast<const uint8_t*>(obj.data()), obj.size());
    } else {
        scene = dir / "in.json";
        write(scene, data + 1, size - 1);
    }
    try {
        std::vector<std::string> warnings;
        (void)tp::flatten(tp::load_scene(scene.string(), warnings));
    } catch (const tp::InputError&) {
    } catch (const tp::RuntimeError&) {
    }
    return 0;
}
