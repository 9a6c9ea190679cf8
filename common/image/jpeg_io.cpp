#include "image/jpeg_io.h"

#include "util/error.h"

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

// After <cstdio>: jpeglib.h uses FILE and size_t without including their headers.
#include <jerror.h>
#include <jpeglib.h>

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "the JPEG reader decodes rows straight into texel words, R in the low byte");

namespace tp {
namespace {

// libjpeg's default error handler ends the process; this one keeps the message and returns
// to the setjmp in decode (libjpeg's documented way out of a failed read, example.c).
struct JpegErrors {
    jpeg_error_mgr mgr;
    std::jmp_buf jump;
    char text[JMSG_LENGTH_MAX];
};

[[noreturn]] void on_jpeg_error(j_common_ptr c) {
    auto* e = reinterpret_cast<JpegErrors*>(c->err);
    (*c->err->format_message)(c, e->text);
    std::longjmp(e->jump, 1);
}

// Warnings (level -1) about damaged data let the read go on; a premature end of the data would
// leave grey rows in the image, so it is an error. Trace messages (level >= 0) are ignored.
void on_jpeg_message(j_common_ptr c, int level) {
    if (level < 0 && c->err->msg_code == JWRN_JPEG_EOF) on_jpeg_error(c);
}

// Frees libjpeg's state however the read ends.
struct JpegRead {
    jpeg_decompress_struct cinfo{};
    bool created = false;
    ~JpegRead() {
        if (created) jpeg_destroy_decompress(&cinfo);
    }
};

// Decodes `bytes`, or `file` when it is not null.
Texture decode(std::string_view bytes, std::FILE* file, const std::string& what) {
    JpegErrors errors;
    JpegRead r;
    r.cinfo.err = jpeg_std_error(&errors.mgr);
    errors.mgr.error_exit = on_jpeg_error;
    errors.mgr.emit_message = on_jpeg_message;
    // Declared before setjmp: a longjmp back here leaves it as last stored (it escapes into
    // the calls below, so it lives in memory), and its destructor runs when the error is thrown.
    std::vector<uint32_t> words;
    if (setjmp(errors.jump))
        input_error("{}: not a JPEG image libjpeg decodes: {}", what, errors.text);
    jpeg_create_decompress(&r.cinfo);
    r.created = true;
    if (file)
        jpeg_stdio_src(&r.cinfo, file);
    else
        jpeg_mem_src(&r.cinfo, reinterpret_cast<const unsigned char*>(bytes.data()),
                     static_cast<unsigned long>(bytes.size()));
    jpeg_read_header(&r.cinfo, TRUE);
    if (r.cinfo.jpeg_color_space == JCS_CMYK || r.cinfo.jpeg_color_space == JCS_YCCK)
        input_error("{}: a CMYK JPEG image: twinpath reads greyscale, YCbCr and RGB JPEG", what);
    // libjpeg-turbo's RGBA output (alpha 255) is the layout of an 8-bit texel word.
    r.cinfo.out_color_space = JCS_EXT_RGBA;
    jpeg_start_decompress(&r.cinfo);
    const uint32_t width = r.cinfo.output_width, height = r.cinfo.output_height;
    if (r.cinfo.output_components != 4)
        input_error("{}: libjpeg gave {} components per pixel", what, r.cinfo.output_components);
    words = texel_storage(width, height, TEXEL_RGBA8, what);
    while (r.cinfo.output_scanline < height) {
        JSAMPROW row =
            reinterpret_cast<JSAMPROW>(words.data() + size_t(r.cinfo.output_scanline) * width);
        jpeg_read_scanlines(&r.cinfo, &row, 1);
    }
    // Not jpeg_finish_decompress: what follows the last scanline (up to the EOI marker) does
    // not change the texels, and a file cut short after them is still a complete image.
    Texture t;
    t.width = width;
    t.height = height;
    t.format = TEXEL_RGBA8;
    t.words = TexelWords(std::move(words));
    return t;
}

} // namespace

Texture decode_jpeg(std::string_view bytes, const std::string& what) {
    if (bytes.empty()) input_error("{}: no JPEG data", what);
    return decode(bytes, nullptr, what);
}

Texture read_jpeg(const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) input_error("{}: cannot open the file: {}", path, std::strerror(errno));
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> close(f, std::fclose);
    return decode({}, f, path);
}

} // namespace tp
