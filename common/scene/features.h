// Scene feature analysis: which of the features of shared/features.h a flattened
// scene uses, so that each engine can render it with a path loop compiled for exactly those.
// Pure: reads the FlatScene, nothing else.
#pragma once

#include "scene/flatten.h"
#include "shared/features.h"

#include <optional>
#include <string>
#include <vector>

namespace tp {

struct SceneFeatures {
    uint32_t mask = 0; // FEATURE_* bits

    bool has(uint32_t feature) const { return (mask & feature) != 0; }
    // Names of the set bits in bit order ("textures", "phong_specular", ...).
    std::vector<std::string> names() const;
    // The names joined by ", ", or "none".
    std::string summary() const;
    // Whether anything emits light: an emissive material on an object, a light, an environment.
    bool emits() const;
};

// For a scene in which nothing emits: a warning that every render of it is black (and two
// engines agree on it whatever their bugs); nullopt otherwise. `where` names the scene.
std::optional<std::string> dark_scene_warning(const FlatScene& scene, const std::string& where);

// What `scene` uses. Only materials that an instance refers to count; a light or environment
// that flatten() dropped (no power) does not.
SceneFeatures analyze_features(const FlatScene& scene);

// The name of one FEATURE_* bit; "" for anything else.
const char* feature_name(uint32_t feature);

// The mask a render uses: the scene's, or FEATURES_ALL when `all` (`--features all`).
uint32_t render_feature_mask(const FlatScene& scene, bool all);

} // namespace tp
