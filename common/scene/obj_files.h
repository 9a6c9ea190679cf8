// The OBJ files that a scene's meshes name, each read once and all at once: a file is parsed
// into a scene of its own on a TBB task, and appended to the scene being loaded as often as a
// mesh names it, in the meshes' order. What each append adds (meshes, materials, texture slots,
// warnings, skipped triangles) is what load_obj would have added at that point, so the scene is
// the same as a serial load's.
#pragma once

#include "scene/obj_loader.h"

#include <exception>
#include <map>
#include <string>
#include <vector>

namespace tp {

// One file as load_obj reads it into an empty scene, or the error that reading it raised.
struct ObjFile {
    Scene scene;
    std::vector<ObjPart> parts;
    std::vector<std::string> warnings;
    std::exception_ptr error;
};

// Reads every file of `paths` (repeats read once) in parallel, with `default_material` for
// faces without a material; errors are kept with their file, not thrown.
std::map<std::string, ObjFile> read_obj_files(const std::vector<std::string>& paths,
                                              uint32_t default_material);

// Appends `file` to `scene` as load_obj(path, scene, default_material, warnings) would, and
// returns the parts; rethrows the file's error.
std::vector<ObjPart> append_obj(const ObjFile& file, Scene& scene, uint32_t default_material,
                                std::vector<std::string>& warnings);

} // namespace tp
