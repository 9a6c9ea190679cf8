// Touching dielectrics, e.g. water filling a glass, are modelled as two closed meshes whose
// shared faces coincide: the same three vertices with opposite windings. Traced as they are,
// a ray leaving one object spawns past the shared plane and misses the other's face there, so
// entries and exits no longer pair up (docs/stress.md, "Touching glass cubes"). The physically
// right model has one surface there, an interface between the two media with relative index
// n_A / n_B (the form pbrt expects such scenes in: one surface whose two sides carry the two
// media, its MediumInterface). This pass rewrites such a scene into that form before
// flatten(): the faces of A that B touches become an object of their own whose material is a
// dielectric of index n_A / n_B seen from B (Material::ior is relative to the side the normal
// points to), and B loses its copies of them. No engine changes: all three trace the result.
#pragma once

#include "scene/scene.h"

#include <optional>

namespace tp {

struct DielectricInterfaces {
    Scene scene;        // the rewritten scene
    uint64_t faces = 0; // coincident triangle pairs merged into one interface triangle each
};

// Pairs triangles of different objects with dielectric, non-emissive materials that have the
// same world-space vertices (each M p + T computed in double) in opposite order. Faces that overlap
// without the same triangulation are left as they are. Returns nothing when there is no such pair,
// so that the common scene is not copied.
std::optional<DielectricInterfaces> merge_dielectric_interfaces(const Scene& scene);

} // namespace tp
