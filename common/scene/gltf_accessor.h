// Reading a glTF accessor's elements out of its buffer view (glTF 2.0, section 3.6.2): any
// component type, strided or packed, normalized integers mapped to [0, 1] or [-1, 1]
// (section 3.11), and sparse substitution (section 3.6.2.3). The bounds were checked when the
// document was read (gltf_document.h); the sparse indices are checked here.
#pragma once

#include "scene/gltf_document.h"
#include "scene/gltf_resources.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tp {

// The accessor's count * components values, element by element. `field` names the accessor's
// use for errors ("meshes[0].primitives[1].attributes.POSITION").
std::vector<double> read_gltf_accessor(const GltfDocument& d, const GltfResources& res,
                                       uint32_t accessor, const std::string& field);

// An index accessor: SCALAR of unsigned byte, short or int, not normalized (section 3.7.2.1).
std::vector<uint32_t> read_gltf_indices(const GltfDocument& d, const GltfResources& res,
                                        uint32_t accessor, const std::string& field);

} // namespace tp
