// The bundled Cornell box (scenes/cornell.json) written by the tests as a plain OBJ + MTL and as
// glTF, for the format-equivalence tests: the same triangles in the same order, one mesh per
// material (as the OBJ loader groups faces by usemtl), vertices in metres as float32 (the glTF
// buffer's type; the OBJ prints each float exactly), no camera (the tests pass the bundled
// camera as flags), and glTF materials that are the MTL's Lambertian ones: base colour the
// MTL's Kd, metallic 0, roughness 1 and KHR_materials_specular factor 0 (glTF's BSDF without
// its specular layer is Kd / pi), and emission as emissiveFactor times
// KHR_materials_emissive_strength.
#pragma once

#include <string>

namespace tp::test {

struct CornellFiles {
    std::string obj;          // dir/cornell.obj (+ cornell.mtl)
    std::string glb;          // dir/cornell.glb
    std::string gltf;         // dir/cornell.gltf (+ cornell.bin)
    std::string camera_flags; // --eye/--target/--up/--fov of the bundled scene
};

CornellFiles write_cornell_files(const std::string& dir);

} // namespace tp::test
