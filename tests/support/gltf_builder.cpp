#include "support/gltf_builder.h"

#include <glm/common.hpp>

#include <fstream>
#include <stdexcept>

namespace tp::test {

namespace {

void put_u32(std::string& s, uint32_t v) {
    for (int i = 0; i < 4; ++i) s += char((v >> (8 * i)) & 0xFF);
}

void write_file(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out << bytes;
    if (!out) throw std::runtime_error("cannot write " + path);
}

} // namespace

std::string base64(const std::string& bytes) {
    static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 2]));
        out += k[(v >> 18) & 63];
        out += k[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? k[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? k[v & 63] : '=';
    }
    return out;
}

GltfBuilder::GltfBuilder() {
    doc["asset"] = {{"version", "2.0"}, {"generator", "twinpath tests"}};
}

uint32_t GltfBuilder::view(const void* data, size_t bytes, uint32_t stride) {
    while (bin.size() % 4 != 0) bin += '\0';
    json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}};
    if (stride != 0) v["byteStride"] = stride;
    bin.append(static_cast<const char*>(data), bytes);
    return add("bufferViews", v);
}

uint32_t GltfBuilder::accessor(uint32_t view, uint32_t component_type, size_t count,
                               const std::string& type, size_t byte_offset) {
    json a = {
        {"bufferView", view}, {"componentType", component_type}, {"count", count}, {"type", type}};
    if (byte_offset != 0) a["byteOffset"] = byte_offset;
    return add("accessors", a);
}

uint32_t GltfBuilder::vec3s(const std::vector<glm::vec3>& v) {
    const uint32_t a = accessor(view(v.data(), v.size() * 12), 5126, v.size(), "VEC3");
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : v) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    doc["accessors"][a]["min"] = {lo.x, lo.y, lo.z};
    doc["accessors"][a]["max"] = {hi.x, hi.y, hi.z};
    return a;
}

uint32_t GltfBuilder::vec2s(const std::vector<glm::vec2>& v) {
    return accessor(view(v.data(), v.size() * 8), 5126, v.size(), "VEC2");
}

uint32_t GltfBuilder::indices(const std::vector<uint32_t>& i) {
    return accessor(view(i.data(), i.size() * 4), 5125, i.size(), "SCALAR");
}

uint32_t GltfBuilder::mesh(const json& attributes, int indices, int material) {
    json p = {{"attributes", attributes}};
    if (indices >= 0) p["indices"] = indices;
    if (material >= 0) p["material"] = material;
    return add("meshes", {{"primitives", json::array({p})}});
}

uint32_t GltfBuilder::add(const char* array, const json& element) {
    if (!doc.contains(array)) doc[array] = json::array();
    doc[array].push_back(element);
    return uint32_t(doc[array].size() - 1);
}

void GltfBuilder::scene(const std::vector<uint32_t>& roots) {
    doc["scenes"] = json::array({{{"nodes", roots}}});
    doc["scene"] = 0;
}

std::string GltfBuilder::gltf_text(const std::string& bin_uri) const {
    json d = doc;
    if (!bin.empty()) d["buffers"] = json::array({{{"byteLength", bin.size()}, {"uri", bin_uri}}});
    return d.dump(1) + "\n";
}

std::string GltfBuilder::write_gltf(const std::string& dir, const std::string& name,
                                    bool embed) const {
    const std::string uri =
        embed ? "data:application/octet-stream;base64," + base64(bin) : name + ".bin";
    if (!embed && !bin.empty()) write_file(dir + "/" + uri, bin);
    const std::string path = dir + "/" + name + ".gltf";
    write_file(path, gltf_text(uri));
    return path;
}

std::string GltfBuilder::glb_bytes() const {
    // glTF 2.0 section 4.4: header, JSON chunk padded with spaces, BIN chunk padded with zeros.
    json d = doc;
    if (!bin.empty()) d["buffers"] = json::array({{{"byteLength", bin.size()}}});
    std::string text = d.dump();
    while (text.size() % 4 != 0) text += ' ';
    std::string data = bin;
    while (data.size() % 4 != 0) data += '\0';
    std::string out;
    put_u32(out, 0x46546C67);
    put_u32(out, 2);
    put_u32(out, uint32_t(12 + 8 + text.size() + (data.empty() ? 0 : 8 + data.size())));
    put_u32(out, uint32_t(text.size()));
    put_u32(out, 0x4E4F534A);
    out += text;
    if (!data.empty()) {
        put_u32(out, uint32_t(data.size()));
        put_u32(out, 0x004E4942);
        out += data;
    }
    return out;
}

std::string GltfBuilder::write_glb(const std::string& dir, const std::string& name) const {
    const std::string path = dir + "/" + name + ".glb";
    write_file(path, glb_bytes());
    return path;
}

CubeData unit_cube() {
    // Each face: a corner and two edge directions whose cross product points outwards.
    const glm::vec3 faces[6][3] = {
        {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}, {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}};
    CubeData c;
    for (const auto& f : faces) {
        const uint32_t base = uint32_t(c.positions.size());
        c.positions.push_back(f[0]);
        c.positions.push_back(f[0] + f[1]);
        c.positions.push_back(f[0] + f[1] + f[2]);
        c.positions.push_back(f[0] + f[2]);
        for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) c.indices.push_back(base + i);
    }
    return c;
}

} // namespace tp::test
