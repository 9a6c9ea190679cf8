#include "scene/gltf_resources.h"

#include "image/jpeg_io.h"
#include "image/png_io.h"
#include "image/texture_io.h"
#include "scene/text_parse.h"
#include "util/error.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace fs = std::filesystem;

namespace tp {
namespace {

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

DataUri decode_data_uri(const GltfDocument& d, const std::string& uri, const std::string& field) {
    std::optional<DataUri> data = parse_data_uri(uri);
    if (!data || data->bytes.empty())
        input_error("{}: {}: a data: URI that is not base64 (data:<type>;base64,<data>) or is "
                    "empty",
                    d.path, field);
    return std::move(*data);
}

// The first bytes of a file, enough to tell its image format (texture_io.h).
std::string file_head(const fs::path& file) {
    std::string head(16, '\0');
    std::ifstream in(file, std::ios::binary);
    in.read(head.data(), std::streamsize(head.size()));
    head.resize(size_t(std::max<std::streamsize>(in.gcount(), 0)));
    return head;
}

// The format a glTF mimeType names when it is not one twinpath decodes.
std::string undecoded_mime_type(const std::string& mime) {
    if (mime.empty() || mime == "image/png" || mime == "image/jpeg") return "";
    return mime;
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
                    ? decode_data_uri(doc, b.uri, field + ".uri").bytes
                    : read_file(doc, uri_file(doc, b.uri, field + ".uri"), field + ".uri"));
            data = owned_.back();
        }
        if (data.size() < b.byte_length)
            input_error("{}: {}.byteLength: {} bytes, but its data has only {}", doc.path, field,
                        b.byte_length, data.size());
        buffers_.push_back(data);
    }
}

std::optional<DataUri> parse_data_uri(std::string_view uri) {
    if (uri.substr(0, 5) != "data:") return std::nullopt;
    const size_t comma = uri.find(',');
    if (comma == std::string_view::npos) return std::nullopt;
    const std::string_view header = uri.substr(5, comma - 5);
    const std::string_view base64_tag = ";base64";
    if (header.size() < base64_tag.size() ||
        header.substr(header.size() - base64_tag.size()) != base64_tag)
        return std::nullopt;
    DataUri out;
    out.media_type = std::string(header.substr(0, header.find(';')));
    // RFC 4648's alphabet; '=' padding only at the end.
    std::array<int, 256> value;
    value.fill(-1);
    const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (int i = 0; i < 64; ++i) value[static_cast<unsigned char>(alphabet[i])] = i;
    std::string_view payload = uri.substr(comma + 1);
    while (!payload.empty() && payload.back() == '=') payload.remove_suffix(1);
    if (uri.size() - comma - 1 - payload.size() > 2 || payload.size() % 4 == 1) return std::nullopt;
    out.bytes.reserve(payload.size() / 4 * 3 + 2);
    uint32_t bits = 0;
    int count = 0;
    for (char c : payload) {
        const int v = value[static_cast<unsigned char>(c)];
        if (v < 0) return std::nullopt;
        bits = bits << 6 | uint32_t(v);
        if (++count == 4) {
            out.bytes += char(bits >> 16);
            out.bytes += char(bits >> 8 & 0xFF);
            out.bytes += char(bits & 0xFF);
            bits = 0;
            count = 0;
        }
    }
    if (count == 2) out.bytes += char(bits >> 4);
    if (count == 3) {
        out.bytes += char(bits >> 10);
        out.bytes += char(bits >> 2 & 0xFF);
    }
    return out;
}

std::string_view GltfResources::view_bytes(uint32_t view) const {
    const GltfBufferView& v = doc_.buffer_views[view];
    return buffers_[v.buffer].substr(v.byte_offset, v.byte_length);
}

std::optional<Texture> GltfResources::decode_image(uint32_t image, const std::string& used_by,
                                                   std::string& undecoded) const {
    const GltfImage& img = doc_.images[image];
    const std::string field = fmt::format("images[{}]", image);
    const std::string where = fmt::format("{}: {} (used by {})", doc_.path, field, used_by);
    // The bytes of a buffer view or a data: URI; a file is decoded as it is read.
    std::string owned, mime = img.mime_type;
    std::string_view bytes;
    std::string data_field; // where the bytes of a buffer view or a data: URI are, for errors
    fs::path file;
    if (img.buffer_view != GLTF_NONE) {
        bytes = view_bytes(uint32_t(img.buffer_view));
        data_field = fmt::format("bufferViews[{}]", img.buffer_view);
    } else if (is_data_uri(img.uri)) {
        data_field = field + ".uri";
        DataUri data = decode_data_uri(doc_, img.uri, field + ".uri");
        if (mime.empty()) mime = data.media_type;
        owned = std::move(data.bytes);
        bytes = owned;
    } else {
        file = uri_file(doc_, img.uri, field + ".uri");
    }
    const std::string head = file.empty() ? std::string(bytes.substr(0, 16)) : file_head(file);
    if (file.empty() && (bytes.empty() || bytes.size() > size_t(INT_MAX)))
        input_error("{}: {} bytes of image data", where, bytes.size());
    Texture t;
    try {
        switch (image_format_of(head)) {
        case ImageFormat::png:
            t = file.empty() ? decode_png(bytes, data_field) : read_png(file.string());
            break;
        case ImageFormat::jpeg:
            t = file.empty() ? decode_jpeg(bytes, data_field) : read_jpeg(file.string());
            break;
        default:
            undecoded = undecoded_format_name(head);
            if (undecoded.empty()) undecoded = undecoded_mime_type(mime);
            if (!undecoded.empty()) return std::nullopt;
            input_error("{}", "not a PNG or JPEG image (glTF's image formats)");
        }
    } catch (const InputError& e) {
        input_error("{}: cannot decode the image: {}", where, e.what());
    }
    t.name = img.uri.empty() || is_data_uri(img.uri) ? field : clip(img.uri);
    t.source = file.empty() ? fmt::format("{}: {}", doc_.path, field) : file.string();
    return t;
}

} // namespace tp
