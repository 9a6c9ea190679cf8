// The rule that maps a glTF 2.0 material (metallic-roughness and the extensions of
// gltf_document.h) onto twinpath's materials; docs/scene-format.md ("glTF materials") states
// it as a table. Pure: no I/O.
#pragma once

#include "scene/gltf_document.h"
#include "shared/types.h"

#include <string>
#include <vector>

namespace tp {

// The largest Phong exponent a glTF roughness maps to (roughness below ~0.027).
constexpr float kMaxGltfPhongExponent = 1e6f;

// The modified-Phong exponent that stands for glTF's roughness r. glTF's microfacet
// distribution has width alpha = r^2 (glTF 2.0, Appendix B.3). Walter et al. 2007, section
// 5.2, match a Phong (half-vector) distribution of exponent a_p = 2 / alpha^2 - 2 to a
// microfacet distribution of width alpha. twinpath's lobe is Lafortune's, around the mirror
// direction: near the peak the angle to the mirror direction is twice the half-vector's angle,
// so cos^n(2 theta) ~ exp(-2 n theta^2) matches cos^a_p(theta) ~ exp(-a_p theta^2 / 2) for
// n = a_p / 4. Hence Ns = (2 / r^4 - 2) / 4 = 1 / (2 r^4) - 1/2: 0 at r = 1, 7.5 at r = 0.5,
// capped at kMaxGltfPhongExponent.
float gltf_phong_exponent(float roughness);

struct GltfMaterialMapping {
    Material material{};                  // kd_texture NO_TEXTURE: the loader sets it
    bool uses_base_color_texture = false; // kd is multiplied by the base colour texture
    std::vector<std::string> dropped;     // what twinpath does not render, one entry each
};

// `emissive_texture_mean`: the mean linear texel of the emissive texture, (1, 1, 1) without
// one. The material satisfies validate_material (scene.h) for every valid glTF input.
GltfMaterialMapping map_gltf_material(const GltfMaterial& m, const vec3& emissive_texture_mean);

} // namespace tp
