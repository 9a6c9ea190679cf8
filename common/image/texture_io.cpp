#include "image/texture_io.h"

#include "image/exr_io.h"
#include "image/jpeg_io.h"
#include "image/png_io.h"
#include "util/error.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#ifdef TWINPATH_WITH_OIIO
#include <OpenImageIO/imageio.h>
#endif

namespace tp {
namespace {

bool starts_with(std::string_view s, std::string_view prefix) {
    return s.substr(0, prefix.size()) == prefix;
}

// R, G, B (or Y, grey) and A where present, as float texels.
Texture from_exr(const std::string& path) {
    const ExrImage img = read_exr(path);
    const bool grey = !img.has("R") && img.has("Y");
    if (!grey)
        for (const char* c : {"R", "G", "B"})
            if (!img.has(c)) input_error("{}: texture has no {} channel (nor Y)", path, c);
    const std::vector<std::string> names =
        grey ? std::vector<std::string>{"Y"} : std::vector<std::string>{"R", "G", "B"};
    const uint32_t nc = uint32_t(names.size()) + (img.has("A") ? 1u : 0u);
    std::vector<const std::vector<float>*> ch;
    for (const std::string& n : names) ch.push_back(&img.channel(n));
    if (img.has("A")) ch.push_back(&img.channel("A"));
    std::vector<float> px(size_t(img.width) * img.height * nc);
    for (size_t i = 0; i < px.size() / nc; ++i)
        for (uint32_t k = 0; k < nc; ++k) px[i * nc + k] = (*ch[k])[i];
    // texture_from_float's channel counts: 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA.
    return texture_from_float(uint32_t(img.width), uint32_t(img.height), nc, px.data());
}

#ifdef TWINPATH_WITH_OIIO
Texture from_oiio(const std::string& path) {
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
        return texture_from_rgba8(w, h, nc, px.data());
    }
    if (spec.format.basetype == OIIO::TypeDesc::UINT16) {
        std::vector<uint16_t> px(n);
        if (!in->read_image(0, 0, 0, int(nc), OIIO::TypeDesc::UINT16, px.data()))
            input_error("{}: cannot read texture: {}", path, in->geterror());
        return texture_from_rgba16(w, h, nc, px.data());
    }
    std::vector<float> px(n);
    if (!in->read_image(0, 0, 0, int(nc), OIIO::TypeDesc::FLOAT, px.data()))
        input_error("{}: cannot read texture: {}", path, in->geterror());
    return texture_from_float(w, h, nc, px.data());
}
#endif

} // namespace

ImageFormat image_format_of(std::string_view head) {
    if (starts_with(head, "\x89PNG\r\n\x1a\n")) return ImageFormat::png;
    if (starts_with(head, "\xFF\xD8\xFF")) return ImageFormat::jpeg;
    if (starts_with(head, std::string_view("\x76\x2F\x31\x01", 4))) return ImageFormat::exr;
    return ImageFormat::other;
}

std::string undecoded_format_name(std::string_view head) {
    if (starts_with(head, "BM")) return "BMP";
    if (starts_with(head, "GIF87a") || starts_with(head, "GIF89a")) return "GIF";
    if (starts_with(head, "RIFF") && head.size() >= 12 && head.substr(8, 4) == "WEBP")
        return "WebP";
    if (starts_with(head, "\xABKTX 20\xBB")) return "KTX2";
    if (starts_with(head, "\xABKTX 11\xBB")) return "KTX";
    if (starts_with(head, "DDS ")) return "DDS";
    if (starts_with(head, std::string_view("II*\0", 4)) ||
        starts_with(head, std::string_view("MM\0*", 4)))
        return "TIFF";
    if (starts_with(head, "#?RADIANCE") || starts_with(head, "#?RGBE")) return "Radiance HDR";
    if (starts_with(head, "sB")) return "Basis Universal";
    return "";
}

Texture load_texture(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) input_error("{}: texture file does not exist", path);
    std::string head(16, '\0');
    {
        std::ifstream in(path, std::ios::binary);
        if (!in) input_error("{}: cannot open the texture file", path);
        in.read(head.data(), std::streamsize(head.size()));
        head.resize(size_t(in.gcount()));
    }
    Texture t;
    switch (image_format_of(head)) {
    case ImageFormat::png:
        t = read_png(path);
        break;
    case ImageFormat::jpeg:
        t = read_jpeg(path);
        break;
    case ImageFormat::exr:
        t = from_exr(path);
        break;
    case ImageFormat::other:
#ifdef TWINPATH_WITH_OIIO
        t = from_oiio(path);
#else
        input_error("{}: not a PNG, JPEG or OpenEXR file; this build has no OpenImageIO (the GPU "
                    "bundle) and reads textures only in those formats",
                    path);
#endif
        break;
    }
    if (t.format == TEXEL_RGBA32F)
        for (size_t i = 0; i < t.texel_count(); ++i) {
            const vec4 c = t.raw(i);
            if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z) ||
                !std::isfinite(c.w) || c.x < 0 || c.y < 0 || c.z < 0 || c.w < 0)
                input_error("{}: texture has negative or non-finite texels", path);
        }
    t.source = path;
    return t;
}

} // namespace tp
