#include "image/texture.h"

#include "shared/texture.h"
#include "util/error.h"

#include <fmt/format.h>

#include <cstring>

namespace tp {

uint32_t words_per_texel(uint32_t format) {
    return format == TEXEL_RGBA8 ? 1u : format == TEXEL_RGBA16 ? 2u : 4u;
}

std::vector<uint32_t> texel_storage(uint32_t width, uint32_t height, uint32_t format,
                                    const std::string& what) {
    const uint64_t texels = uint64_t(width) * height;
    if (texels > uint64_t(UINT32_MAX))
        input_error("{}: a {}x{} image has more than 2^32 texels, more than the engines' 32-bit "
                    "texel index reaches",
                    what, width, height);
    return std::vector<uint32_t>(size_t(texels) * words_per_texel(format));
}

uvec4 Texture::channels(size_t i) const {
    return words_texel_channels(words.data(), format, i);
}

vec4 Texture::raw(size_t i) const {
    return texel_channels_value(channels(i), format);
}

vec4 Texture::linear(size_t i, bool srgb) const {
    const vec4 c = raw(i);
    return srgb && format != TEXEL_RGBA32F ? srgb_to_linear4(c) : c;
}

vec3 Texture::mean_linear(bool srgb) const {
    glm::dvec3 sum(0.0);
    for (size_t i = 0; i < texel_count(); ++i) sum += glm::dvec3(vec3(linear(i, srgb)));
    return texel_count() ? vec3(sum / double(texel_count())) : vec3(0.0f);
}

std::string Texture::describe() const {
    const std::string from = source.empty() || source == name ? "" : source + ", ";
    return fmt::format("'{}' ({}{}x{})", name, from, width, height);
}

namespace {

// Channel k of a texel with n interleaved channels: grey images repeat their one channel, and
// an image without alpha is opaque.
template <typename T>
T channel(const T* texel, uint32_t n, uint32_t k, T opaque) {
    if (k == 3) return n == 2 || n >= 4 ? texel[n == 2 ? 1 : 3] : opaque;
    return n <= 2 ? texel[0] : texel[k];
}

Texture texture_of(uint32_t width, uint32_t height, uint32_t format, std::vector<uint32_t>&& w) {
    Texture t;
    t.width = width;
    t.height = height;
    t.format = format;
    t.words = TexelWords(std::move(w));
    return t;
}

} // namespace

Texture texture_from_linear_rgb(uint32_t width, uint32_t height, const std::vector<vec3>& texels) {
    std::vector<float> rgb(texels.size() * 3);
    std::memcpy(rgb.data(), texels.data(), rgb.size() * sizeof(float));
    return texture_from_float(width, height, 3, rgb.data());
}

Texture texture_from_rgba8(uint32_t width, uint32_t height, uint32_t channels,
                           const uint8_t* samples) {
    std::vector<uint32_t> w = texel_storage(width, height, TEXEL_RGBA8, "an image");
    for (size_t i = 0; i < w.size(); ++i) {
        const uint8_t* p = samples + i * channels;
        uint32_t word = 0;
        for (uint32_t k = 0; k < 4; ++k)
            word |= uint32_t(channel<uint8_t>(p, channels, k, 255)) << (8 * k);
        w[i] = word;
    }
    return texture_of(width, height, TEXEL_RGBA8, std::move(w));
}

Texture texture_from_rgba16(uint32_t width, uint32_t height, uint32_t channels,
                            const uint16_t* samples) {
    std::vector<uint32_t> w = texel_storage(width, height, TEXEL_RGBA16, "an image");
    for (size_t i = 0; i < w.size() / 2; ++i) {
        const uint16_t* p = samples + i * channels;
        w[2 * i] = uint32_t(channel<uint16_t>(p, channels, 0, 65535)) |
                   uint32_t(channel<uint16_t>(p, channels, 1, 65535)) << 16;
        w[2 * i + 1] = uint32_t(channel<uint16_t>(p, channels, 2, 65535)) |
                       uint32_t(channel<uint16_t>(p, channels, 3, 65535)) << 16;
    }
    return texture_of(width, height, TEXEL_RGBA16, std::move(w));
}

Texture texture_from_float(uint32_t width, uint32_t height, uint32_t channels,
                           const float* samples) {
    std::vector<uint32_t> w = texel_storage(width, height, TEXEL_RGBA32F, "an image");
    for (size_t i = 0; i < w.size() / 4; ++i) {
        const float* p = samples + i * channels;
        for (uint32_t k = 0; k < 4; ++k) {
            const float v = channel<float>(p, channels, k, 1.0f);
            std::memcpy(&w[4 * i + k], &v, sizeof v);
        }
    }
    return texture_of(width, height, TEXEL_RGBA32F, std::move(w));
}

} // namespace tp
