// Writes glTF 2.0 assets for the tests (docs/scene-format.md, "glTF 2.0"): a JSON document
// that the test builds, with helpers that append data to one binary buffer and describe it,
// written as .gltf (buffer in a .bin file or a data: URI) or .glb. Independent of the loader:
// it writes the format as the specification gives it.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace tp::test {

class GltfBuilder {
  public:
    using json = nlohmann::json;

    json doc;        // "asset" is set; the helpers append to the top-level arrays
    std::string bin; // buffer 0

    GltfBuilder();

    // Appends `bytes` (aligned to 4) as a new buffer view; returns its index.
    uint32_t view(const void* data, size_t bytes, uint32_t stride = 0);
    uint32_t accessor(uint32_t view, uint32_t component_type, size_t count, const std::string& type,
                      size_t byte_offset = 0);
    // Float VEC3 (with min and max, as the specification requires of POSITION), VEC2, and
    // UNSIGNED_INT indices.
    uint32_t vec3s(const std::vector<glm::vec3>& v);
    uint32_t vec2s(const std::vector<glm::vec2>& v);
    uint32_t indices(const std::vector<uint32_t>& i);
    // A mesh of one primitive; `attributes` as in the file ({"POSITION": 0, ...}).
    uint32_t mesh(const json& attributes, int indices = -1, int material = -1);
    uint32_t add(const char* array, const json& element); // appends to doc[array]
    // The default scene with these root nodes.
    void scene(const std::vector<uint32_t>& roots);

    // The .gltf text with buffer 0 at `bin_uri` (the caller writes the file there).
    std::string gltf_text(const std::string& bin_uri) const;
    // dir/name.gltf with the buffer in dir/name.bin, or embedded as a data: URI.
    std::string write_gltf(const std::string& dir, const std::string& name,
                           bool embed = false) const;
    std::string write_glb(const std::string& dir, const std::string& name) const;
    // The bytes of the .glb file (for tests that corrupt them).
    std::string glb_bytes() const;
};

std::string base64(const std::string& bytes);

// A unit cube's 12 triangles (24 vertices, 4 per face, counter-clockwise seen from outside).
struct CubeData {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> indices;
};
CubeData unit_cube();

} // namespace tp::test
