// The scene as Embree's path tracer tutorial (/usr/bin/pathtracer, Debian embree-tools) can
// render it too: the tutorial reads OBJ + MTL, takes its lights from the command line, ignores
// MTL Ke, and its ambient light is both sampled by shadow rays and added when a path escapes,
// without MIS (tutorials/pathtracer/pathtracer_device.cpp), so it counts a sky twice. Both
// renderers of a peer comparison render the variant made here, so they compute the same image.
#pragma once

#include "scene/flatten.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace tp::lab {

// Turns `scene` into its peer variant and returns what changed (for the report):
// - each emissive object becomes a point light at its area-weighted centroid, a quarter of
//   the emitter's size in front of it, of the same power: a Lambertian emitter of radiance L
//   and area A emits pi L A, an isotropic point light 4 pi I, so I = L A / 4;
// - the environment is removed.
// Leaves `reason` non-empty (and the scene unusable) when a material has no equivalent in the
// tutorial's OBJ material: mirror, dielectric, textured.
std::vector<std::string> make_peer_variant(Scene& scene, std::string& reason);

// Writes the flattened scene's world-space triangles (instances expanded) to `obj_path` and
// its materials to an MTL file beside it (Kd, Ks, Ns, named m<index>), with the meshes' normals and
// uvs where they have them. Like everything flatten() places, they
// are camera-relative (FlatScene::origin), as are the camera and lights that
// peer_scene_arguments() gives the tutorial, so both renderers see the same scene.
void write_obj(const FlatScene& scene, const std::string& obj_path);

// The tutorial's command-line arguments for the scene's camera, film and lights.
std::vector<std::string> peer_scene_arguments(const FlatScene& scene);

} // namespace tp::lab
