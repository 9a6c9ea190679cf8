// Meshes and textures the project generates itself (bundled scenes use nothing else).
#pragma once

#include "scene/scene.h"

namespace tp {

// Icosphere of radius 1 about the origin: the icosahedron subdivided `subdivisions` times
// (20 * 4^s triangles), smooth normals, lat-long uvs. Outward-facing, or inward-facing
// (winding and normals reversed) for a closed room seen from inside.
Mesh make_icosphere(uint32_t subdivisions, bool inward);

// Square [-1, 1]^2 in the XZ plane facing +Y, uv (0,0) at (-1, 0, 1).
Mesh make_quad();

// Cube [-1, 1]^3 with outward faces and flat shading.
Mesh make_box();

// Checkerboard of `checks` x `checks` squares.
Texture make_checker_texture(uint32_t size, uint32_t checks, vec3 a, vec3 b);

// Marble: veins sin(scale x + 6 turbulence) between colors a and b, with turbulence the
// classic sum of |noise| octaves (Perlin, "An Image Synthesizer", SIGGRAPH 1985) over Perlin's
// improved gradient noise (SIGGRAPH 2002). Tileable: the noise lattice wraps at the border.
Texture make_marble_texture(uint32_t size, float scale, vec3 a, vec3 b, uint32_t seed);

} // namespace tp
