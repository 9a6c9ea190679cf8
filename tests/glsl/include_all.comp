#version 460
// Compiles every shared header as GLSL 4.60 (tests/CMakeLists.txt runs glslangValidator on it),
// so a C++-only construct in common/shared/ fails the suite before any engine uses it.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require

#include "shared/brdf.h"
#include "shared/camera.h"
#include "shared/features.h"
#include "shared/intersect.h"
#include "shared/lang.h"
#include "shared/lights.h"
#include "shared/math.h"
#include "shared/offset.h"
#include "shared/path.h"
#include "shared/path_log.h"
#include "shared/rng.h"
#include "shared/roulette.h"
#include "shared/sampling.h"
#include "shared/surface.h"
#include "shared/texture.h"
#include "shared/types.h"

layout(local_size_x = 1) in;
layout(scalar, binding = 0) buffer Result { vec4 value; } result;

void main() {
    RngKey key = rng_key(1u, 2u, 3u);
    result.value = vec4(rng_get(key, 0u), phong_power(0.5f, 10.0f), 0.0f, 1.0f);
}
