// Texture addressing shared by both engines: bilinear filtering of an RGB texel array and the
// latitude-longitude parameterisation of environment maps. The engines fetch the four texels
// themselves (a buffer in GLSL, a vector in C++) and blend them with texture_bilerp.
//
// Image coordinates (s, t) are in [0, 1]^2 with t = 0 at the top row, texel (i, j) centred at
// ((i + 0.5) / w, (j + 0.5) / h). OBJ uv has v = 0 at the bottom: use uv_to_image.
#ifndef TP_SHARED_TEXTURE_H
#define TP_SHARED_TEXTURE_H

#include "math.h"

TP_NAMESPACE_BEGIN

struct TexelFootprint {
    uint i00; // texel indices (row * width + column) relative to the texture's first texel
    uint i10;
    uint i01;
    uint i11;
    vec2 f; // blend weights along s and t
};

inline vec2 uv_to_image(vec2 uv) {
    return vec2(uv.x, 1.0f - uv.y);
}

// Wraps the integer-valued float i into [0, n); exact for |i| < 2^24. GPUs divide with up to
// 2.5 ulp of error (Vulkan's bound for OpFDiv), so at a multiple of n the quotient can land
// just below an integer and floor() be one too small: the remainder is folded back into range.
inline uint wrap_texel(float i, uint n) {
    float fn = float(n);
    float r = i - fn * floor(i / fn);
    if (r >= fn) r -= fn;
    if (r < 0.0f) r += fn;
    return uint(r);
}

// Bilinear footprint with repeat addressing along s and, unless clamp_t, along t (an
// environment map clamps at the poles).
inline TexelFootprint texture_footprint(vec2 st, uint w, uint h, bool clamp_t) {
    float x = st.x * float(w) - 0.5f;
    float y = st.y * float(h) - 0.5f;
    float x0 = floor(x);
    float y0 = floor(y);
    TexelFootprint fp;
    fp.f = vec2(x - x0, y - y0);
    uint ix0 = wrap_texel(x0, w);
    uint ix1 = ix0 + 1u == w ? 0u : ix0 + 1u;
    uint iy0;
    uint iy1;
    if (clamp_t) {
        iy0 = uint(clamp(y0, 0.0f, float(h - 1u)));
        iy1 = uint(clamp(y0 + 1.0f, 0.0f, float(h - 1u)));
    } else {
        iy0 = wrap_texel(y0, h);
        iy1 = iy0 + 1u == h ? 0u : iy0 + 1u;
    }
    fp.i00 = iy0 * w + ix0;
    fp.i10 = iy0 * w + ix1;
    fp.i01 = iy1 * w + ix0;
    fp.i11 = iy1 * w + ix1;
    return fp;
}

inline vec3 texture_bilerp(vec3 c00, vec3 c10, vec3 c01, vec3 c11, vec2 f) {
    return mix(mix(c00, c10, f.x), mix(c01, c11, f.x), f.y);
}

// ---- latitude-longitude environment maps ----------------------------------------------------
// s = 0.5 + phi / (2 pi) with phi = atan2(x, -z), so the image centre looks down -Z;
// t = theta / pi with theta the angle from +Y (t = 0 is straight up).
inline vec3 latlong_to_direction(vec2 st) {
    float phi = (st.x - 0.5f) * TWO_PI;
    float theta = st.y * PI;
    float sin_theta = sin(theta);
    return vec3(sin_theta * sin(phi), cos(theta), -sin_theta * cos(phi));
}

inline vec2 direction_to_latlong(vec3 d) {
    // atan(0, 0) is undefined in GLSL: the poles get phi = 0.
    float phi = (d.x == 0.0f && d.z == 0.0f) ? 0.0f : atan(d.x, -d.z);
    float rho = length(vec2(d.x, d.z));
    // theta = atan(rho, y) rather than acos(y): acos loses precision near the poles, where y is
    // within a few float ulps of +-1 (at theta = 0.005 its error is 1e-3 relative, which the
    // 1 / sin(theta) of environment_map_pdf carries into the pdf).
    return vec2(0.5f + phi * INV_TWO_PI, atan(rho, d.y) * INV_PI);
}

// Right-handed rotation of d about +Y by angle (radians). A map rotated by a is looked up
// with rotate_y(d, -a).
inline vec3 rotate_y(vec3 d, float angle) {
    float c = cos(angle);
    float s = sin(angle);
    return vec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z);
}

TP_NAMESPACE_END

#endif // TP_SHARED_TEXTURE_H
