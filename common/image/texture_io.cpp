#include "image/texture_io.h"

#include "image/exr_io.h"
#include "image/png_io.h"
#include "util/error.h"

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
    Texture t;
    t.width = uint32_t(img.width);
    t.height = uint32_t(img.height);
    t.texels.resize(size_t(t.width) * t.height);
    const auto &r = img.channel("R"), &g = img.channel("G"), &b = img.channel("B");
    for (size_t i = 0; i < t.texels.size(); ++i) t.texels[i] = vec3(r[i], g[i], b[i]);
    return t;
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
    std::vector<float> pixels(size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
        input_error("{}: cannot read texture: {}", path, in->geterror());
    const bool encoded = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                         spec.format.basetype == OIIO::TypeDesc::UINT16;
    t.width = uint32_t(spec.width);
    t.height = uint32_t(spec.height);
    t.texels.resize(size_t(t.width) * t.height);
    const int nc = spec.nchannels;
    for (size_t i = 0; i < t.texels.size(); ++i) {
        vec3 c;
        for (int k = 0; k < 3; ++k) c[k] = pixels[i * nc + std::min(k, nc - 1)];
        if (encoded)
            for (int k = 0; k < 3; ++k) c[k] = srgb_to_linear(c[k]);
        t.texels[i] = c;
    }
#else
    const std::string ext = std::filesystem::path(path).extension().string();
    if (ext != ".exr" && ext != ".EXR")
        input_error("{}: this build has no OpenImageIO (gpu-bundle) and reads textures only "
                    "from OpenEXR files",
                    path);
    t = from_exr(path);
#endif
    for (const vec3& c : t.texels)
        if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z) || c.x < 0 ||
            c.y < 0 || c.z < 0)
            input_error("{}: texture has negative or non-finite texels", path);
    return t;
}

} // namespace tp
