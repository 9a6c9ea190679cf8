// The GPU engine's scene reads: the storage buffers of bindings.glsl under the names that
// shared/scene_access.h reads, the feature mask as a specialization constant (features.glsl),
// and its two hooks.
#ifndef TP_SHADERS_SCENE_ACCESS_GLSL
#define TP_SHADERS_SCENE_ACCESS_GLSL

#include "bindings.glsl"
#include "features.glsl"
#include "shared/alpha.h"
#include "shared/lights.h"
#include "shared/path.h"
#include "shared/surface.h"
#include "shared/texture.h"
#include "trace_hit.glsl"

// Computed at each hit: a buffer of them would be one more read per hit.
InstanceErrorTerms scene_error_terms(uint instance) {
    return instance_error_terms(instances[instance]);
}

uint scene_env_table_size() {
    return batch.env_table_size;
}

#include "shared/scene_access.h"

#endif // TP_SHADERS_SCENE_ACCESS_GLSL
