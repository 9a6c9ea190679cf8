// An image texture or environment map in memory, texels as the engines read them
// (shared/types.h, TextureInfo): 8-bit and 16-bit images keep their integer values, sRGB-encoded
// or not (how a texture slot reads them decides, shared/texture.h), float images their floats.
// Rows top to bottom.
#pragma once

#include "shared/types.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace tp {

// The texel words of an image, immutable once decoded and shared by the copies of its Texture:
// the scene description (scene/scene.h) and the flat scene the engines read (scene/flatten.h)
// hold one image once, not twice (an 8000 x 8000 8-bit image is 244 MiB).
class TexelWords {
  public:
    TexelWords() = default;
    explicit TexelWords(std::vector<uint32_t>&& words)
        : words_(std::make_shared<const std::vector<uint32_t>>(std::move(words))) {}

    size_t size() const { return words_ ? words_->size() : 0; }
    bool empty() const { return size() == 0; }
    const uint32_t* data() const { return words_ ? words_->data() : nullptr; }
    uint32_t operator[](size_t i) const { return (*words_)[i]; }
    const uint32_t* begin() const { return data(); }
    const uint32_t* end() const { return data() + size(); }

  private:
    std::shared_ptr<const std::vector<uint32_t>> words_;
};

struct Texture {
    std::string name;   // what the scene calls it: a JSON texture's key, a file, a glTF image
    std::string source; // where its texels came from (a file, a glTF image field), for messages
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t format = TEXEL_RGBA32F; // TEXEL_*
    TexelWords words;                // words_per_texel(format) per texel

    size_t texel_count() const { return size_t(width) * height; }
    // Texel i's channels as stored (shared/texture.h, texel_channels_value decodes them).
    uvec4 channels(size_t i) const;
    // Texel i as stored: integer formats as values in [0, 1], not decoded.
    vec4 raw(size_t i) const;
    // Texel i in linear values: sRGB-decoded where `srgb` and the format is an integer one.
    vec4 linear(size_t i, bool srgb) const;
    // The mean linear RGB over all texels.
    vec3 mean_linear(bool srgb) const;
    // Bytes the texels take.
    size_t bytes() const { return words.size() * sizeof(uint32_t); }
    // "'name' (file, 4096x4096)" for messages: the name, where it came from when that differs,
    // and the size.
    std::string describe() const;
};

uint32_t words_per_texel(uint32_t format);

// The channels of texel i of words in `format`: 8-bit R, G, B, A (R in the low byte of its
// word), 16-bit R, G, B, A (R | G << 16, B | A << 16), or the bits of four floats. The same
// uvec4 as the GPU's texel fetch from the image (vulkan_rt/render_loop/scene_images.h).
inline uvec4 words_texel_channels(const uint32_t* w, uint32_t format, size_t i) {
    if (format == TEXEL_RGBA8)
        return uvec4(w[i] & 0xFFu, (w[i] >> 8) & 0xFFu, (w[i] >> 16) & 0xFFu, w[i] >> 24);
    if (format == TEXEL_RGBA16)
        return uvec4(w[2 * i] & 0xFFFFu, w[2 * i] >> 16, w[2 * i + 1] & 0xFFFFu,
                     w[2 * i + 1] >> 16);
    return uvec4(w[4 * i], w[4 * i + 1], w[4 * i + 2], w[4 * i + 3]);
}

// The words of a width x height image in `format`, zero, for a decoder to fill in place. Throws
// InputError naming `what` when the image has more texels than a 32-bit texel index reaches
// (shared/texture.h: the engines index texels as row * width + column in 32 bits).
std::vector<uint32_t> texel_storage(uint32_t width, uint32_t height, uint32_t format,
                                    const std::string& what);

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
