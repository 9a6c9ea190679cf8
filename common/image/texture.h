// An image texture or environment map in memory, texels as the engines read them
// (shared/types.h, TextureInfo): 8-bit and 16-bit images keep their integer values, sRGB-encoded
// or not (how a texture slot reads them decides, shared/texture.h), float images their floats.
// Rows top to bottom.
#pragma once

#include "shared/types.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tp {

struct Texture {
    std::string name;
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t format = TEXEL_RGBA32F; // TEXEL_*
    std::vector<uint32_t> words;     // words_per_texel(format) per texel

    size_t texel_count() const { return size_t(width) * height; }
    // Texel i as stored: integer formats as values in [0, 1], not decoded.
    vec4 raw(size_t i) const;
    // Texel i in linear values: sRGB-decoded where `srgb` and the format is an integer one.
    vec4 linear(size_t i, bool srgb) const;
    // The mean linear RGB over all texels.
    vec3 mean_linear(bool srgb) const;
    // Bytes the texels take.
    size_t bytes() const { return words.size() * sizeof(uint32_t); }
};

uint32_t words_per_texel(uint32_t format);

// A float image from linear RGB texels (alpha 1).
Texture texture_from_linear_rgb(uint32_t width, uint32_t height, const std::vector<vec3>& texels);

// An 8-bit image from interleaved samples with `channels` per texel (1: grey, 2: grey + alpha,
// 3: RGB, 4: RGBA), as a decoder gives them.
Texture texture_from_rgba8(uint32_t width, uint32_t height, uint32_t channels,
                           const uint8_t* samples);

// A 16-bit image from interleaved samples (host byte order), channels as above.
Texture texture_from_rgba16(uint32_t width, uint32_t height, uint32_t channels,
                            const uint16_t* samples);

// A float image from interleaved samples, channels as above.
Texture texture_from_float(uint32_t width, uint32_t height, uint32_t channels,
                           const float* samples);

} // namespace tp
