#include "image/texture_io.h"

#include "image/exr_io.h"
#include "image/png_io.h"
#include "util/error.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#ifdef TWINPATH_WITH_OIIO
#include <OpenImageIO/imageio.h>
#endif

namespace tp {
#ifndef TWINPATH_WITH_OIIO
namespace {

Texture from_exr(const std::string& path) {
    const ExrImage img = read_exr(path);
    for (const char* c : {"R", "G", "B"})
        if (!img.has(c)) input_error("{}: texture has no {} channel", path, c);
    const auto &r = img.channel("R"), &g = img.channel("G"), &b = img.channel("B");
    std::vector<float> rgb(size_t(img.width) * img.height * 3);
    for (size_t i = 0; i < rgb.size() / 3; ++i) {
        rgb[3 * i] = r[i];
        rgb[3 * i + 1] = g[i];
        rgb[3 * i + 2] = b[i];
    }
    return texture_from_float(uint32_t(img.width), uint32_t(img.height), 3, rgb.data());
}

} // namespace
#endif

Texture load_texture(const std::string& path) {
    if (!std::filesystem::exists(path)) input_error("{}: texture file does not exist", path);
    Texture t;
#ifdef TWINPATH_WITH_OIIO
    auto in = OIIO::ImageInput::open(path);
    if (!in) input_error("{}: cannot read texture: {}", path, OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0) input_error("{}: texture has no pixels", path);
    const uint32_t w = uint32_t(spec.width), h = uint32_t(spec.height);
    const uint32_t nc = uint32_t(std::min(spec.nchannels, 4));
    const size_t n = size_t(w) * h * nc;
    // Integer images keep their values (a texture slot decides whether they are sRGB colour,
    // shared/texture.h); anything else is read as float.
    if (spec.format.basetype == OIIO::TypeDesc::UINT8) {
        std::vector<uint8_t> px(n);
        if (!in->read_image(0, 0, 0, int(nc), OIIO::TypeDesc::UINT8, px.data()))
            input_error("{}: cannot read texture: {}", path, in->geterror());
        t = texture_from_rgba8(w, h, nc, px.data());
    } else if (spec.format.basetype == OIIO::TypeDesc::UINT16) {
        std::vector<uint16_t> px(n);
        if (!in->read_image(0, 0, 0, int(nc), OIIO::TypeDesc::UINT16, px.data()))
            input_error("{}: cannot read texture: {}", path, in->geterror());
        t = texture_from_rgba16(w, h, nc, px.data());
    } else {
        std::vector<float> px(n);
        if (!in->read_image(0, 0, 0, int(nc), OIIO::TypeDesc::FLOAT, px.data()))
            input_error("{}: cannot read texture: {}", path, in->geterror());
        t = texture_from_float(w, h, nc, px.data());
    }
#else
    const std::string ext = std::filesystem::path(path).extension().string();
    if (ext != ".exr" && ext != ".EXR")
        input_error("{}: this build has no OpenImageIO (gpu-bundle) and reads textures only "
                    "from OpenEXR files",
                    path);
    t = from_exr(path);
#endif
    if (t.format == TEXEL_RGBA32F)
        for (size_t i = 0; i < t.texel_count(); ++i) {
            const vec4 c = t.raw(i);
            if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z) ||
                !std::isfinite(c.w) || c.x < 0 || c.y < 0 || c.z < 0 || c.w < 0)
                input_error("{}: texture has negative or non-finite texels", path);
        }
    return t;
}

} // namespace tp
