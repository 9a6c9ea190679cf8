#include "scene/gltf_resources.h"

#include "image/png_io.h"
#include "scene/text_parse.h"
#include "util/error.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <climits>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace fs = std::filesystem;

namespace tp {
namespace {

// tinygltf's messages end in newlines; an error message is one line.
std::string one_line(std::string s) {
    for (char& c : s)
        if (c == '\n' || c == '\r') c = ' ';
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return clip(s);
}

bool is_data_uri(const std::string& uri) {
    return uri.rfind("data:", 0) == 0;
}

// A relative file path of `uri`, decoded, next to the asset. Anything with a scheme (http:,
// file:) or an absolute path is not read: an asset refers to its own files.
fs::path uri_file(const GltfDocument& d, const std::string& uri, const std::string& field) {
    const size_t colon = uri.find(':'), slash = uri.find('/');
    if ((colon != std::string::npos && (slash == std::string::npos || colon < slash)) ||
        uri.empty() || uri[0] == '/')
        input_error("{}: {}: '{}' is not a relative file path or a data: URI", d.path, field,
                    clip(uri));
    const fs::path file = fs::path(d.path).parent_path() / gltf_percent_decode(uri);
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))
        input_error("{}: {}: file '{}' does not exist", d.path, field, file.string());
    return file;
}

std::string read_file(const GltfDocument& d, const fs::path& file, const std::string& field) {
    std::ifstream in(file, std::ios::binary);
    std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (!in.good() && !in.eof())
        input_error("{}: {}: cannot read '{}'", d.path, field, file.string());
    return bytes;
}

std::string decode_data_uri(const GltfDocument& d, const std::string& uri,
                            const std::string& field) {
    std::vector<unsigned char> out;
    std::string mime;
    if (!tinygltf::DecodeDataURI(&out, mime, uri, 0, false))
        input_error("{}: {}: a data: URI that is not base64 of a type glTF allows "
                    "(application/octet-stream, application/gltf-buffer, image/png, "
                    "image/jpeg), or is empty",
                    d.path, field);
    return std::string(out.begin(), out.end());
}

} // namespace

std::string gltf_percent_decode(std::string_view uri) {
    auto hex = [](char c) {
        return c >= '0' && c <= '9'   ? c - '0'
               : c >= 'a' && c <= 'f' ? c - 'a' + 10
               : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                      : -1;
    };
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
            out += char(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

GltfResources::GltfResources(const GltfDocument& doc, std::string_view bin, bool has_bin)
    : doc_(doc) {
    owned_.reserve(doc.buffers.size());
    for (size_t i = 0; i < doc.buffers.size(); ++i) {
        const GltfBuffer& b = doc.buffers[i];
        const std::string field = fmt::format("buffers[{}]", i);
        std::string_view data;
        if (b.uri.empty()) { // buffer 0 of a .glb (gltf_document.h)
            if (!has_bin)
                input_error("{}: {}: has no uri and the GLB file has no BIN chunk", doc.path,
                            field);
            data = bin;
        } else {
            owned_.push_back(
                is_data_uri(b.uri)
                    ? decode_data_uri(doc, b.uri, field + ".uri")
                    : read_file(doc, uri_file(doc, b.uri, field + ".uri"), field + ".uri"));
            data = owned_.back();
        }
        if (data.size() < b.byte_length)
            input_error("{}: {}.byteLength: {} bytes, but its data has only {}", doc.path, field,
                        b.byte_length, data.size());
        buffers_.push_back(data);
    }
}

std::string_view GltfResources::view_bytes(uint32_t view) const {
    const GltfBufferView& v = doc_.buffer_views[view];
    return buffers_[v.buffer].substr(v.byte_offset, v.byte_length);
}

Texture GltfResources::decode_image(uint32_t image, const std::string& used_by) const {
    const GltfImage& img = doc_.images[image];
    const std::string field = fmt::format("images[{}]", image);
    std::string owned;
    std::string_view bytes;
    if (img.buffer_view != GLTF_NONE) {
        bytes = view_bytes(uint32_t(img.buffer_view));
    } else {
        owned = is_data_uri(img.uri)
                    ? decode_data_uri(doc_, img.uri, field + ".uri")
                    : read_file(doc_, uri_file(doc_, img.uri, field + ".uri"), field + ".uri");
        bytes = owned;
    }
    if (bytes.empty() || bytes.size() > size_t(INT_MAX))
        input_error("{}: {} (used by {}): {} bytes of image data", doc_.path, field, used_by,
                    bytes.size());
    tinygltf::Image decoded;
    std::string err, warn;
    if (!tinygltf::LoadImageData(&decoded, int(image), &err, &warn, 0, 0,
                                 reinterpret_cast<const unsigned char*>(bytes.data()),
                                 int(bytes.size()), nullptr))
        input_error("{}: {} (used by {}): cannot decode the image (PNG, JPEG, BMP or GIF): {}",
                    doc_.path, field, used_by, one_line(err));
    const size_t texels = size_t(decoded.width) * size_t(decoded.height);
    const size_t channels = size_t(decoded.component);
    const size_t bytes_per = decoded.bits == 16 ? 2 : 1;
    if (decoded.width <= 0 || decoded.height <= 0 || channels < 1 ||
        decoded.image.size() != texels * channels * bytes_per)
        input_error("{}: {} (used by {}): the decoder returned no usable pixels", doc_.path, field,
                    used_by);
    const uint32_t w = uint32_t(decoded.width), h = uint32_t(decoded.height);
    Texture t;
    if (bytes_per == 2) {
        // 16-bit samples are in the host's order.
        std::vector<uint16_t> px(texels * channels);
        std::memcpy(px.data(), decoded.image.data(), px.size() * 2);
        t = texture_from_rgba16(w, h, uint32_t(channels), px.data());
    } else {
        t = texture_from_rgba8(w, h, uint32_t(channels), decoded.image.data());
    }
    t.name = img.uri.empty() || is_data_uri(img.uri) ? field : clip(img.uri);
    return t;
}

} // namespace tp
