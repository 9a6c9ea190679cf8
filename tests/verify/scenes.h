// The scenes verify's statistical tests render: bundled scenes at a small size, and one with
// every emitter made brighter (a uniform relative bias of the whole image).
#pragma once

#include "scene/flatten.h"

#include <string>

namespace tp::test {

// The bundled scene `name` at width x height, with `camera` overrides when given.
FlatScene small_scene(const std::string& name, uint32_t width, uint32_t height,
                      const SceneOverrides& camera = {});

// The scene with the emission of its materials and the value of its lights (radiance,
// intensity, irradiance, a constant environment's radiance) times `scale`: light transport is
// linear in the emission, so every sample, hence every pixel's mean and standard deviation, is
// times `scale` too. (An environment map's texels are not scaled: no scene here has one.)
FlatScene brighter(FlatScene scene, float scale);

} // namespace tp::test
