// The samplers sample_draws.comp can run, and its parameter blocks (shared-header dialect:
// the C++ test fills them).
#ifndef TP_TESTS_DRAW_IDS_H
#define TP_TESTS_DRAW_IDS_H

#include "shared/lang.h"

TP_NAMESPACE_BEGIN

const uint DRAW_COSINE = 0u;
const uint DRAW_PHONG_LOBE = 1u; // f0.x: exponent
const uint DRAW_SPHERE = 2u;
const uint DRAW_TRIANGLE = 3u;
const uint DRAW_RNG_PAIR = 4u;
const uint DRAW_PHONG_MIXTURE = 5u;  // (kd, ns) f0, ks f1, n f2, wo f3
const uint DRAW_DIELECTRIC = 6u;     // ior f0.w, n f2, wo f3
const uint DRAW_TRIANGLE_LIGHT = 7u; // (p0, area) f0, p1 f1, p2 f2, shading point f3
const uint DRAW_ENV_MAP = 8u;        // rotation f0.x, width u.x, height u.y; table: pixels
const uint DRAW_ALIAS = 9u;          // table: the alias table
// The glTF material (pbr_sample): (base colour, metallic) f0, (specular colour, roughness) f1,
// (n, transmission) f2, (wo, specular) f3, ior f4.x, flags u.x. x = 0 marks a draw that gave
// no direction or a Dirac lobe.
const uint DRAW_PBR = 10u;

struct DrawParams {
    vec4 f[6];
    uvec4 u;
};

struct DrawPush {
    uint sampler_id;
    uint seed;
    uint count;
    uint table_size;
};

TP_NAMESPACE_END

#endif // TP_TESTS_DRAW_IDS_H
