#include "image/texture.h"

#include "shared/texture.h"

#include <cstring>

namespace tp {

uint32_t words_per_texel(uint32_t format) {
    return format == TEXEL_RGBA8 ? 1u : format == TEXEL_RGBA16 ? 2u : 4u;
}

vec4 Texture::raw(size_t i) const {
    if (format == TEXEL_RGBA8) return unpack_rgba8(words[i]);
    if (format == TEXEL_RGBA16) return unpack_rgba16(words[2 * i], words[2 * i + 1]);
    vec4 c;
    std::memcpy(&c, &words[4 * i], sizeof c);
    return c;
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

namespace {

// Channel k of a texel with n interleaved channels: grey images repeat their one channel, and
// an image without alpha is opaque.
template <typename T>
T channel(const T* texel, uint32_t n, uint32_t k, T opaque) {
    if (k == 3) return n == 2 || n >= 4 ? texel[n == 2 ? 1 : 3] : opaque;
    return n <= 2 ? texel[0] : texel[k];
}

Texture empty_texture(uint32_t width, uint32_t height, uint32_t format) {
    Texture t;
    t.width = width;
    t.height = height;
    t.format = format;
    t.words.resize(t.texel_count() * words_per_texel(format));
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
    Texture t = empty_texture(width, height, TEXEL_RGBA8);
    for (size_t i = 0; i < t.texel_count(); ++i) {
        const uint8_t* p = samples + i * channels;
        uint32_t w = 0;
        for (uint32_t k = 0; k < 4; ++k) w |= uint32_t(channel<uint8_t>(p, channels, k, 255)) << (8 * k);
        t.words[i] = w;
    }
    return t;
}

Texture texture_from_rgba16(uint32_t width, uint32_t height, uint32_t channels,
                            const uint16_t* samples) {
    Texture t = empty_texture(width, height, TEXEL_RGBA16);
    for (size_t i = 0; i < t.texel_count(); ++i) {
        const uint16_t* p = samples + i * channels;
        t.words[2 * i] = uint32_t(channel<uint16_t>(p, channels, 0, 65535)) |
                         uint32_t(channel<uint16_t>(p, channels, 1, 65535)) << 16;
        t.words[2 * i + 1] = uint32_t(channel<uint16_t>(p, channels, 2, 65535)) |
                             uint32_t(channel<uint16_t>(p, channels, 3, 65535)) << 16;
    }
    return t;
}

Texture texture_from_float(uint32_t width, uint32_t height, uint32_t channels,
                           const float* samples) {
    Texture t = empty_texture(width, height, TEXEL_RGBA32F);
    for (size_t i = 0; i < t.texel_count(); ++i) {
        const float* p = samples + i * channels;
        for (uint32_t k = 0; k < 4; ++k) {
            const float v = channel<float>(p, channels, k, 1.0f);
            std::memcpy(&t.words[4 * i + k], &v, sizeof v);
        }
    }
    return t;
}

} // namespace tp
