// The GPU engine's side of the shared path loop (shared/integrator.h): its ray counts and, in
// the normal variant, a path log that records nothing (debug.glsl is the debug variant's).
// The trace hooks come from the trace include the entry point includes before this file.
#ifndef TP_SHADERS_INTEGRATOR_GLSL
#define TP_SHADERS_INTEGRATOR_GLSL

#include "scene_access.glsl"
#include "shared/camera.h"
#include "shared/path.h"
#include "shared/path_log.h"
#include "shared/rng.h"
#include "shared/roulette.h"

struct RayCounts {
    uint camera;
    uint extension;
    uint shadow;
};

#ifndef TP_DEBUG_SHADER
const bool path_log_recording = false;
void path_log_emit(PathVertex v, uint termination) {}
#endif

#include "shared/integrator.h"

#endif // TP_SHADERS_INTEGRATOR_GLSL
