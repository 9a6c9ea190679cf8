#include "scene/glb_container.h"

#include "util/error.h"

#include <cstdint>

namespace tp {
namespace {

constexpr uint32_t kMagic = 0x46546C67;     // "glTF"
constexpr uint32_t kChunkJson = 0x4E4F534A; // "JSON"
constexpr uint32_t kChunkBin = 0x004E4942;  // "BIN\0"

// GLB is little-endian whatever the host.
uint32_t read_u32(std::string_view b, size_t at) {
    return uint32_t(uint8_t(b[at])) | uint32_t(uint8_t(b[at + 1])) << 8 |
           uint32_t(uint8_t(b[at + 2])) << 16 | uint32_t(uint8_t(b[at + 3])) << 24;
}

} // namespace

bool is_glb(std::string_view bytes) {
    return bytes.size() >= 4 && read_u32(bytes, 0) == kMagic;
}

GlbChunks split_glb(const std::string& path, std::string_view bytes) {
    if (bytes.size() < 12)
        input_error("{}: GLB: the file has {} bytes, less than the 12-byte header", path,
                    bytes.size());
    if (!is_glb(bytes)) input_error("{}: GLB: the file does not start with the magic 'glTF'", path);
    const uint32_t version = read_u32(bytes, 4);
    if (version != 2)
        input_error("{}: GLB: header version is {}, twinpath reads version 2", path, version);
    const uint32_t length = read_u32(bytes, 8);
    if (length != bytes.size())
        input_error("{}: GLB: header length is {} bytes but the file has {}", path, length,
                    bytes.size());
    GlbChunks out;
    size_t at = 12;
    for (int chunk = 0; at < bytes.size(); ++chunk) {
        if (bytes.size() - at < 8)
            input_error("{}: GLB: chunk {} at byte {}: {} bytes left, less than a chunk header",
                        path, chunk, at, bytes.size() - at);
        const uint32_t size = read_u32(bytes, at), type = read_u32(bytes, at + 4);
        if (size > bytes.size() - at - 8)
            input_error("{}: GLB: chunk {} at byte {}: length {} runs past the end of the file",
                        path, chunk, at, size);
        const std::string_view data = bytes.substr(at + 8, size);
        if (chunk == 0) {
            if (type != kChunkJson)
                input_error("{}: GLB: chunk 0 must be the JSON chunk, its type is 0x{:08x}", path,
                            type);
            out.json = data;
        } else if (type == kChunkBin) {
            if (chunk != 1 || out.has_bin)
                input_error("{}: GLB: chunk {} is a BIN chunk; only chunk 1 may be", path, chunk);
            out.bin = data;
            out.has_bin = true;
        } else if (type == kChunkJson) {
            input_error("{}: GLB: chunk {} is a second JSON chunk", path, chunk);
        } // other chunk types are reserved for extensions and skipped (section 4.4.3.1)
        at += 8 + size_t(size);
    }
    if (out.json.data() == nullptr) input_error("{}: GLB: the file has no JSON chunk", path);
    return out;
}

} // namespace tp
