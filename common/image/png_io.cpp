#include "image/png_io.h"

#include "util/error.h"
#include "util/output_file.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace tp {

std::vector<uint8_t> tonemap_srgb8(const std::vector<float>& r, const std::vector<float>& g,
                                   const std::vector<float>& b, float exposure_stops) {
    const float scale = std::exp2(exposure_stops);
    std::vector<uint8_t> out(r.size() * 3);
    for (size_t i = 0; i < r.size(); ++i) {
        const uvec3 code = display_srgb8(vec3(r[i], g[i], b[i]), scale);
        for (int k = 0; k < 3; ++k) out[3 * i + k] = uint8_t(code[k]);
    }
    return out;
}

namespace {
void append_bytes(png_structp png, png_bytep data, png_size_t n) {
    static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<char*>(data), n);
}
void no_flush(png_structp) {}
} // namespace

void write_png(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb) {
    if (rgb.size() != size_t(width) * size_t(height) * 3)
        runtime_error("{}: {} bytes for a {}x{} RGB image", path, rgb.size(), width, height);
    // Encoded in memory, then written by write_output_file (util/output_file.h).
    std::string encoded;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        runtime_error("cannot write {}: libpng failed", path);
    }
    png_set_write_fn(png, &encoded, append_bytes, no_flush);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    for (int y = 0; y < height; ++y) png_write_row(png, rgb.data() + size_t(y) * size_t(width) * 3);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    write_output_file(path, encoded);
}

} // namespace tp
