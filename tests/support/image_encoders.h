// Test images written by the reference encoders, libpng's and libjpeg's, from samples given by
// hand: any PNG colour type, bit depth, palette and tRNS, and JPEG (grey, RGB, CMYK) at quality
// 100 without chroma subsampling. Header-only: a test that includes it links PNG::PNG and
// JPEG::JPEG.
#pragma once

#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include <jpeglib.h>
#include <png.h>

namespace tp::test {

struct PngSpec {
    uint32_t width, height;
    int color; // PNG_COLOR_TYPE_*
    int depth; // bits per sample (per index for a palette)
    bool interlaced = false;
    std::vector<png_color> palette = {};
    std::vector<uint8_t> trns = {}; // palette alphas; non-empty for grey/RGB: trns_value is
    png_color_16 trns_value = {};   // the transparent colour
    bool fast = false;              // zlib level 1 and no row filters (large flat images)
};

namespace detail {
inline void append_png_bytes(png_structp png, png_bytep data, png_size_t n) {
    static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<char*>(data), n);
}
struct JpegErrors {
    jpeg_error_mgr mgr;
    std::jmp_buf jump;
};
} // namespace detail

// A PNG of `rows`, each row's bytes as PNG stores them (big-endian 16-bit samples, low depths
// packed from the high bits).
inline std::string encode_png(const PngSpec& s, std::vector<std::vector<uint8_t>> rows) {
    std::string out;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        throw std::runtime_error("libpng could not write the test image");
    }
    png_set_write_fn(png, &out, detail::append_png_bytes, nullptr);
    png_set_IHDR(png, info, s.width, s.height, s.depth, s.color,
                 s.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (s.fast) {
        png_set_compression_level(png, 1);
        png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
    }
    if (!s.palette.empty()) png_set_PLTE(png, info, s.palette.data(), int(s.palette.size()));
    if (!s.trns.empty()) {
        png_color_16 value = s.trns_value;
        const bool palette = s.color == PNG_COLOR_TYPE_PALETTE;
        png_set_tRNS(png, info, palette ? s.trns.data() : nullptr, palette ? int(s.trns.size()) : 0,
                     &value);
    }
    png_write_info(png, info);
    std::vector<png_bytep> ptrs;
    for (auto& r : rows) ptrs.push_back(r.data());
    png_write_image(png, ptrs.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return out;
}

// A JPEG of `samples` (width x height x components; 1: grey, 3: RGB, 4: CMYK).
inline std::string encode_jpeg(uint32_t width, uint32_t height, int components,
                               const std::vector<uint8_t>& samples) {
    jpeg_compress_struct c{};
    detail::JpegErrors errors;
    c.err = jpeg_std_error(&errors.mgr);
    errors.mgr.error_exit = [](j_common_ptr p) {
        std::longjmp(reinterpret_cast<detail::JpegErrors*>(p->err)->jump, 1);
    };
    unsigned char* out = nullptr;
    unsigned long size = 0;
    if (setjmp(errors.jump)) {
        jpeg_destroy_compress(&c);
        throw std::runtime_error("libjpeg could not write the test image");
    }
    jpeg_create_compress(&c);
    jpeg_mem_dest(&c, &out, &size);
    c.image_width = width;
    c.image_height = height;
    c.input_components = components;
    c.in_color_space = components == 1 ? JCS_GRAYSCALE : components == 3 ? JCS_RGB : JCS_CMYK;
    jpeg_set_defaults(&c);
    jpeg_set_quality(&c, 100, TRUE);
    for (int i = 0; i < c.num_components; ++i)
        c.comp_info[i].h_samp_factor = c.comp_info[i].v_samp_factor = 1;
    jpeg_start_compress(&c, TRUE);
    while (c.next_scanline < height) {
        JSAMPROW row = const_cast<JSAMPROW>(samples.data() +
                                            size_t(c.next_scanline) * width * size_t(components));
        jpeg_write_scanlines(&c, &row, 1);
    }
    jpeg_finish_compress(&c);
    jpeg_destroy_compress(&c);
    std::string bytes(reinterpret_cast<char*>(out), size);
    std::free(out);
    return bytes;
}

} // namespace tp::test
