// Texture addressing shared by both engines: a sampler's wrap modes, nearest and bilinear
// footprints, the decoding of texel words, and the latitude-longitude parameterisation of
// environment maps. The engines fetch the texels themselves (the scene_texel hook of
// scene_access.h), decode them here and blend them with texture_bilerp after decoding, so that
// sRGB texels are filtered in linear space and both engines filter alike.
//
// Image coordinates (s, t) are in [0, 1]^2 with t = 0 at the top row, texel (i, j) centred at
// ((i + 0.5) / w, (j + 0.5) / h). OBJ uv has v = 0 at the bottom: use uv_to_image.
#ifndef TP_SHARED_TEXTURE_H
#define TP_SHARED_TEXTURE_H

#include "math.h"
#include "types.h"

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

// Texel index i (an integer-valued float) of an axis n texels long under a sampler's wrap mode
// (SLOT_WRAP_*, types.h; glTF's REPEAT, CLAMP_TO_EDGE and MIRRORED_REPEAT: a mirrored axis
// repeats with period 2n, its second half reversed).
inline uint wrap_texel_mode(float i, uint n, uint mode) {
    if (mode == SLOT_WRAP_CLAMP) return uint(clamp(i, 0.0f, float(n - 1u)));
    if (mode == SLOT_WRAP_MIRROR) {
        uint r = wrap_texel(i, 2u * n);
        return r < n ? r : 2u * n - 1u - r;
    }
    return wrap_texel(i, n);
}

// Bilinear footprint under the wrap modes of s and t.
inline TexelFootprint texture_footprint(vec2 st, uint w, uint h, uint wrap_s, uint wrap_t) {
    float x = st.x * float(w) - 0.5f;
    float y = st.y * float(h) - 0.5f;
    float x0 = floor(x);
    float y0 = floor(y);
    TexelFootprint fp;
    fp.f = vec2(x - x0, y - y0);
    uint ix0 = wrap_texel_mode(x0, w, wrap_s);
    uint ix1 = wrap_texel_mode(x0 + 1.0f, w, wrap_s);
    uint iy0 = wrap_texel_mode(y0, h, wrap_t);
    uint iy1 = wrap_texel_mode(y0 + 1.0f, h, wrap_t);
    fp.i00 = iy0 * w + ix0;
    fp.i10 = iy0 * w + ix1;
    fp.i01 = iy1 * w + ix0;
    fp.i11 = iy1 * w + ix1;
    return fp;
}

// The texel that contains st (a sampler's NEAREST filter).
inline uint texture_nearest(vec2 st, uint w, uint h, uint wrap_s, uint wrap_t) {
    return wrap_texel_mode(floor(st.y * float(h)), h, wrap_t) * w +
           wrap_texel_mode(floor(st.x * float(w)), w, wrap_s);
}

inline vec4 texture_bilerp(vec4 c00, vec4 c10, vec4 c01, vec4 c11, vec2 f) {
    return mix(mix(c00, c10, f.x), mix(c01, c11, f.x), f.y);
}

// ---- texel decoding --------------------------------------------------------------------------
// A texel's channels as its image stores them (TextureInfo::format): 8- or 16-bit integers, or
// the bits of four floats, as both engines fetch them (the CPU from the texel words, the GPU
// from an integer image, vulkan_rt/render_loop/scene_images.h), to values: integers over their
// maximum (a product with 1/255 rather than a division or GLSL's unpackUnorm4x8, whose rounding
// a device may choose, so that both engines decode the same floats), float bits as floats.
inline vec4 texel_channels_value(uvec4 c, uint format) {
    if (format == TEXEL_RGBA8)
        return vec4(float(c.x), float(c.y), float(c.z), float(c.w)) * (1.0f / 255.0f);
    if (format == TEXEL_RGBA16)
        return vec4(float(c.x), float(c.y), float(c.z), float(c.w)) * (1.0f / 65535.0f);
    return vec4(uintBitsToFloat(c.x), uintBitsToFloat(c.y), uintBitsToFloat(c.z),
                uintBitsToFloat(c.w));
}

// An 8-bit texel word (TEXEL_RGBA8, R in the low byte) as four values in [0, 1].
inline vec4 unpack_rgba8(uint w) {
    return texel_channels_value(uvec4(w & 0xFFu, (w >> 8u) & 0xFFu, (w >> 16u) & 0xFFu, w >> 24u),
                                TEXEL_RGBA8);
}

// A 16-bit texel's two words (TEXEL_RGBA16) as four values in [0, 1].
inline vec4 unpack_rgba16(uint rg, uint ba) {
    return texel_channels_value(uvec4(rg & 0xFFFFu, rg >> 16u, ba & 0xFFFFu, ba >> 16u),
                                TEXEL_RGBA16);
}

// The sRGB transfer function's inverse (IEC 61966-2-1): encoded value to linear.
inline float srgb_to_linear(float c) {
    if (c <= 0.04045f) return c * (1.0f / 12.92f);
    return pow((c + 0.055f) * (1.0f / 1.055f), 2.4f);
}

inline vec4 srgb_to_linear4(vec4 c) {
    return vec4(srgb_to_linear(c.x), srgb_to_linear(c.y), srgb_to_linear(c.z), c.w);
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
