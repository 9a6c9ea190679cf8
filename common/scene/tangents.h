// The tangent frame a normal map needs where a mesh gives none (glTF 2.0, "Meshes": a mesh
// without NORMAL gets flat normals and its tangents are ignored; a normal-mapped mesh without
// TANGENT gets generated tangents).
//
// The tangent frame is that of the normal map's image: its texel x points along increasing s
// and its texel y up the image, towards decreasing t (image coordinates, shared/texture.h; glTF
// 2.0, "normalTexture": +Y is up). Per triangle the tangent T = dP/ds and the image's up
// U = -dP/dt follow from the positions and the (s, t) of its corners (Lengyel, "Computing
// Tangent Space Basis Vectors for an Arbitrary Mesh", 2001). Each vertex sums, over the
// triangles around it, T and U projected onto the plane of its normal, normalized and weighted
// by the triangle's angle at that corner (MikkTSpace's weighting); its tangent is the sum made
// orthogonal to the normal (Gram-Schmidt) and w = +1 where cross(normal, tangent) points up
// the image, -1 where the mapping is mirrored (glTF's bitangent = cross(normal, tangent) w).
//
// This is MikkTSpace's per-vertex accumulation without its splitting of vertices whose
// triangles' tangent spaces disagree (a mirrored seam sharing vertices): such a vertex gets the
// mean, as it gets the mean normal. Where the uv mapping is degenerate (no triangle around the
// vertex spans an area in (s, t)) the tangent is an arbitrary unit vector orthogonal to the
// normal, w = +1: the map has no direction there.
#pragma once

#include "scene/scene.h"

#include <vector>

namespace tp {

// Tangents (xyz unit, w = +-1) for `mesh`'s vertices, read through `slot`: its uv set
// (SLOT_UV1: mesh.uvs1, else mesh.uvs; a mesh without that set has no directions) and its
// uv -> (s, t) map. Uses mesh.normals where given.
std::vector<vec4> generate_tangents(const Mesh& mesh, const TextureSlot& slot);

// Gives every triangle its own three vertices with the triangle's unit normal (counter-clockwise
// front), carrying the uv sets; the triangles must have non-zero area (finalize_mesh). Drops
// tangents, which were made for the old normals.
void unweld_flat_normals(Mesh& mesh);

// What a normal map read through `slot` needs of `mesh`: flat normals where it has none, then
// generated tangents where it has none.
void add_tangent_frame(Mesh& mesh, const TextureSlot& slot);

} // namespace tp
