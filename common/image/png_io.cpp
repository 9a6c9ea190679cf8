#include "image/png_io.h"

#include "util/error.h"
#include "util/output_file.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "the PNG reader decodes rows straight into texel words, R in the low byte");

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

// libpng reports errors through these: the message is kept and control returns to the setjmp
// in decode (libpng's own way out of a failed read); warnings (an unknown or damaged ancillary
// chunk) do not stop the read and print nothing.
struct PngMessage {
    char text[256] = "";
};
void on_png_error(png_structp png, png_const_charp message) {
    auto* m = static_cast<PngMessage*>(png_get_error_ptr(png));
    std::snprintf(m->text, sizeof m->text, "%s", message);
    png_longjmp(png, 1);
}
void on_png_warning(png_structp, png_const_charp) {}

struct MemoryInput {
    const uint8_t* data;
    size_t size;
    size_t at;
};
void read_memory(png_structp png, png_bytep out, png_size_t n) {
    auto* in = static_cast<MemoryInput*>(png_get_io_ptr(png));
    if (n > in->size - in->at) png_error(png, "the data ends before the image does");
    std::memcpy(out, in->data + in->at, n);
    in->at += n;
}

// Frees libpng's state however the read ends.
struct PngRead {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ~PngRead() { png_destroy_read_struct(&png, &info, nullptr); }
};

// Decodes from `memory`, or from `file` when memory is null.
Texture decode(MemoryInput* memory, std::FILE* file, const std::string& what) {
    PngMessage message;
    PngRead r;
    r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &message, on_png_error, on_png_warning);
    if (r.png) r.info = png_create_info_struct(r.png);
    if (!r.png || !r.info) runtime_error("{}: libpng cannot start a read (out of memory)", what);
    // Declared before setjmp: a longjmp back here leaves them as they were last stored (they
    // escape into libpng's calls, so they live in memory), and the guard frees them.
    std::vector<uint32_t> words;
    std::vector<png_bytep> rows;
    if (setjmp(png_jmpbuf(r.png))) input_error("{}: not a valid PNG image: {}", what, message.text);
    if (memory)
        png_set_read_fn(r.png, memory, read_memory);
    else
        png_init_io(r.png, file);
    // The texel count is checked below (texel_storage); libpng's own limit is 10^6 per side.
    png_set_user_limits(r.png, 0x7fffffffu, 0x7fffffffu);
    png_read_info(r.png, r.info);
    png_uint_32 width = 0, height = 0;
    int depth = 0, color = 0, interlace = 0;
    png_get_IHDR(r.png, r.info, &width, &height, &depth, &color, &interlace, nullptr, nullptr);
    // Every image becomes RGBA of its depth (8 bits for 1, 2 and 4), little-endian 16-bit
    // samples: the layout of the texel words.
    if (color == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(r.png);
    if (color == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(r.png);
    if (png_get_valid(r.png, r.info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(r.png);
    if (color == PNG_COLOR_TYPE_GRAY || color == PNG_COLOR_TYPE_GRAY_ALPHA)
        png_set_gray_to_rgb(r.png);
    png_set_filler(r.png, 0xFFFF, PNG_FILLER_AFTER); // opaque alpha where there is none
    if (depth == 16) png_set_swap(r.png);
    png_set_interlace_handling(r.png);
    png_read_update_info(r.png, r.info);
    const uint32_t format = depth == 16 ? TEXEL_RGBA16 : TEXEL_RGBA8;
    const size_t row_bytes = size_t(width) * words_per_texel(format) * sizeof(uint32_t);
    if (png_get_channels(r.png, r.info) != 4 || png_get_rowbytes(r.png, r.info) != row_bytes)
        input_error("{}: libpng gave {} channels of {} bytes per row for a {}x{} image", what,
                    png_get_channels(r.png, r.info), png_get_rowbytes(r.png, r.info), width,
                    height);
    words = texel_storage(width, height, format, what);
    rows.resize(height);
    for (png_uint_32 y = 0; y < height; ++y)
        rows[y] = reinterpret_cast<png_bytep>(words.data()) + y * row_bytes;
    png_read_image(r.png, rows.data());
    // The rest of the file (chunks after the image data) is not read: the texels are complete.
    Texture t;
    t.width = width;
    t.height = height;
    t.format = format;
    t.words = TexelWords(std::move(words));
    return t;
}

} // namespace

Texture decode_png(std::string_view bytes, const std::string& what) {
    MemoryInput in{reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), 0};
    return decode(&in, nullptr, what);
}

Texture read_png(const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) input_error("{}: cannot open the file: {}", path, std::strerror(errno));
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> close(f, std::fclose);
    return decode(nullptr, f, path);
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
