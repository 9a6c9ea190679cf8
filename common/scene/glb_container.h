// The binary glTF container (glTF 2.0 specification, section 4.4 "GLB File Format
// Specification"): a 12-byte header (magic "glTF", version 2, total length), a JSON chunk and
// an optional BIN chunk that holds buffer 0. Every length is checked against the file before it
// is used.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace tp {

struct GlbChunks {
    std::string_view json; // the JSON chunk's text
    std::string_view bin;  // the BIN chunk's bytes (padding included); empty if there is none
    bool has_bin = false;
};

// True when `bytes` starts with the GLB magic "glTF".
bool is_glb(std::string_view bytes);

// The chunks of the GLB file `bytes` (views into it); InputError naming `path` when the header
// or a chunk is malformed.
GlbChunks split_glb(const std::string& path, std::string_view bytes);

} // namespace tp
