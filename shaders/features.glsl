// The feature mask of the render shaders (shared/features.h) as a specialization
// constant: the host sets it to the scene's mask when it creates the pipeline
// (vulkan_rt/device/specialization.h), so the driver compiles a path loop without the code of the
// features the scene lacks; the default, every feature, is what `--features all` runs and what
// the SPIR-V holds before specialization.
#ifndef TP_SHADERS_FEATURES_GLSL
#define TP_SHADERS_FEATURES_GLSL

#include "interface.h"
#include "shared/features.h"

layout(constant_id = SPEC_SCENE_FEATURES) const uint scene_features = FEATURES_ALL;

#endif // TP_SHADERS_FEATURES_GLSL
